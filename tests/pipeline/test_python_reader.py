#!/usr/bin/python3
"""The Python reader (pipeline/python/crumple): a tiny crumple-sim run and its crumple-analyze
folder read back into arrays and frames that equal the files (h5py, the CSVs), with units on
every table; the README's five-line example run as written; bad paths refused by name.

usage: test_python_reader.py CRUMPLE_SIM CRUMPLE_ANALYZE   (from the repository root)
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "pipeline", "python"))
import crumple  # noqa: E402
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

SIM = ANALYZE = None
TINY = """mesh: {nodes: 120, seed: 4}
material: {yield_radius: 0.02}
protocol:
  cycles: 2
  stages:
    - {type: roll, duration: 0.2}
    - {type: compress, compaction: 0.5, speed: 0.3}
output: {dt: 0.05, checkpoint_wall_s: 0}
"""


class Reader(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        # Laid out as make reproduce lays out a run, for the README's example.
        cls.dir = os.path.join(cls.tmp.name, "runs", "quick", "axial_crumpling")
        os.makedirs(cls.dir)
        cfg = os.path.join(cls.tmp.name, "tiny.yaml")
        with open(cfg, "w") as f:
            f.write(TINY)
        cls.run_path = os.path.join(cls.dir, "seed1.h5")
        subprocess.run([SIM, cfg, "-o", cls.run_path, "--quiet", "--threads", "1"], check=True)
        subprocess.run([ANALYZE, cls.run_path], check=True, capture_output=True)
        cls.ana_path = os.path.join(cls.dir, "seed1.analysis")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_run_file_equals_what_h5py_reads(self):
        run = crumple.load_run(self.run_path)
        with h5py.File(self.run_path, "r") as f:
            np.testing.assert_array_equal(run.mesh["triangles"], f["mesh/triangles"][()])
            frames = sorted(f["frames"])
            self.assertEqual(len(run.frames), len(frames))
            self.assertEqual(run.frames["t"].iloc[-1], f["frames"][frames[-1]].attrs["t"])
            np.testing.assert_array_equal(run.frame(len(frames) - 1)["x"], f["frames"][frames[-1]]["x"][()])
            np.testing.assert_array_equal(run.cycle(2)["p"], f["cycles/0002/p"][()])
            self.assertEqual(len(run.log), len(f["log/t"]))
            self.assertEqual(run.meta["seed"], f["meta"].attrs["seed"])
        self.assertEqual(list(run.cycles["cycle"]), [1, 2])
        self.assertEqual(list(run.cycles["compaction"]), [0.5, 0.5])
        self.assertEqual(list(run.stage_ends["stage"]), ["roll", "compress"] * 2)
        # Each roll's axis (a random draw) as recorded; none for the compress stages.
        axes = run.stage_ends["roll_axis_deg"]
        with h5py.File(self.run_path, "r") as f:
            want = [f["stage_ends"][k].attrs.get("roll_axis_deg", np.nan) for k in sorted(f["stage_ends"])]
        np.testing.assert_array_equal(axes.to_numpy(), np.array(want))
        self.assertTrue(all(0 <= a < 180 for a in axes[::2]))
        self.assertTrue(axes[1::2].isna().all())
        self.assertEqual(run.config["material"]["yield_radius"], 0.02)
        # Units: on the arrays and on every column of every table.
        self.assertEqual(run.units["x"], "m")
        self.assertIn("mass-scaled", run.units["t"])
        for table in (run.frames, run.cycles, run.stage_ends, run.log):
            for c in table.columns.drop("name", errors="ignore"):
                self.assertIsNotNone(table.attrs["units"].get(c), c)

    def test_analysis_folder_equals_its_csv_files(self):
        ana = crumple.load_analysis(self.ana_path)
        csv = pd.read_csv(os.path.join(self.ana_path, "cycles.csv"))
        pd.testing.assert_frame_equal(ana.cycles, csv)
        with open(os.path.join(self.ana_path, "stats.json")) as f:
            self.assertEqual(ana.stats, json.load(f))
        self.assertEqual(ana.cycles.attrs["units"]["perimeter_P"], "L0")
        self.assertEqual(ana.cycles.attrs["units"]["crease_length_m"], "m")
        for name in ("cycles", "stages", "sensitivity", "facets", "distribution"):
            table = getattr(ana, name)
            self.assertGreater(len(table), 0, name)
            for c in table.columns:
                self.assertIsNotNone(table.attrs["units"].get(c), f"{name}.{c}")
        self.assertTrue(os.path.isfile(ana.crease_map(2)))

    def test_readme_example_runs_as_written(self):
        with open(os.path.join(REPO, "README.md")) as f:
            readme = f.read()
        m = re.search(r"<!-- python-reader-example -->\n```python\n(.*?)```", readme, re.S)
        self.assertIsNotNone(m, "README: the Python reader's example block")
        code = m.group(1)
        self.assertLessEqual(len(code.strip().splitlines()), 5)
        os.symlink(os.path.join(REPO, "pipeline"), os.path.join(self.tmp.name, "pipeline"))
        r = subprocess.run(["/usr/bin/python3", "-c", code], cwd=self.tmp.name,
                           capture_output=True, text=True, env={**os.environ, "MPLBACKEND": "Agg"})
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.getsize(os.path.join(self.tmp.name, "P.png")) > 1000)

    def test_bad_paths_are_named(self):
        with self.assertRaisesRegex(FileNotFoundError, "nope.h5: no such run file"):
            crumple.load_run(os.path.join(self.tmp.name, "nope.h5"))
        with self.assertRaisesRegex(FileNotFoundError, "no stats.json"):
            crumple.load_analysis(self.tmp.name)
        with self.assertRaisesRegex(ValueError, "not a crumple run file"):
            with h5py.File(os.path.join(self.tmp.name, "other.h5"), "w") as f:
                f["x"] = 1
            crumple.load_run(os.path.join(self.tmp.name, "other.h5"))


if __name__ == "__main__":
    SIM, ANALYZE = sys.argv[1], sys.argv[2]
    unittest.main(argv=sys.argv[:1])
