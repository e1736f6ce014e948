#!/usr/bin/python3
"""docs/FILE_FORMAT.md against the files crumple-sim writes (issue 37): a tiny run is stopped by
SIGTERM inside a stage (its checkpoint file RUN.h5.tmp) and resumed to the end (RUN.h5). Both
files are walked with h5py: every group, dataset and attribute must have a row in the document's
layout tables with the same kind, type, shape and (for datasets) `units` attribute, and every
row the document says is present `always` must be in both files (the rows present after a
resume and inside a stage in the file that has them).

usage: test_file_format.py CRUMPLE_SIM   (from the repository root)
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import h5py
import numpy as np

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DOC = os.path.join(REPO, "docs", "FILE_FORMAT.md")
HEADER = "| path | kind | type | shape | units | present | meaning |"
SIM = None
TYPES = {"float64": "f8", "int64": "i8", "int32": "i4", "int8": "i1", "uint8": "u1"}


def doc_rows(path=DOC):
    """{pattern: row} from every layout table of the document."""
    rows, in_table = {}, False
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line == HEADER:
                in_table = True
                continue
            if not in_table or line.startswith("| ---"):
                continue
            if not line.startswith("|"):
                in_table = False
                continue
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            name, kind, typ, shape, units, present = cells[:6]
            pattern = name.strip("`")
            if pattern in rows:
                raise AssertionError(f"{path}: {pattern} documented twice")
            rows[pattern] = {"kind": kind, "type": typ, "shape": shape, "units": units,
                             "present": present}
    return rows


def pattern_of(name):
    """/frames/000012/x -> /frames/NNNNNN/x; /cycles/0002@t -> /cycles/NNNN@t."""
    name = re.sub(r"/\d{6}(?=[/@]|$)", "/NNNNNN", name)
    return re.sub(r"/\d{4}(?=[/@]|$)", "/NNNN", name)


def type_of(value):
    """The document's type name of an h5py dataset or attribute value."""
    dt = value.dtype if hasattr(value, "dtype") else np.asarray(value).dtype
    if isinstance(value, (str, bytes)) or dt.kind in ("O", "S", "U") or \
            h5py.check_string_dtype(dt) is not None:
        return "string"
    for name, code in TYPES.items():
        if dt == np.dtype(code):
            return name
    return str(dt)


def walk(path):
    """{pattern: [(kind, type, shape, units, name)]} of everything in a run file."""
    found = {}

    def add(name, kind, typ="", shape=None, units=None):
        found.setdefault(pattern_of(name), []).append((kind, typ, shape, units, name))

    def attrs(name, obj):
        for key in obj.attrs:
            if key == "units" and isinstance(obj, h5py.Dataset):
                continue
            add(f"{name}@{key}", "attribute", type_of(obj.attrs[key]))

    with h5py.File(path) as f:
        def visit(name, obj):
            full = "/" + name
            if isinstance(obj, h5py.Group):
                add(full, "group")
            else:
                units = obj.attrs.get("units")
                add(full, "dataset", type_of(obj), obj.shape,
                    units.decode() if isinstance(units, bytes) else units)
            attrs(full, obj)
        f.visititems(visit)
        sizes = {"n": f["mesh/ref_positions"].shape[0], "t": f["mesh/triangles"].shape[0],
                 "e": f["mesh/edges"].shape[0], "h": f["mesh/hinges"].shape[0],
                 "s": f["log/t"].shape[0]}
    return found, sizes


def shape_matches(doc_shape, shape, sizes):
    if doc_shape == "scalar":
        return shape == ()
    dims = [d.strip() for d in doc_shape.strip("()").split(",")]
    if len(dims) != len(shape):
        return False
    return all(d == "k" or (d in sizes and sizes[d] == s) or (d.isdigit() and int(d) == s)
               for d, s in zip(dims, shape))


