#!/usr/bin/python3
"""pipeline/sweeps/convergence.py on ladders built here, whose statistics follow Q* + C h^p
exactly: it recovers the order and the converged value (second and first order, rising and
falling), falls back to an assumed first order on two rungs or a non-monotone ladder and says
so, marks a finest step within the seeds' noise, picks the presets' coarsest rungs by their
tolerance at face value (the coarsest rung from which on all are within it) and as shown by the
seeds' errors (none without an s.e.m., or where re-drawn ladders often have no estimate), takes
the s.e.m. from re-drawn ladders (the linear spread at an assumed order and at small noise, an
independent re-draw's where the noise changes the method; reproducible; a missing mean or
s.e.m. leaves unknown only what it enters), and the sweep report and figure read its output.

usage: test_convergence.py   (from the repository root)
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "convergence.py")
AREA = 0.01  # m^2, the 10 cm sheet


def h_of(nodes):
    return math.sqrt(AREA / (2 * nodes))  # triangles ~ 2 nodes


def ladder(tmp, values, sem=0.0, cycles=2):
    """values: {nodes: [Q for each cycle]} for every statistic alike; sem one value for all rungs
    or {nodes: sem}."""
    pts = {"name": "ladder", "grid": [{"key": "mesh.nodes", "values": [str(n) for n in values]}],
           "points": []}
    for nodes, qs in values.items():
        g = f"nodes-{nodes}"
        an = os.path.join(tmp, "runs", g, "seed1.analysis")
        os.makedirs(an)
        with open(os.path.join(an, "stats.json"), "w") as f:
            json.dump({"sheet": {"nodes": nodes, "triangles": 2 * nodes, "area_m2": AREA}}, f)
        pts["points"].append({"group": g, "seed": 1, "analysis": an})
        rows = []
        for c in range(cycles):
            row = {"cycle": c + 1}
            for key in ("perimeter_P", "crease_length_L0", "n_facets", "single_triangle_fraction",
                        "a_fit", "dangling_fraction"):
                row[key + "_mean"] = qs[c]
                row[key + "_sem"] = sem.get(nodes) if isinstance(sem, dict) else sem
            rows.append(row)
        os.makedirs(os.path.join(tmp, "groups", g))
        with open(os.path.join(tmp, "groups", g, "ensemble.json"), "w") as f:
            json.dump({"cycles": rows, "fits": {}, "stages": {}, "threshold_sensitivity": {},
                       "runs": [], "n_runs": 3, "seeds": [1, 2, 3]}, f)
    with open(os.path.join(tmp, "points.json"), "w") as f:
        json.dump(pts, f)


def run(tmp):
    r = subprocess.run([sys.executable, SCRIPT, "--points", os.path.join(tmp, "points.json"),
                        "--results", tmp], capture_output=True, text=True)
    if r.returncode != 0:
        raise AssertionError(r.stderr)
    with open(os.path.join(tmp, "convergence.json")) as f:
        return json.load(f)


def section(doc):
    """The sweep report's convergence section for a convergence.json document."""
    sys.path.insert(0, os.path.join(REPO, "pipeline", "report"))
    sys.path.insert(0, os.path.join(REPO, "pipeline", "plots"))
    from make_sweep_report import convergence_section
    lines = []
    convergence_section(lines.append, doc)
    return "\n".join(lines)


def exact(nodes, q_star, c, p):
    return q_star + c * h_of(nodes) ** p


