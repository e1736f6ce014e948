#!/usr/bin/python3
"""pipeline/sweeps/roll_axes.py on run files written here: a square sheet rolled (exactly, as
the roll stage's target) about axes of 30, 30 and 120 degrees in three cycles, with other stages'
frames between; the axes come back to the degree (or, recorded at the roll's end, as recorded, with
the recovered axis beside them), the second roll is 0 degrees from an earlier
one and the third 90, each beside its increment of P; a file that is not a run is refused.

usage: test_roll_axes.py   (from the repository root)
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "roll_axes.py")


def rolled(ref, deg, R=0.0177, shift=(0.01, -0.02)):
    """The sheet rolled about the in-plane axis at `deg` (u across it, w along it)."""
    a = np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])
    b = np.array([-a[1], a[0]])
    u, w = ref[:, :2] @ b, ref[:, :2] @ a
    k = 1.0 / R
    xy = np.outer(w, a) + np.outer(np.sin(k * u) / k, b) + np.array(shift)
    return np.column_stack([xy, (1 - np.cos(k * u)) / k])


def write_run(path, axes, P, recorded=None):
    """recorded: the axes as a newer crumple-sim records them at each roll's end, or None (an
    older file)."""
    g = np.linspace(-0.05, 0.05, 21)
    ref = np.array([(x, y, 0.0) for x in g for y in g])
    rng = np.random.default_rng(3)
    with h5py.File(path, "w") as f:
        f["mesh/ref_positions"] = ref
        k = 0
        for c, deg in enumerate(axes, start=1):
            t0 = 10.0 * c
            for stage, t, x in (("roll", t0, rolled(ref, deg)),
                                ("compress", t0 + 3, ref + rng.normal(0, 0.01, ref.shape)),
                                ("unfold", t0 + 6, ref)):
                fr = f.create_group(f"frames/{k:06d}")
                fr.attrs["t"] = t
                fr["x"] = x
                se = f.create_group(f"stage_ends/{k:06d}")
                se.attrs["cycle"] = c
                se.attrs["stage"] = stage
                se.attrs["t"] = t
                if recorded is not None and stage == "roll":
                    se.attrs["roll_axis_deg"] = recorded[c - 1]
                k += 1
    an = os.path.splitext(path)[0] + ".analysis"
    os.makedirs(an)
    with open(os.path.join(an, "stats.json"), "w") as f:
        json.dump({"cycles": [{"cycle": c, "perimeter_P": p} for c, p in enumerate(P, start=1)]}, f)


class RollAxes(unittest.TestCase):
    def table(self, tmp, axes, P, recorded=None):
        """roll_axes.py on one run written here: (its CSV rows, its stdout)."""
        run = os.path.join(tmp, "seed1.h5")
        write_run(run, axes, P, recorded)
        out = os.path.join(tmp, "axes.csv")
        r = subprocess.run([sys.executable, SCRIPT, run, "-o", out], capture_output=True,
                           text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(out) as f:
            return list(csv.DictReader(f)), r.stdout

    def test_axes_novelty_and_increments(self):
        with tempfile.TemporaryDirectory() as tmp:
            rows, stdout = self.table(tmp, [30, 30, 120], [10.0, 11.5, 25.0])
            self.assertEqual([int(x["axis_deg"]) for x in rows], [30, 30, 120])
            self.assertEqual({x["axis_source"] for x in rows}, {"inferred"})
            self.assertEqual([x["angle_to_earlier_axes_deg"] for x in rows], ["", "0", "90"])
            self.assertEqual([float(x["P_increment"]) for x in rows], [10.0, 1.5, 13.5])
            self.assertIn("new axis 30-90 degrees from every earlier one: 1 cycles, mean P "
                          "increment 13.50", stdout)

    def test_a_recorded_axis_is_used_and_checked(self):
        with tempfile.TemporaryDirectory() as tmp:
            rows, _ = self.table(tmp, [30, 30, 120], [10.0, 11.5, 25.0],
                                 recorded=[30.25, 29.8, 120.4])
            self.assertEqual([float(x["axis_deg"]) for x in rows], [30.25, 29.8, 120.4])
            self.assertEqual({x["axis_source"] for x in rows}, {"recorded"})
            self.assertEqual([int(x["inferred_axis_deg"]) for x in rows], [30, 30, 120])
            self.assertAlmostEqual(float(rows[1]["angle_to_earlier_axes_deg"]), 0.45, places=9)
            self.assertAlmostEqual(float(rows[2]["angle_to_earlier_axes_deg"]), 89.4, places=9)

    def test_not_a_run_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, "x.h5")
            with h5py.File(bad, "w") as f:
                f["junk"] = [1]
            os.makedirs(os.path.join(tmp, "x.analysis"))
            with open(os.path.join(tmp, "x.analysis", "stats.json"), "w") as f:
                json.dump({"cycles": []}, f)
            r = subprocess.run([sys.executable, SCRIPT, bad, "-o", os.path.join(tmp, "o.csv")],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)
            self.assertIn("not a crumple-sim run file", r.stderr)
            self.assertFalse(os.path.exists(os.path.join(tmp, "o.csv")))


if __name__ == "__main__":
    unittest.main()
