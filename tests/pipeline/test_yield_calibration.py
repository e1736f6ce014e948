#!/usr/bin/python3
"""pipeline/calibration/yield_calibration.py on ensembles built here, and the protocol against
the kept calibration:
- P falling exactly exponentially with the angle: the calibrated angle is the exact crossing of
  the law's value, its uncertainty the seeds' s.e.m. carried through the interpolation;
- a target above or below every angle's P: exit 3, saying which way to extend the grid, or that
  P peaks or dips inside it where the seeds show the turn (not where it is within their noise);
- groups crumpled to different compactions: exit 2;
- protocols/axial_crumpling.yaml states the yield radius that `make calibrate-yield`'s kept
  calibration found, with the same unfold;
- pipeline/calibration/predictions.py: a simulation 10 % above the law in every cycle, with
  c1, c2, a and the KS test within their goals, reaches every goal; 50 % above misses the P goal
  and a collapse far from the law misses c1 and c2; the growth's shape at each threshold of the
  sensitivity table (and at the analysis's own) is P(n)/P(1) over the law's L(n)/L(1), a ratio
  of means over every seed (one without creases at cycle 1 included), each run's slot found by
  its key, with the delta method's error checked against re-drawn ensembles.

usage: test_yield_calibration.py   (from the repository root)
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "calibration", "yield_calibration.py")
PREDICT = os.path.join(REPO, "pipeline", "calibration", "predictions.py")
D = 0.27
TARGET = 52 * (1 - D) * math.log1p(0.1 / D)  # data/crease_length_law_constants.csv


def ensemble(p_mean, p_sem, compaction=D):
    row = {"cycle": 1, "compaction": compaction, "perimeter_P_mean": p_mean, "perimeter_P_sem": p_sem,
           "crease_length_L0_mean": 1.5 * p_mean, "crease_length_L0_sem": p_sem}
    return {"cycles": [row], "fits": {}, "stages": {}, "threshold_sensitivity": {}, "runs": [],
            "n_runs": 3, "compaction": compaction,
            "parameters": {"threshold": 2 * math.sin(math.radians(18.3) / 2)}}


class YieldCalibration(unittest.TestCase):
    def run_case(self, groups, key="material.yield_angle"):
        """groups: {value of key: ensemble}; returns (exit code, stderr, calibration.json or
        None, output folder)."""
        tmp = tempfile.mkdtemp()
        pts = {"points": []}
        for value, e in groups.items():
            g = f"{key.split('.')[-1]}-{value:g}"
            pts["points"].append({"group": g, "values": {key: value}})
            os.makedirs(os.path.join(tmp, "groups", g))
            with open(os.path.join(tmp, "groups", g, "ensemble.json"), "w") as f:
                json.dump(e, f)
        with open(os.path.join(tmp, "points.json"), "w") as f:
            json.dump(pts, f)
        out = os.path.join(tmp, "out")
        r = subprocess.run([sys.executable, SCRIPT, "--points", os.path.join(tmp, "points.json"),
                            "--groups", os.path.join(tmp, "groups"), "--out", out,
                            "-o", os.path.join(out, "calibration.svg")],
                           capture_output=True, text=True)
        path = os.path.join(out, "calibration.json")
        doc = None
        if os.path.isfile(path):
            with open(path) as f:
                doc = json.load(f)
        return r.returncode, r.stderr, doc, out

    def test_exponential_fall_gives_the_exact_crossing(self):
        a, b, rel = 5.9, 0.09, 0.05
        angles = [28.0, 32.0, 36.0, 40.0]
        code, err, doc, out = self.run_case(
            {t: ensemble(math.exp(a - b * t), rel * math.exp(a - b * t)) for t in angles})
        self.assertEqual(code, 0, err)
        exact = (a - math.log(TARGET)) / b
        got = doc["interpolation"]
        self.assertAlmostEqual(got["value"], exact, places=9)
        self.assertAlmostEqual(got["dlnP_dvalue"], -b, places=9)
        lo = max(t for t in angles if t <= exact)
        self.assertEqual(got["between"], [lo, lo + 4])
        t = (exact - lo) / 4
        self.assertAlmostEqual(got["sigma"], math.hypot((1 - t) * rel, t * rel) / b, places=9)
        self.assertAlmostEqual(doc["line_fit"]["value"], exact, places=6)
        self.assertAlmostEqual(doc["target_P_L0"], TARGET, places=9)
        self.assertAlmostEqual(doc["calibrated"]["c0"], 2 * math.sin(math.radians(round(exact, 1)) / 2), places=9)
        for f in ("calibration.csv", "CALIBRATION.md", "calibration.svg"):
            self.assertTrue(os.path.isfile(os.path.join(out, f)), f)
        with open(os.path.join(out, "CALIBRATION.md")) as f:
            md = f.read()
        self.assertIn(f"{exact:.2f} ± ", md)
        self.assertIn("a permanent fold of more than 18.3 degrees, at every value", md)
        # make study-figures redraws the figure from the kept JSON alone.
        r = subprocess.run([sys.executable, SCRIPT, "--replot", os.path.join(out, "calibration.json"),
                            "-o", os.path.join(out, "again.svg")], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.isfile(os.path.join(out, "again.svg")))

    def test_target_outside_the_bracket_says_which_way(self):
        code, err, doc, out = self.run_case({30.0: ensemble(40, 2), 34.0: ensemble(30, 2)})
        self.assertEqual(code, 3)
        self.assertIn("to 34 degrees: add larger values", err)
        self.assertIsNone(doc["interpolation"])
        self.assertNotIn("calibrated", doc)
        self.assertIn("add larger values", doc["not_calibrated"])
        with open(os.path.join(out, "CALIBRATION.md")) as f:
            self.assertIn("**Not calibrated:** P after cycle 1 is above the target", f.read())
        code, err, _, _ = self.run_case({30.0: ensemble(5, 1), 34.0: ensemble(3, 1)})
        self.assertEqual(code, 3)
        self.assertIn("to 30 degrees: add smaller values", err)

    def test_a_radius_calibration_rises_and_is_read_in_metres(self):
        # P rises with the yield radius: exp(1.2 + 0.4 r/mm), crossing the target between 3 and 4 mm.
        radii_m = [2.0e-3, 3.0e-3, 4.0e-3]
        code, err, doc, out = self.run_case(
            {r: ensemble(math.exp(1.2 + 400 * r), 0.05 * math.exp(1.2 + 400 * r)) for r in radii_m},
            key="material.yield_radius")
        self.assertEqual(code, 0, err)
        exact_mm = (math.log(TARGET) - 1.2) / 0.4
        self.assertAlmostEqual(doc["interpolation"]["value"], exact_mm, places=9)
        self.assertEqual(doc["interpolation"]["between"], [3.0, 4.0])
        self.assertEqual(doc["calibrated"]["unit"], "mm")
        self.assertAlmostEqual(doc["calibrated"]["key_value"], round(exact_mm, 2) * 1e-3, places=12)
        self.assertIsNone(doc["calibrated"]["c0"])  # each mesh derives its own
        # Too stiff everywhere: extend toward larger radii.
        code, err, _, _ = self.run_case({2.0e-3: ensemble(4, 1), 3.0e-3: ensemble(6, 1)},
                                        key="material.yield_radius")
        self.assertEqual(code, 3)
        self.assertIn("to 3 mm: add larger values", err)

    def test_a_peak_below_the_target_is_not_sent_to_an_end(self):
        # P rises, peaks below the target inside the grid and falls again (as at a crease angle
        # of 27.5 degrees): extending the grid at either end is no answer, and the message says so.
        code, err, doc, out = self.run_case({4.2e-3: ensemble(7.4, 0.4), 5.0e-3: ensemble(9.4, 1.2),
                                             6.6e-3: ensemble(9.1, 0.4), 10e-3: ensemble(4.2, 0.3)},
                                            key="material.yield_radius")
        self.assertEqual(code, 3)
        self.assertNotIn("add larger", err)
        self.assertNotIn("add smaller", err)
        self.assertIn("with a peak of 9.40 ± 1.20 L0 (0.79 of the target) at 5 mm inside the grid", err)
        self.assertIn("7.40 and 4.20 L0 at its ends", doc["not_calibrated"])
        # Below the target with the closest value at the first end: extend that way, whatever
        # the overall trend from end to end.
        code, err, _, _ = self.run_case({4.2e-3: ensemble(9.0, 0.4), 5.0e-3: ensemble(8.0, 0.4),
                                         6.6e-3: ensemble(8.5, 0.4)}, key="material.yield_radius")
        self.assertEqual(code, 3)
        self.assertIn("to 4.2 mm: add smaller values", err)

    def dip(self, sem):
        """A dip of 24 inside against 30 and 28 at the ends, every value with s.e.m. `sem`
        (target 12.0): (exit code, stderr)."""
        code, err, _, _ = self.run_case({28.0: ensemble(30, sem), 30.0: ensemble(24, sem),
                                         34.0: ensemble(28, sem)})
        return code, err

    def test_a_turn_within_the_seeds_noise_is_no_turn(self):
        # A dip above the target shown by the seeds (24 ± 0.5 inside, 30 ± 0.5 and 28 ± 0.5 at
        # the ends): not sent to an end.
        code, err = self.dip(0.5)
        self.assertEqual(code, 3)
        self.assertIn("with a dip of 24.00 ± 0.50 L0", err)
        # The same means with s.e.m. 3: the dip is within the noise of the ends. P moves toward
        # the target at neither end (both ends are further from it than their neighbour), so
        # the grid does not show which way.
        code, err = self.dip(3)
        self.assertEqual(code, 3)
        self.assertNotIn("dip of", err)
        self.assertIn("does not show which way the target lies", err)
        # Below the target, a peak of 9.0 ± 1 inside against 8.8 ± 0.3 at the last end, which
        # still rises toward the target past its neighbour 8.5: extend that end, and no peak is
        # claimed.
        code, err, _, _ = self.run_case({4.2e-3: ensemble(6.0, 0.3), 5.0e-3: ensemble(9.0, 1.0),
                                         6.6e-3: ensemble(8.5, 0.3), 8.0e-3: ensemble(8.8, 0.3)},
                                        key="material.yield_radius")
        self.assertEqual(code, 3)
        self.assertNotIn("peak of", err)
        self.assertIn("to 8 mm: add larger values", err)

    def test_a_turn_is_claimed_at_twice_the_combined_sem(self):
        # The dip of 24 against ends of 30 and 28 (target 12.0): the nearer end is 4 L0 further
        # from the target, so the dip is shown while 4 > 2 hypot(s, s), s < 1.414.
        code, err = self.dip(1.40)
        self.assertEqual(code, 3)
        self.assertIn("with a dip of 24.00 ± 1.40 L0", err)
        code, err = self.dip(1.43)
        self.assertEqual(code, 3)
        self.assertNotIn("dip of", err)

    def test_a_single_seed_is_refused(self):
        code, err, doc, _ = self.run_case({28.0: ensemble(30, None), 30.0: ensemble(24, 1.0),
                                           34.0: ensemble(28, 1.0)})
        self.assertEqual(code, 2)
        self.assertIn("at least two seeds per value", err)
        self.assertIn("yield_angle-28", err)
        self.assertIsNone(doc)

    def test_a_non_monotonic_bracket_is_refused(self):
        code, err, doc, _ = self.run_case({28.0: ensemble(20, 1), 32.0: ensemble(8, 1),
                                           36.0: ensemble(16, 1), 40.0: ensemble(5, 1)})
        self.assertEqual(code, 3)
        self.assertIn("crosses the target more than once", err)
        self.assertIsNone(doc["interpolation"])

    def test_mixed_compactions_are_refused(self):
        code, err, _, _ = self.run_case({30.0: ensemble(20, 2), 34.0: ensemble(8, 1, compaction=0.18)})
        self.assertEqual(code, 2)
        self.assertIn("different or unknown compactions", err)

    def test_the_protocol_states_the_kept_calibration(self):
        # The protocol states the yield one way; the kept calibration of that statement, the one
        # `make calibrate-yield` makes (CALIBRATE_SWEEP's default, or the yield-angle one), must
        # have found the protocol's value, with the protocol's unfold.
        with open(os.path.join(REPO, "pipeline", "calibration", "calibrate.mk")) as f:
            default_sweep = re.search(r"^CALIBRATE_SWEEP \?= (\S+)$", f.read(), re.M).group(1)
        kept_dir = {"yield_angle": "yield_calibration", "yield_radius": default_sweep}
        with open(os.path.join(REPO, "protocols", "axial_crumpling.yaml")) as f:
            protocol = f.read()
        stated = dict(re.findall(r"^\s+(yield_angle|yield_radius):\s*([0-9.eE+-]+)\s*(?:#.*)?$",
                                 protocol, re.M))
        self.assertEqual(len(stated), 1, f"protocols/axial_crumpling.yaml states {stated}: "
                         "exactly one of material.yield_angle and material.yield_radius")
        name, value = stated.popitem()
        with open(os.path.join(REPO, "docs", "studies", kept_dir[name], "calibration.json")) as f:
            kept = json.load(f)
        self.assertEqual(kept["calibrated"]["key"], "material." + name)
        self.assertAlmostEqual(float(value), kept["calibrated"]["key_value"], places=12,
                               msg=f"the protocol's {name} is not the kept calibration's "
                               f"(docs/studies/{kept_dir[name]}/; make calibrate-yield)")
        self.assertAlmostEqual(kept["target_P_L0"], TARGET, places=6)
        if name == "yield_radius":
            # The calibration's sweep ran the protocol's unfold (its flatten_length, pinned there).
            unfold = re.search(r"- type: unfold\n((?:\s{6,}\S.*\n)*)", protocol).group(1)
            proto_flat = re.search(r"flatten_length:\s*([0-9.eE+-]+)", unfold)
            with open(os.path.join(REPO, "pipeline", "sweeps", default_sweep + ".yaml")) as f:
                swept = re.search(r"^\s+protocol\.stages\.unfold\.flatten_length:\s*([0-9.eE+-]+)",
                                  f.read(), re.M)
            self.assertEqual(float(proto_flat.group(1)) if proto_flat else None,
                             float(swept.group(1)) if swept else None,
                             f"the protocol's unfold is not that of pipeline/sweeps/{default_sweep}.yaml")


def law(n):
    return 52 * (1 - D) * math.log1p(0.1 * n / D)


class Predictions(unittest.TestCase):
    def run_case(self, factor, c1=50.0, c2=0.12, compactions=(0.63, 0.27, 0.18), sensitivity=None,
                 runs=None, material=("--set", "material.yield_radius=3.58e-3"), protocol=None,
                 code=0, group=None):
        tmp = tempfile.mkdtemp()
        if runs is None:
            # Three seeds each growing as the law, at 0.9, 1 and 1.1 times the mean.
            runs = [{"seed": k + 1, "cycles": [{"cycle": n, "perimeter_P": factor * law(n) * sk}
                                               for n in range(1, 11)]}
                    for k, sk in enumerate((0.9, 1.0, 1.1))]
        rows = []
        for n in range(1, 11):
            rows.append({"cycle": n, "compaction": D, "perimeter_P_mean": factor * law(n),
                         "perimeter_P_sem": 1.0, "a_fit_mean": 3.6, "a_fit_sem": 0.3,
                         "a_univ_mean": 3.0, "ks_n_tested": 3, "ks_n_rejected": 1 if n % 2 else 2,
                         "single_triangle_fraction_mean": 0.1, "n_facets_mean": 300})
        ens = {"cycles": rows, "stages": {}, "threshold_sensitivity": sensitivity or {}, "runs": runs,
               "n_runs": 3, "compaction": D, "seeds": [1, 2, 3], "parameters": {"threshold": 0.318},
               "fits": {"perimeter_P": {"increments": {"C": 38.0, "sigma_C": 3.0, "n0": 2.5,
                                                        "sigma_n0": 0.5}}}}
        name = group or "compaction-0.27"
        os.makedirs(os.path.join(tmp, "groups", name))
        with open(os.path.join(tmp, "groups", name, "ensemble.json"), "w") as f:
            json.dump(ens, f)
        with open(os.path.join(tmp, "collapse.json"), "w") as f:
            json.dump({"compactions": list(compactions), "fits": {"perimeter_P": {"increments": {
                "c1": c1, "sigma_c1": 1.0, "c2": c2, "sigma_c2": 0.01, "chi2": 50.0, "dof": 28,
                "at_bound": False}}}}, f)
        with open(os.path.join(tmp, "cal.json"), "w") as f:
            json.dump({"calibrated": {"key": "material.yield_radius", "value": 3.58, "unit": "mm",
                                      "sigma": 0.05, "key_value": 3.58e-3, "c0": None}}, f)
        # The sweep's points: the preset's node count, then the sweep's own, which wins.
        with open(os.path.join(tmp, "points.json"), "w") as f:
            pts = {"points": [{"group": name, "analyze_args": ["--px-per-edge", "24"],
                               "args": ["p.yaml", "--set", "mesh.nodes=1500", "--set",
                                        "mesh.nodes=3000", *material]}]}
            if protocol is not None:
                pts["protocol"] = os.path.join(tmp, "p.yaml")
                with open(pts["protocol"], "w") as g:
                    g.write(protocol)
            json.dump(pts, f)
        r = subprocess.run([sys.executable, PREDICT, "--sweep-results", tmp, "--calibration",
                            os.path.join(tmp, "cal.json"), "--points", os.path.join(tmp, "points.json"),
                            "--out", os.path.join(tmp, "out"),
                            "-o", os.path.join(tmp, "out", "p.svg"),
                            *(["--group", group] if group else [])], capture_output=True, text=True)
        self.assertEqual(r.returncode, code, r.stderr)
        if code:
            return r.stderr
        with open(os.path.join(tmp, "out", "predictions.json")) as f:
            doc = json.load(f)
        doc["_path"] = os.path.join(tmp, "out", "predictions.json")
        with open(os.path.join(tmp, "out", "PREDICTIONS.md")) as f:
            md = f.read()
        return {g["goal"].split(" within")[0]: g["reached"] for g in doc["goals"]}, doc, md

    def test_the_sweep_must_have_run_the_calibrated_material(self):
        # Set by the sweep to another radius: refused, naming both.
        err = self.run_case(1.1, material=("--set", "material.yield_radius=3.34e-3"), code=2)
        self.assertIn("ran material.yield_radius = 0.00334", err)
        self.assertIn("calibrated 0.00358", err)
        # Not set by the sweep: the protocol file's value counts, right or wrong.
        goals, _, _ = self.run_case(1.1, material=(), protocol="material: {yield_radius: 3.58e-3}\n")
        self.assertEqual(goals["P(n)"], "yes")
        err = self.run_case(1.1, material=(), protocol="material: {yield_radius: 8.1e-3}\n", code=2)
        self.assertIn("ran material.yield_radius = 0.0081", err)

    def test_one_compaction_is_no_collapse(self):
        goals, doc, md = self.run_case(1.1, compactions=(0.27,))
        self.assertEqual(goals["global c1 and c2"], "not tested")
        self.assertIsNone(doc["global"])
        self.assertIn("fewer than two compactions", md)

    def test_a_one_group_sweep_names_its_group(self):
        # A sweep of one group at the calibrated radius (not a compaction sweep): --group names
        # it, and its points give the resolution as a compaction sweep's do.
        goals, doc, _ = self.run_case(1.1, compactions=(0.27,), group="yield_radius-3.58e-3")
        self.assertEqual(goals["P(n)"], "yes")
        self.assertTrue(doc["source"].endswith(os.path.join("yield_radius-3.58e-3", "ensemble.json")))
        self.assertEqual(doc["resolution"], "3000 nodes, analysed at --px-per-edge 24")

    def test_within_every_goal(self):
        goals, doc, md = self.run_case(1.1)
        self.assertEqual(set(goals.values()), {"yes"}, goals)
        self.assertEqual(doc["P"][0]["role"], "calibrated")
        self.assertAlmostEqual(doc["P"][4]["ratio"], 1.1, places=9)
        self.assertEqual(sum(r["ks_not_rejecting"] for r in doc["facets"]), 5)
        self.assertIn("| 5 | predicted |", md)
        self.assertIn("The yield radius 3.58 ± 0.05 mm was fitted", md)
        self.assertEqual(doc["resolution"], "3000 nodes, analysed at --px-per-edge 24")
        r = subprocess.run([sys.executable, PREDICT, "--replot", doc["_path"], "-o",
                            doc["_path"] + ".svg"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.isfile(doc["_path"] + ".svg"))

    def test_misses_are_reported(self):
        goals, doc, md = self.run_case(1.5, c1=20.0, c2=1.0)
        self.assertEqual(goals["P(n)"], "no")
        self.assertEqual(goals["global c1"], "no")
        self.assertEqual(goals["global c2"], "no")
        self.assertFalse(any(r["within_band"] for r in doc["P"]))
        self.assertIn("| 0 of 9 cycles (ratios 1.50-1.50; cycle 1, the calibration, 1.50) | no |", md)

    def test_growth_shape_against_the_threshold(self):
        # Per seed, counted at 0.5 c0 each run grows as the law (P = 2 law times the seed's
        # scale: the ratio is 1 with no error, the seeds' P(n) and P(1) fully correlated); at
        # c0 the mean does not grow at all (P(n) = 3) but the seeds trade places between cycle 1
        # and later (anti-correlated: a larger error than independent s.e.m. would give); at
        # the analysis's own threshold (P = 1.5 law per seed) as the law.
        # Seed 2 lists its slots in the other order: a slot is matched by its factor of c0.
        scale = (0.9, 1.0, 1.1)
        runs = []
        for k, sk in enumerate(scale):
            order = [1, 0] if k == 1 else [0, 1]
            runs.append({"seed": k + 1,
                         "cycles": [{"cycle": n, "perimeter_P": 1.5 * law(n) * sk} for n in range(1, 11)],
                         "threshold_sensitivity": {
                             "factors_of_c0": [[0.5, 1.0][i] for i in order],
                             "thresholds": [[0.2, 0.4][i] for i in order],
                             "cycles": [{"cycle": n, "perimeter_P": [
                                 [2 * law(n) * sk, 3.0 * (sk if n == 1 else scale[2 - k])][i]
                                 for i in order]} for n in range(1, 11)]}})
        sens = {"factors_of_c0": [0.5, 1.0], "thresholds_mean": [0.2, 0.4]}
        _, doc, md = self.run_case(1.5, sensitivity=sens, runs=runs)
        rows = doc["threshold_shape"]
        self.assertEqual([r["threshold"] for r in rows], [0.2, 0.318, 0.4])
        self.assertEqual(rows[1]["role"], "the analysis's own")
        for r in rows[:2]:
            self.assertTrue(r["within_band"])
            self.assertEqual(r["n_runs"], 3)
            for c in r["cycles"]:
                self.assertAlmostEqual(c["shape_ratio"], 1.0, places=9)
                self.assertAlmostEqual(c["sigma"], 0.0, places=6)
                for x in c["per_run"]:
                    self.assertAlmostEqual(x, 1.0, places=9)
        flat = rows[2]["cycles"]
        self.assertFalse(rows[2]["within_band"])
        self.assertAlmostEqual(rows[2]["P1_mean"], 3.0, places=9)
        self.assertAlmostEqual(rows[2]["P1_sem"], math.sqrt(0.09 / 3), places=9)
        r10 = law(1) / law(10)
        self.assertAlmostEqual(flat[-1]["shape_ratio"], r10, places=9)
        # Delta method: var = (0.01 + 0.01 + 0.02) / 3 for the plain ratio, twice what
        # independent errors would give.
        self.assertAlmostEqual(flat[-1]["sigma"], r10 * math.sqrt(0.04 / 3), places=9)
        self.assertEqual([round(x / r10, 9) for x in flat[-1]["per_run"]],
                         [round(3.3 / 2.7, 9), 1.0, round(2.7 / 3.3, 9)])
        self.assertAlmostEqual(rows[0]["fold_angle_deg"], math.degrees(2 * math.asin(0.1)), places=9)
        self.assertIn("| 0.200 (0.5 c0) | 11.5 | ", md)
        self.assertIn("| **0.318 (the analysis's own)** |", md)
        self.assertIn(f"| 1.00 ± 0.00 | 1.00 ± 0.00 | 1.00-1.00 | yes | 1.00, 1.00, 1.00 |", md)
        self.assertIn(f"| {r10:.2f} ± {r10 * math.sqrt(0.04 / 3):.2f} |", md)

    def test_growth_shape_edge_cases(self):
        # A threshold given as an absolute value (no factor of c0) is not set in bold; a seed
        # with no crease at cycle 1 stays in that threshold's means (P(1) = 0: dropping it
        # would bias the ratio up) and has no ratio of its own; a threshold where no seed has
        # one is left out; with the own threshold's P(1) = 0 in every seed the report says it
        # is not tabulated.
        runs = [{"seed": k + 1,
                 "cycles": [{"cycle": n, "perimeter_P": 0.0 if n == 1 else law(n)} for n in range(1, 4)],
                 "threshold_sensitivity": {"factors_of_c0": [], "thresholds": [0.2, 0.4], "cycles": [
                     {"cycle": n, "perimeter_P": [law(n) if (k or n > 1) else 0.0, 0.0]}
                     for n in range(1, 4)]}}
                for k in range(3)]
        sens = {"factors_of_c0": [], "thresholds_mean": [0.2, 0.4]}
        _, doc, md = self.run_case(1.1, sensitivity=sens, runs=runs)
        rows = doc["threshold_shape"]
        self.assertEqual([r["threshold"] for r in rows], [0.2])
        self.assertEqual(rows[0]["n_runs"], 3)
        self.assertAlmostEqual(rows[0]["P1_mean"], 2 * law(1) / 3, places=9)
        for c in rows[0]["cycles"]:
            self.assertAlmostEqual(c["shape_ratio"], 1.5, places=9)  # law(n) over 2/3 law(1)
            self.assertIsNone(c["per_run"][0])
            self.assertAlmostEqual(c["per_run"][1], 1.0, places=9)
        self.assertIn("| 0.200 | 11.5 |", md)
        self.assertIn("| –, 1.00, 1.00 |", md)
        self.assertNotIn("**0.200", md)
        self.assertIn("The analysis's own threshold has no mean P > 0 at cycle 1", md)

    def test_growth_shape_slots_by_key_and_a_single_seed(self):
        # Seed 2's table has no 0.5 c0 slot (another analysis version), so that row is the
        # other two seeds; one seed alone has no error and prints none.
        runs = []
        for k in range(3):
            fs = [1.0] if k == 1 else [0.5, 1.0]
            runs.append({"seed": k + 1,
                         "cycles": [{"cycle": n, "perimeter_P": law(n)} for n in range(1, 4)],
                         "threshold_sensitivity": {
                             "factors_of_c0": fs, "thresholds": [0.4 * f for f in fs],
                             "cycles": [{"cycle": n, "perimeter_P": [(1 + k) * law(n) * f for f in fs]}
                                        for n in range(1, 4)]}})
        sens = {"factors_of_c0": [0.5, 1.0], "thresholds_mean": [0.2, 0.4]}
        _, doc, md = self.run_case(1.1, sensitivity=sens, runs=runs)
        half = [r for r in doc["threshold_shape"] if r["factor_of_c0"] == 0.5][0]
        self.assertEqual(half["n_runs"], 2)
        self.assertAlmostEqual(half["P1_mean"], (0.5 + 1.5) * law(1) / 2, places=9)
        _, doc, md = self.run_case(1.1, runs=runs[:1])
        own = doc["threshold_shape"][0]
        self.assertIsNone(own["P1_sem"])
        self.assertIsNone(own["cycles"][0]["sigma"])
        self.assertIn(f"| {law(1):.2f} | 1.00 | 1.00 |", md)
        self.assertNotIn("± –", md)

    def test_ratio_of_means_delta_method(self):
        sys.path.insert(0, os.path.join(REPO, "pipeline", "calibration"))
        from predictions import ratio_of_means
        # mean(y) = 0: the ratio is 0 and its error var y / (n mean(x)^2), not undefined.
        r, sig = ratio_of_means([1.0, 2.0, 3.0], [1.0, -1.0, 0.0])
        self.assertEqual(r, 0.0)
        self.assertAlmostEqual(sig, math.sqrt(1.0 / (3 * 4.0)), places=12)
        # The formula is the residuals' variance: with R = mean(y)/mean(x), var(y - R x) over
        # n mean(x)^2 (sample variance, n - 1), for any data.
        import random
        import statistics
        rng = random.Random(3)
        xs = [rng.uniform(5, 15) for _ in range(4)]
        ys = [3 * x + rng.gauss(0, 2) for x in xs]
        r, sig = ratio_of_means(xs, ys)
        mx = statistics.fmean(xs)
        self.assertAlmostEqual(r, statistics.fmean(ys) / mx, places=12)
        resid = [y - r * x for x, y in zip(xs, ys)]
        self.assertAlmostEqual(sig, math.sqrt(statistics.variance(resid) / (len(xs) * mx ** 2)),
                               places=12)
        # Against re-drawn seeds: the spread of mean(y)/mean(x) over many ensembles of 50 runs
        # with correlated x, y (R = 3, where the covariance nearly cancels the variances, so a
        # term dropped or taken once instead of squared shows) matches the formula's expectation
        # to a few per cent.
        rng = random.Random(5)
        ratios, sigs = [], []
        for _ in range(4000):
            xs, ys = [], []
            for _ in range(50):
                x = rng.gauss(10.0, 1.0)
                xs.append(x)
                ys.append(3.0 * x + rng.gauss(0.0, 1.0))
            r, sig = ratio_of_means(xs, ys)
            ratios.append(r)
            sigs.append(sig)
        self.assertAlmostEqual(statistics.fmean(sigs) / statistics.stdev(ratios), 1.0, delta=0.05)

    def test_without_a_sensitivity_table_only_the_own_threshold(self):
        _, doc, md = self.run_case(1.1)
        self.assertEqual([r["role"] for r in doc["threshold_shape"]], ["the analysis's own"])


if __name__ == "__main__":
    unittest.main()