class Convergence(unittest.TestCase):
    def rows(self, doc, key="perimeter_P"):
        return [r for r in doc["rows"] if r["quantity"] == key]

    def test_recovers_order_and_limit(self):
        for p, c in ((2.0, 4e4), (1.0, -300.0), (1.5, 5e3)):
            with self.subTest(p=p, c=c), tempfile.TemporaryDirectory() as tmp:
                nodes = [1500, 3000, 6000, 12000]
                ladder(tmp, {n: [exact(n, 50, c, p), exact(n, 80, 2 * c, p)] for n in nodes})
                doc = run(tmp)
                self.assertEqual([r["nodes"] for r in doc["rungs"]], nodes)
                for row, q_star in zip(self.rows(doc), (50, 80)):
                    self.assertAlmostEqual(row["order"], p, delta=1e-6)
                    self.assertAlmostEqual(row["estimate"], q_star, delta=1e-6 * q_star)
                    self.assertIn("observed", row["method"])
                    for g in row["rungs"]:
                        self.assertAlmostEqual(g["rel_error"], (g["mean"] - q_star) / q_star,
                                               delta=1e-9)

    def test_two_rungs_assume_first_order(self):
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {n: [exact(n, 50, -300, 1.0)] * 2 for n in (3000, 6000)})
            row = self.rows(run(tmp))[0]
            self.assertIn("assumed", row["method"])
            self.assertEqual(row["order"], 1.0)
            self.assertAlmostEqual(row["estimate"], 50, delta=1e-9)  # exact at first order

    def test_non_monotone_is_not_trusted_with_an_observed_order(self):
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {1500: [40, 40], 3000: [48, 48], 6000: [46, 46]})
            row = self.rows(run(tmp))[0]
            self.assertIn("assumed", row["method"])
            self.assertIn("do not converge monotonically", row["method"])

    def test_noise_presets_and_errors(self):
        with tempfile.TemporaryDirectory() as tmp:
            # P: 30 % off at 1500, 10 % at 3000, 3 % at 6000, 1 % at 12000 (not exactly a power
            # law, so the estimate moves a little); s.e.m. 0.5 on 100.
            ladder(tmp, {1500: [130] * 2, 3000: [110] * 2, 6000: [103] * 2, 12000: [101] * 2},
                   sem=0.5)
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertTrue(row["finest_step_resolved"])  # 2 > 2 * hypot(0.5, 0.5)
            self.assertGreater(row["estimate_sem"], 0.5)  # the extrapolation amplifies the s.e.m.
            self.assertAlmostEqual(row["estimate"], 100, delta=1.5)
            self.assertEqual(doc["presets"]["quick"]["coarsest_nodes"], 3000)
            self.assertEqual(doc["presets"]["paper"]["coarsest_nodes"], 6000)
            # With s.e.m. 0.5 the 3000-node rung's 10 % is shown within 15 %.
            self.assertEqual(doc["presets"]["quick"]["coarsest_nodes_shown"], 3000)
            self.assertLess(doc["error_bound_2sem"]["3000"], 0.15)
        with tempfile.TemporaryDirectory() as tmp:
            # The same means with s.e.m. 3 (as three seeds give): the rungs' 10 % and 3 % are
            # within 15 % and 5 % at face value, but the seeds cannot show it. The order (3.6)
            # is observed from steps of 7 and 2 that the noise blurs: a fifth of the re-drawn
            # ladders have no estimate and most of the rest assume the order, so no rung is
            # shown within either tolerance, and the estimate is marked unstable.
            ladder(tmp, {1500: [130] * 2, 3000: [110] * 2, 6000: [103] * 2, 12000: [101] * 2},
                   sem=3.0)
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertIn("observed", row["method"])
            self.assertGreater(row["redrawn"]["no_estimate_share"], 0.16)
            self.assertEqual(doc["presets"]["quick"]["coarsest_nodes"], 3000)
            self.assertEqual(doc["presets"]["paper"]["coarsest_nodes"], 6000)
            self.assertIsNone(doc["presets"]["quick"]["coarsest_nodes_shown"])
            self.assertIsNone(doc["presets"]["paper"]["coarsest_nodes_shown"])
            self.assertGreater(doc["error_bound_2sem"]["3000"], 0.15)
        with tempfile.TemporaryDirectory() as tmp:
            # A coarse rung that crosses the estimate (1500 nodes on it, Q* = 98 from the finest
            # three at order 2) while the finer 3000 and 6000 are 12 % and 6 % off is not where
            # the ladder has converged: the face-value rung is the coarsest from which on every
            # rung is within the tolerance.
            ladder(tmp, {1500: [98] * 2, 3000: [110] * 2, 6000: [104] * 2, 12000: [101] * 2})
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertAlmostEqual(row["estimate"], 98, places=6)
            self.assertLess(abs(row["rungs"][0]["rel_error"]), 0.05)
            self.assertGreater(abs(row["rungs"][2]["rel_error"]), 0.05)
            self.assertEqual(doc["presets"]["paper"]["coarsest_nodes"], 12000)
            self.assertEqual(doc["presets"]["quick"]["coarsest_nodes"], 1500)
        with tempfile.TemporaryDirectory() as tmp:
            # One seed per rung: no s.e.m., so nothing is shown and the step's noise is unknown,
            # not zero; the face value stands.
            ladder(tmp, {3000: [104] * 2, 6000: [102] * 2}, sem=None)
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertIsNone(row["estimate_sem"])
            self.assertIsNone(row["finest_step_resolved"])
            self.assertEqual(doc["presets"]["quick"]["coarsest_nodes"], 3000)
            self.assertIsNone(doc["presets"]["quick"]["coarsest_nodes_shown"])
            self.assertIsNone(doc["error_bound_2sem"]["3000"])
            r = subprocess.run([sys.executable, os.path.join(REPO, "pipeline", "plots", "plot_sweep.py"),
                                "--results", tmp, "--convergence-only"], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            text = section(doc)
            self.assertIn("(no s.e.m.)", text)
            self.assertIn("3000 nodes at face value, but no rung is shown", text)
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {3000: [100] * 2, 6000: [100.5] * 2}, sem=1.0)
            self.assertFalse(self.rows(run(tmp))[0]["finest_step_resolved"])

    def test_errors_at_an_assumed_order_match_linear_propagation(self):
        """Two rungs, first order assumed: Q* = (1 + k) Q3 - k Q2 is linear in the rungs and the
        method cannot change, so the re-drawn spread is the linear one, denominator included:
        4000 re-drawn ladders pin a 68 % half-width to about 1.7 %, and 6 % is three and a half
        of those (a swapped rung misses by 22 %)."""
        with tempfile.TemporaryDirectory() as tmp:
            values = {3000: [110] * 2, 6000: [103] * 2}
            # Unequal, so a swapped rung would show; small beside Q* (86), so that the
            # relative errors, which divide by Q*, are linear over the spread as well.
            sems = {3000: 0.2, 6000: 0.5}
            ladder(tmp, values, sem=sems)
            row = self.rows(run(tmp))[0]
            k = row["extrapolation_k"]
            self.assertAlmostEqual(k, 1 / (math.sqrt(2) - 1), places=12)
            q2, q3 = 110.0, 103.0
            est = (1 + k) * q3 - k * q2
            self.assertAlmostEqual(row["estimate"], est, places=9)
            self.assertAlmostEqual(row["estimate_sem"] / math.hypot(k * 0.2, (1 + k) * 0.5), 1.0,
                                   delta=0.06)
            self.assertEqual(row["redrawn"]["other_method_share"], 0.0)
            self.assertTrue(row["redrawn"]["stable"])
            grad = {3000: -k, 6000: 1 + k}
            for g in row["rungs"]:
                n, m = g["nodes"], g["mean"]
                want = math.sqrt(sum((((1.0 if j == n else 0.0) - m / est * grad[j]) / est
                                      * sems[j]) ** 2 for j in (3000, 6000)))
                self.assertAlmostEqual(g["rel_error_sem"] / want, 1.0, delta=0.06)

    def redrawn_by_hand(self, lad, draws=4000, seed=7):
        """An independent re-draw (its own generator and loop) of Q* and each rung's relative
        error: (half 68 % widths of Q*, of each error; share with no estimate)."""
        import random
        from convergence import extrapolate
        rng = random.Random(seed)
        es, rs, none = [], [[] for _ in lad], 0
        for _ in range(draws):
            moved = [(h, m + rng.gauss(0.0, s), s) for h, m, s in lad]
            e = extrapolate(moved)["estimate"]
            if e is None:
                none += 1
                continue
            es.append(e)
            for i, (_, m, _) in enumerate(moved):
                rs[i].append(m / e - 1)

        def hw(v):
            v = sorted(v)
            return 0.5 * (v[int(0.84135 * len(v))] - v[int(0.15865 * len(v))])
        return hw(es), [hw(r) for r in rs], none / draws

    def test_errors_at_an_observed_order_match_an_independent_redraw(self):
        """With the order observed from the finest three rungs, Q* is nonlinear in them. Small
        noise: the spread is the first-order one, which a central difference of Q* gives here;
        leaving the order's noise out, or treating the third-finest rung as independent of Q*,
        would miss by a factor 1.2-3."""
        sys.path.insert(0, os.path.join(REPO, "pipeline", "sweeps"))
        from convergence import extrapolate, redraw
        nodes = [1500, 3000, 6000, 12000]
        sems = [0.004, 0.006, 0.005, 0.003]
        means = [130.0, 110.0, 103.0, 101.0]
        lad = [(h_of(n), m, s) for n, m, s in zip(nodes, means, sems)]
        est = extrapolate(lad)
        self.assertTrue(est["order_observed"])
        est_sem, rel_sems, summary = redraw(lad, est, "L0", 36)
        self.assertTrue(summary["stable"])
        # First order by hand: central differences of Q* in each rung.
        grad = []
        for j in range(4):
            d = 1e-5
            up = [(h, m + (d if i == j else 0), s) for i, (h, m, s) in enumerate(lad)]
            dn = [(h, m - (d if i == j else 0), s) for i, (h, m, s) in enumerate(lad)]
            grad.append((extrapolate(up)["estimate"] - extrapolate(dn)["estimate"]) / (2 * d))
        self.assertEqual(grad[0], 0.0)  # the coarsest rung is not one Q* is made from
        self.assertNotEqual(grad[1], 0.0)  # the third-finest enters through the order
        linear = math.sqrt(sum((g * s) ** 2 for g, s in zip(grad, sems)))
        self.assertAlmostEqual(est_sem / linear, 1.0, delta=0.06)
        hw_e, hw_r, none = self.redrawn_by_hand(lad)
        self.assertEqual(none, 0.0)
        self.assertAlmostEqual(est_sem / hw_e, 1.0, delta=0.08)
        for i in range(len(nodes)):
            self.assertAlmostEqual(rel_sems[i] / hw_r[i], 1.0, delta=0.08)

    def test_large_noise_changes_the_method(self):
        """Rungs 9, 10, 10.8403 at h ratio sqrt(2) with s.e.m. 0.1: the order is observed
        (0.50, at the bottom of its range) and Q* = 15.3, while a shift of 0.007 in the finest
        mean makes the order assumed and Q* 12.9. A derivative at the means quotes Q* = 15.3 +- 8;
        the re-drawn ladders change method or lose the estimate in about half the draws, and
        their spread is what the seeds allow."""
        sys.path.insert(0, os.path.join(REPO, "pipeline", "sweeps"))
        from convergence import extrapolate, redraw
        lad = [(h_of(n), m, 0.1) for n, m in ((3000, 9.0), (6000, 10.0), (12000, 10.8403))]
        est = extrapolate(lad)
        self.assertTrue(est["order_observed"])
        self.assertAlmostEqual(est["estimate"], 15.26, delta=0.01)
        moved = lad[:2] + [(lad[2][0], 10.8475, 0.1)]
        self.assertFalse(extrapolate(moved)["order_observed"])
        est_sem, rel_sems, summary = redraw(lad, est, "L0", 5)
        self.assertGreater(summary["other_method_share"], 0.15)
        self.assertGreater(summary["no_estimate_share"], 0.15)
        self.assertFalse(summary["stable"])
        self.assertFalse(summary["mostly_estimable"])
        hw_e, hw_r, none = self.redrawn_by_hand(lad)
        self.assertAlmostEqual(none, summary["no_estimate_share"], delta=0.03)
        self.assertAlmostEqual(est_sem / hw_e, 1.0, delta=0.1)
        self.assertLess(est_sem, 2.0)

    def test_redrawn_ladders_without_an_estimate_show_nothing(self):
        """Steps of 10 then 9 per doubling with s.e.m. 1: the central ladder converges (barely)
        and the face value stands, but about a third of the re-drawn ladders have no
        estimate (their finest step is the larger), so no rung is shown within a tolerance
        and the report says the estimate is unstable."""
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {3000: [120] * 2, 6000: [110] * 2, 12000: [101] * 2}, sem=1.0)
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertIsNotNone(row["estimate"])
            self.assertGreater(row["redrawn"]["no_estimate_share"], 0.2)
            self.assertFalse(row["redrawn"]["mostly_estimable"])
            self.assertIsNone(doc["presets"]["quick"]["coarsest_nodes_shown"])
            self.assertIn("*unstable (", section(doc))

    def test_the_table_is_reproducible(self):
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {1500: [130] * 2, 3000: [110] * 2, 6000: [103] * 2, 12000: [101] * 2},
                   sem=3.0)
            self.assertEqual(run(tmp), run(tmp))

    def test_a_missing_mean_or_sem(self):
        with tempfile.TemporaryDirectory() as tmp:
            # No mean at 1500 nodes (e.g. no facets found): the ladder is the other three, and
            # the missing rung has no error; a missing s.e.m. at a rung Q* is made from leaves
            # Q*'s s.e.m. unknown, and no rung is shown.
            ladder(tmp, {1500: [None] * 2, 3000: [110] * 2, 6000: [103] * 2, 12000: [101] * 2},
                   sem={1500: None, 3000: 1.0, 6000: None, 12000: 1.0})
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertIsNotNone(row["estimate"])
            self.assertIsNone(row["rungs"][0]["rel_error"])
            self.assertIsNone(row["estimate_sem"])
            self.assertTrue(all(g["rel_error_sem"] is None for g in row["rungs"]))
            self.assertIsNone(doc["presets"]["quick"]["coarsest_nodes_shown"])
        with tempfile.TemporaryDirectory() as tmp:
            # A missing s.e.m. at a rung Q* does not use (the coarsest of four, the order
            # observed from the finest three) leaves Q*'s s.e.m. and the other rungs' known.
            ladder(tmp, {1500: [130] * 2, 3000: [110] * 2, 6000: [103] * 2, 12000: [101] * 2},
                   sem={1500: None, 3000: 1.0, 6000: 1.0, 12000: 1.0})
            row = self.rows(run(tmp))[0]
            self.assertIn("observed", row["method"])
            self.assertIsNotNone(row["estimate_sem"])
            self.assertIsNone(row["rungs"][0]["rel_error_sem"])
            self.assertTrue(all(g["rel_error_sem"] is not None for g in row["rungs"][1:]))

    def test_refresh_kept_study(self):
        """--refresh-kept remakes a kept study's table from the means it holds (the same table
        the runs gave) and replaces only its report's convergence section."""
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {1500: [130] * 2, 3000: [110] * 2, 6000: [103] * 2, 12000: [101] * 2},
                   sem=3.0)
            doc = run(tmp)
            stale = json.loads(json.dumps(doc))
            for row in stale["rows"]:
                row["estimate_sem"] = 0.0
            with open(os.path.join(tmp, "convergence.json"), "w") as f:
                json.dump(stale, f)
            with open(os.path.join(tmp, "REPORT.md"), "w") as f:
                f.write("# Sweep\n\n## Convergence in resolution\n\nold table\n\n## Files\n\n- x\n")
            r = subprocess.run([sys.executable, SCRIPT, "--refresh-kept", tmp],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(tmp, "convergence.json")) as f:
                self.assertEqual(json.load(f), doc)
            with open(os.path.join(tmp, "REPORT.md")) as f:
                text = f.read()
            self.assertNotIn("old table", text)
            self.assertTrue(text.startswith("# Sweep\n\n## Convergence in resolution\n"))
            self.assertIn("**Presets from the ladder.**", text)
            self.assertTrue(text.endswith("\n## Files\n\n- x\n"))

    def test_a_share_extrapolated_out_of_range_has_no_estimate(self):
        with tempfile.TemporaryDirectory() as tmp:
            # A jump at the finest rung (0.6 -> 0.25) extrapolates a share below 0.
            ladder(tmp, {1500: [0.6] * 2, 3000: [0.62] * 2, 6000: [0.25] * 2}, sem=0.01)
            doc = run(tmp)
            share = self.rows(doc, "single_triangle_fraction")[0]
            self.assertIsNone(share["estimate"])
            self.assertIn("leaves the quantity's range", share["method"])
            self.assertIsNone(share["rungs"][0]["rel_error"])

    def test_no_estimate_where_the_steps_do_not_shrink(self):
        with tempfile.TemporaryDirectory() as tmp:
            # +22 then +23 per doubling: growing like ln N, no limit to extrapolate to.
            ladder(tmp, {1500: [55] * 2, 3000: [77] * 2, 6000: [100] * 2}, sem=1.0)
            doc = run(tmp)
            row = self.rows(doc)[0]
            self.assertIsNone(row["estimate"])
            self.assertTrue(row["method"].startswith("no convergence seen"))
            self.assertIsNone(doc["presets"]["quick"]["coarsest_nodes"])

    def test_refuses_a_grid_that_is_not_a_ladder(self):
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {1500: [1, 1], 3000: [2, 2]})
            with open(os.path.join(tmp, "points.json")) as f:
                pts = json.load(f)
            pts["grid"] = [{"key": "protocol.stages.compress.compaction", "values": ["0.27"]}]
            with open(os.path.join(tmp, "points.json"), "w") as f:
                json.dump(pts, f)
            r = subprocess.run([sys.executable, SCRIPT, "--points",
                                os.path.join(tmp, "points.json"), "--results", tmp],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)
            self.assertIn("mesh.nodes", r.stderr)

    def test_paired_by_seed(self):
        """Each seed's ratio fine / coarse between neighbouring rungs, over the seeds both ran:
        the mean and s.e.m. of the per-seed ratios (exact here), a seed that only one rung ran
        or with a zero coarse value left out, and the report's paired table marking a ratio
        more than 2 s.e.m. from 1. A seed-level offset shared by both rungs cancels in the
        ratio, where the independent means keep it."""
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {3000: [10.0, 20.0], 6000: [11.0, 20.0]}, sem=2.0)
            with open(os.path.join(tmp, "points.json")) as f:
                pts = json.load(f)
            pts["points"] = []
            # P at 3000 nodes per seed; 6000 nodes is 10 % higher in cycle 1 on average (seed 2
            # +12 %, seed 3 +8 %) and the same in cycle 2 (seed 2 +2 %, seed 3 -2 %); seed 4 ran
            # only at 3000 nodes, seed 5's coarse a_fit is zero.
            base = {1: (8.0, 15.0), 2: (10.0, 20.0), 3: (12.0, 25.0), 4: (9.0, 9.0),
                    5: (11.0, 22.0)}
            fine = {1: (8.8, 15.0), 2: (11.2, 20.4), 3: (12.96, 24.5), 5: (12.1, 22.0)}
            for nodes, vals in ((3000, base), (6000, fine)):
                ens_path = os.path.join(tmp, "groups", f"nodes-{nodes}", "ensemble.json")
                with open(ens_path) as f:
                    ens = json.load(f)
                for s, (p1, p2) in vals.items():
                    an = os.path.join(tmp, "runs", f"nodes-{nodes}", f"seed{s}.analysis")
                    os.makedirs(an, exist_ok=True)
                    cyc = [{"cycle": n, "perimeter_P": p, "crease_length_L0": 2 * p,
                            "n_facets": 100.0, "single_triangle_fraction": 0.5,
                            "a_fit": 0.0 if (s == 5 and nodes == 3000) else 1.0,
                            "dangling_fraction": 0.3} for n, p in ((1, p1), (2, p2))]
                    with open(os.path.join(an, "stats.json"), "w") as f:
                        json.dump({"sheet": {"nodes": nodes, "triangles": 2 * nodes,
                                             "area_m2": AREA}, "cycles": cyc}, f)
                    pts["points"].append({"group": f"nodes-{nodes}", "seed": s, "analysis": an})
                    # crumple-analyze ensemble keeps each run's cycles beside its seed.
                    ens["runs"].append({"seed": s, "cycles": cyc})
                with open(ens_path, "w") as f:
                    json.dump(ens, f)
            with open(os.path.join(tmp, "points.json"), "w") as f:
                json.dump(pts, f)
            doc = run(tmp)
            self.assertEqual(len(doc["paired_steps"]), 1)
            step = doc["paired_steps"][0]
            self.assertEqual((step["coarse"], step["fine"], step["seeds"]), (3000, 6000, [1, 2, 3, 5]))
            rows = {(r["quantity"], r["cycle"]): r for r in step["rows"]}
            p1 = rows[("perimeter_P", 1)]
            self.assertEqual(p1["seeds"], [1, 2, 3, 5])
            p2 = rows[("perimeter_P", 2)]
            for row, ratios in ((p1, [1.1, 1.12, 1.08, 1.1]), (p2, [1.0, 1.02, 0.98, 1.0])):
                m = sum(ratios) / 4
                self.assertAlmostEqual(row["mean"], m, places=12)
                self.assertAlmostEqual(row["sem"], math.sqrt(sum((x - m) ** 2 for x in ratios)
                                                             / 3 / 4), places=12)
            self.assertEqual(rows[("a_fit", 1)]["seeds"], [1, 2, 3])
            # The independent means do not see the 10 % in cycle 1 within twice their s.e.m.;
            # the paired ratio does, and the report marks it.
            text = section(doc)
            self.assertIn("**Paired by seed.**", text)
            self.assertIn("6000 / 3000 nodes (seeds 1, 2, 3, 5):", text)
            self.assertIn("| 1 | 1.1 ± 0.0082 * |", text)
            self.assertIn("| 2 | 1 ± 0.0082 |", text)
            with open(os.path.join(tmp, "convergence_paired.csv")) as f:
                lines = f.read().splitlines()
            self.assertEqual(lines[0], "quantity,cycle,coarse_nodes,fine_nodes,seeds,mean_ratio,"
                             "sem,ratios")
            self.assertEqual(len(lines), 1 + 6 * 2)
            # A kept study keeps its paired steps when refreshed (it has no runs to redo them).
            os.rename(os.path.join(tmp, "runs"), os.path.join(tmp, "gone"))
            r = subprocess.run([sys.executable, SCRIPT, "--refresh-kept", tmp],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(tmp, "convergence.json")) as f:
                self.assertEqual(json.load(f)["paired_steps"], doc["paired_steps"])

    def test_figure_and_report_section(self):
        with tempfile.TemporaryDirectory() as tmp:
            ladder(tmp, {n: [exact(n, 50, 4e4, 2), exact(n, 80, 8e4, 2)]
                         for n in (1500, 3000, 6000)}, sem=0.3)
            run(tmp)
            r = subprocess.run([sys.executable, os.path.join(REPO, "pipeline", "plots",
                                                             "plot_sweep.py"),
                                "--results", tmp, "--convergence-only"],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertGreater(os.path.getsize(os.path.join(tmp, "convergence.png")), 1000)
            with open(os.path.join(tmp, "convergence.json")) as f:
                text = section(json.load(f))
            self.assertIn("| 1 | ", text)
            self.assertIn("estimate", text)
            self.assertIn("`quick`", text)
            self.assertIn("nodes at face value", text)
            self.assertIn("Largest |error| + 2 s.e.m. of P over the cycles: 1500 nodes", text)
            # Three seeds per rung: ±2 s.e.m. is a Student's t band with 2 degrees of freedom,
            # P(|T| < 2) = 2 / sqrt(6) = 82 %.
            self.assertIn("With 3 seeds per rung, ±2 s.e.m. covers about 82 %", text)
            from make_sweep_report import t_coverage
            self.assertAlmostEqual(t_coverage(2.0, 2), 2 / math.sqrt(6), places=9)
            self.assertAlmostEqual(t_coverage(2.0, 1), 2 / math.pi * math.atan(2), places=9)
            self.assertAlmostEqual(t_coverage(1.959964, 10 ** 6), 0.95, places=4)
            for q in ("P (facet perimeters)", "facet count", "dangling crease share"):
                self.assertIn(q, text)


if __name__ == "__main__":
    unittest.main()
