#!/usr/bin/python3
"""pipeline/sweeps/seed_roll_axes.py: the roll axes it lists for a seed are those crumple-sim
draws (read back from run files written here, /stage_ends/NNNNNN@roll_axis_deg, for a small seed
and the largest the simulator takes); novelty is the smallest angle to an earlier axis modulo 180
degrees; over many seeds the draw is uniform (each cycle's mean novelty near 90/n degrees); a bad
seed list exits 2.

usage: test_seed_roll_axes.py CRUMPLE_SIM   (from the repository root)
"""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

import h5py

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "seed_roll_axes.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
from seed_roll_axes import drawn_axes, novelties  # noqa: E402

SIM = None
# Rolled and laid out again, three times: each roll stage draws its axis (axis: random).
PROTOCOL = """mesh: {nodes: 120, seed: 4}
integrator: {plastic_c0: 0.3}
protocol:
  cycles: 3
  stages:
    - {type: roll, duration: 0.05}
    - {type: unfold, open_time: 0.05, max_duration: 0.1}
output: {dt: 0.05, xdmf: false}
"""


class SeedRollAxes(unittest.TestCase):
    def test_the_simulators_draws(self):
        with tempfile.TemporaryDirectory() as tmp:
            cfg = os.path.join(tmp, "c.yaml")
            with open(cfg, "w") as f:
                f.write(PROTOCOL)
            for seed in (11, 2 ** 53):
                run = os.path.join(tmp, f"s{seed}.h5")
                subprocess.run([SIM, cfg, "-o", run, "--seed", str(seed), "--threads", "1",
                                "--quiet"], check=True, cwd=REPO)
                with h5py.File(run, "r") as f:
                    ends = [f["stage_ends"][k].attrs for k in sorted(f["stage_ends"])]
                    recorded = [float(e["roll_axis_deg"]) for e in ends if e["stage"] == "roll"]
                self.assertEqual(len(recorded), 3)
                for r, d in zip(recorded, drawn_axes(seed, 3)):
                    self.assertAlmostEqual(r, d, places=9, msg=f"seed {seed}")

    def test_novelty_and_uniformity(self):
        self.assertEqual(novelties([10.0, 175.0, 100.0]), [None, 15.0, 75.0])
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "axes.csv")
            r = subprocess.run([sys.executable, SCRIPT, "--seeds", "1-400", "--cycles", "4",
                                "-o", out], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out) as f:
                rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 1600)
        for c in (2, 3, 4):
            nov = [float(x["angle_to_earlier_axes_deg"]) for x in rows if int(x["cycle"]) == c]
            # The mean of 400 novelties: 90/c with a standard error under 1.6 degrees.
            self.assertLess(abs(sum(nov) / len(nov) - 90.0 / c), 5.0, f"cycle {c}")

    def test_bad_seeds(self):
        for args in (["--seeds", "x"], ["--seeds", "3-a"], ["--seeds", "1", "--cycles", "0"]):
            r = subprocess.run([sys.executable, SCRIPT] + args, capture_output=True, text=True)
            self.assertEqual(r.returncode, 2, args)


if __name__ == "__main__":
    SIM = os.path.abspath(sys.argv.pop(1))
    unittest.main()
