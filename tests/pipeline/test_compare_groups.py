#!/usr/bin/python3
"""pipeline/sweeps/compare_groups.py on ensembles built here: a variant that scales every seed's
P by 1.2 has ratio 1.2 with no error and no change of shape; one whose growth is steeper by a
known factor per cycle has exactly that change of shape, seed by seed; a variant that only
reorders which seed is high and low is no resolved change; groups at different compactions or
without shared seeds are refused (exit 2).

usage: test_compare_groups.py   (from the repository root)
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "compare_groups.py")
D = 0.27


def law(n):
    return 52 * (1 - D) * math.log1p(0.1 * n / D)


def ensemble(path, per_seed, compaction=D, n0=1.0, at_bound=False):
    """per_seed: {seed: [P at cycles 1..N]}."""
    runs = [{"seed": s, "cycles": [{"cycle": i + 1, "perimeter_P": p} for i, p in enumerate(ps)]}
            for s, ps in per_seed.items()]
    doc = {"cycles": [], "stages": {}, "threshold_sensitivity": {}, "runs": runs,
           "compaction": compaction, "n_runs": len(runs), "seeds": list(per_seed),
           "fits": {"perimeter_P": {"increments": {"n0": n0, "sigma_n0": 0.5, "c1": 20.0,
                                                    "sigma_c1": 5.0, "c2": D / n0,
                                                    "sigma_c2": 0.05, "at_bound": at_bound}}}}
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


def run(tmp, base, var):
    out = os.path.join(tmp, "out", "COMPARISON")
    r = subprocess.run([sys.executable, SCRIPT, "--baseline", base, "--variant", var,
                        "--baseline-label", "protocol", "--variant-label", "flatter", "-o", out],
                       capture_output=True, text=True)
    doc = md = None
    if r.returncode == 0:
        with open(out + ".json") as f:
            doc = json.load(f)
        with open(out + ".md") as f:
            md = f.read()
    return r, doc, md


SCALE = {1: 0.8, 2: 1.0, 3: 1.3}


class CompareGroups(unittest.TestCase):
    def test_a_scaled_variant_changes_the_level_not_the_shape(self):
        with tempfile.TemporaryDirectory() as tmp:
            base = ensemble(os.path.join(tmp, "a.json"),
                            {s: [0.7 * law(n) * k for n in range(1, 6)] for s, k in SCALE.items()})
            var = ensemble(os.path.join(tmp, "b.json"),
                           {s: [1.2 * 0.7 * law(n) * k for n in range(1, 6)] for s, k in SCALE.items()},
                           n0=1e-6, at_bound=True)
            r, doc, md = run(tmp, base, var)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(doc["seeds"], [1, 2, 3])
            for row in doc["rows"]:
                self.assertAlmostEqual(row["ratio"], 1.2, places=12)
                self.assertAlmostEqual(row["ratio_sem"], 0.0, places=6)  # sqrt of a cancelled variance
                self.assertTrue(row["ratio_resolved"])
                if row["cycle"] > 1:
                    self.assertAlmostEqual(row["baseline_shape"], 1.0, places=12)
                    self.assertAlmostEqual(row["variant_shape"], 1.0, places=12)
                    self.assertAlmostEqual(row["shape_change"], 0.0, places=12)
            self.assertIn("| 5 | 39.8 |", md)
            self.assertIn("1.20 ± 0.00 *", md)
            self.assertIn("| protocol | 1.00 ± 0.50 | 20.0 ± 5.0 | 0.270 ± 0.050 |", md)
            self.assertIn("| flatter | 1e-06 (on its search bound: not determined) | – | – |", md)

    def test_a_steeper_growth_is_a_change_of_shape(self):
        # The variant's P(n) is the baseline's times 1 + 0.1 (n - 1): its shape over the law's
        # is 1 + 0.1 (n - 1) times the baseline's in every seed, whatever the seed's level.
        with tempfile.TemporaryDirectory() as tmp:
            bp = {s: [k * law(n) * (1 - 0.02 * n * s) for n in range(1, 6)] for s, k in SCALE.items()}
            vp = {s: [p * (1 + 0.1 * i) for i, p in enumerate(ps)] for s, ps in bp.items()}
            r, doc, _ = run(tmp, ensemble(os.path.join(tmp, "a.json"), bp),
                            ensemble(os.path.join(tmp, "b.json"), vp))
            self.assertEqual(r.returncode, 0, r.stderr)
            for row in doc["rows"][1:]:
                n = row["cycle"]
                lr = law(n) / law(1)
                want = [(bp[s][n - 1] / bp[s][0]) * 0.1 * (n - 1) / lr for s in (1, 2, 3)]
                for got, w in zip(row["shape_change_per_seed"], want):
                    self.assertAlmostEqual(got, w, places=12)
                self.assertAlmostEqual(row["shape_change"], sum(want) / 3, places=12)
                self.assertTrue(row["shape_change_resolved"])

    def test_seeds_trading_places_is_no_resolved_change(self):
        with tempfile.TemporaryDirectory() as tmp:
            # Each seed its own level and shape; the variant gives seed 1 seed 3's run and back.
            bp = {s: [k * law(n) * (1 + 0.05 * s * (n - 1)) for n in range(1, 4)]
                  for s, k in SCALE.items()}
            vp = {1: bp[3], 2: bp[2], 3: bp[1]}
            r, doc, _ = run(tmp, ensemble(os.path.join(tmp, "a.json"), bp),
                            ensemble(os.path.join(tmp, "b.json"), vp))
            self.assertEqual(r.returncode, 0, r.stderr)
            for row in doc["rows"]:
                self.assertAlmostEqual(row["ratio"], 1.0, places=12)
                self.assertGreater(row["ratio_sem"], 0.1)  # anti-correlated pairs
                self.assertFalse(row["ratio_resolved"])
                if row["cycle"] > 1:
                    self.assertAlmostEqual(row["shape_change"], 0.0, places=12)
                    self.assertGreater(row["shape_change_sem"], 0.01)
                    self.assertFalse(row["shape_change_resolved"])

    def test_refused_inputs(self):
        with tempfile.TemporaryDirectory() as tmp:
            a = ensemble(os.path.join(tmp, "a.json"), {1: [1.0, 2.0], 2: [1.5, 2.5]})
            b = ensemble(os.path.join(tmp, "b.json"), {1: [1.0, 2.0], 2: [1.5, 2.5]}, compaction=0.18)
            r, _, _ = run(tmp, a, b)
            self.assertEqual(r.returncode, 2)
            self.assertIn("different compactions", r.stderr)
            c = ensemble(os.path.join(tmp, "c.json"), {7: [1.0, 2.0]})
            r, _, _ = run(tmp, a, c)
            self.assertEqual(r.returncode, 2)
            self.assertIn("share no seed", r.stderr)
            self.assertFalse(os.path.exists(os.path.join(tmp, "out")))


if __name__ == "__main__":
    unittest.main()