class FileFormat(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp()
        run = os.path.join(cls.tmp, "run.h5")
        args = [SIM, "protocols/axial_crumpling.yaml", "--seed", "5", "--threads", "1", "--set",
                "mesh.nodes=200", "--set", "protocol.cycles=2", "-o", run, "--quiet"]
        proc = subprocess.Popen(args, cwd=REPO, stderr=subprocess.PIPE, text=True)
        tmp = run + ".tmp"
        # The first checkpoint appears at a stage's end; a moment later the run is inside the
        # next stage, where SIGTERM makes it write one with the stage's starting state.
        deadline = time.time() + 120
        while not os.path.exists(tmp) and time.time() < deadline and proc.poll() is None:
            time.sleep(0.02)
        time.sleep(0.5)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=120)
        assert os.path.exists(tmp), f"no checkpoint file ({proc.returncode}): {err}"
        cls.checkpoint = os.path.join(cls.tmp, "checkpoint.h5")
        shutil.copyfile(tmp, cls.checkpoint)
        r = subprocess.run(args[:-1] + ["--resume", "--quiet"], cwd=REPO, capture_output=True,
                           text=True)
        assert r.returncode == 0, r.stderr
        cls.complete = run
        cls.rows = doc_rows()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def check_file(self, path):
        found, sizes = walk(path)
        for pattern, items in found.items():
            with self.subTest(file=os.path.basename(path), path=pattern):
                self.assertTrue(pattern in self.rows, f"{items[0][4]} in the file is not in "
                                "docs/FILE_FORMAT.md")
                row = self.rows[pattern]
                for kind, typ, shape, units, name in items:
                    self.assertEqual(kind, row["kind"], name)
                    if kind == "group":
                        continue
                    self.assertEqual(typ, row["type"], f"{name}: type")
                    if kind == "dataset":
                        self.assertTrue(shape_matches(row["shape"], shape, sizes),
                                        f"{name}: shape {shape} against {row['shape']}")
                        self.assertEqual(units, row["units"], f"{name}: units attribute")
        return found

    def test_checkpoint_file_matches_the_document(self):
        found = self.check_file(self.checkpoint)
        with h5py.File(self.checkpoint) as f:
            self.assertEqual(f["meta"].attrs["status"], "running")
            inside = int(f["checkpoint"].attrs["in_stage"]) == 1
        for pattern, row in self.rows.items():
            if row["present"] == "always" or (inside and row["present"] == "when taken inside a stage"):
                self.assertTrue(pattern in found, f"{pattern} ({row['present']}) is not in the "
                                "checkpoint file")
        self.assertTrue(inside, "SIGTERM inside a stage keeps the stage's start")

    def test_resumed_complete_file_matches_the_document(self):
        found = self.check_file(self.complete)
        # A complete run has ended its stages and cycles and has rolled the sheet; this one
        # was resumed.
        for pattern, row in self.rows.items():
            if row["present"] in ("always", "after a resume", "once a cycle has ended",
                                  "once a stage has ended", "once rolled"):
                self.assertTrue(pattern in found, f"{pattern} ({row['present']}) is not in the "
                                "complete file")
        with h5py.File(self.complete) as f:
            self.assertEqual(f["meta"].attrs["status"], "complete")
            frames = [f["frames"][k] for k in sorted(f["frames"])]
            # The first frame is the flat sheet before the protocol; the last, the run's end.
            self.assertEqual(frames[0].attrs["cycle"], 0)
            self.assertEqual(frames[0].attrs["stage"], "initial")
            last = f["cycles"][sorted(f["cycles"])[-1]]
            self.assertAlmostEqual(frames[-1].attrs["t"], last.attrs["t"], places=12)
            np.testing.assert_array_equal(frames[-1]["x"][:], last["x"][:])
            threshold = f["meta"].attrs["crease_threshold"]
            np.testing.assert_array_equal(last["crease"][:], np.abs(last["p"][:]) > threshold)
            self.assertIn("mass_scale", f["log/t"].attrs["time_note"])

    def test_the_walk_catches_what_the_document_lacks(self):
        # The check above can fail: an undocumented dataset and a wrong units attribute.
        bad = os.path.join(self.tmp, "bad.h5")
        shutil.copyfile(self.complete, bad)
        with h5py.File(bad, "a") as f:
            f["mesh/extra"] = np.zeros(3)
            f["mesh/rest_lengths"].attrs["units"] = "mm"
        found, sizes = walk(bad)
        self.assertNotIn("/mesh/extra", self.rows)
        self.assertIn("/mesh/extra", found)
        self.assertNotEqual(found["/mesh/rest_lengths"][0][3], self.rows["/mesh/rest_lengths"]["units"])


if __name__ == "__main__":
    SIM = os.path.abspath(sys.argv.pop(1))
    unittest.main()
