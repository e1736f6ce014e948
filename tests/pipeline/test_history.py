#!/usr/bin/python3
"""pipeline/sweeps/history_test.py on ensembles built here: a history group whose increments
follow the reference curve from its own length agrees with history independence (z about 0),
one that adds twice as much disagrees, a cycle whose length lies beyond the reference is left
out with a note, and the sweep expander turns list-valued grid points into --set lists.

usage: test_history.py   (from the repository root)
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "history_test.py")


def ref_len(k):
    return 10 * math.log1p(k)


def ensemble(lengths, compactions, sem=0.1):
    rows = []
    for n, (l, d) in enumerate(zip(lengths, compactions), 1):
        prev = lengths[n - 2] if n > 1 else 0.0
        row = {"cycle": n, "compaction": d}
        for key in ("perimeter_P", "crease_length_L0"):
            row.update({key + "_mean": l, key + "_sem": sem, key + "_increment_mean": l - prev,
                        key + "_increment_sem": sem})
        rows.append(row)
    return {"cycles": rows, "fits": {}, "stages": {}, "threshold_sensitivity": {}, "runs": [],
            "n_runs": 3}


class History(unittest.TestCase):
    def run_case(self, groups):
        with tempfile.TemporaryDirectory() as tmp:
            pts = {"points": [{"group": g} for g in groups]}
            for g, e in groups.items():
                os.makedirs(os.path.join(tmp, "groups", g))
                with open(os.path.join(tmp, "groups", g, "ensemble.json"), "w") as f:
                    json.dump(e, f)
            with open(os.path.join(tmp, "points.json"), "w") as f:
                json.dump(pts, f)
            r = subprocess.run([sys.executable, SCRIPT, "--points", os.path.join(tmp, "points.json"),
                                "--results", tmp, "--compaction", "0.27"],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(tmp, "history.json")) as f:
                return json.load(f)

    def test_independent_agrees_and_dependent_disagrees(self):
        ref = ensemble([ref_len(k) for k in range(1, 7)], [0.27] * 6)
        # One strong crumple leaves the length of 2.5 reference cycles; from there on the
        # sheet follows the reference (history-independent), or adds twice as much.
        same = [ref_len(2.5)] + [ref_len(2.5 + k) for k in (1, 2)]
        double = [ref_len(2.5)]
        for k in (1, 2):
            double.append(double[-1] + 2 * (ref_len(2.5 + k) - ref_len(2.5 + k - 1)))
        far = [ref_len(5.5), ref_len(6.5)]  # beyond the reference's last cycle but one
        h = self.run_case({"c-0.27": ref, "strong": ensemble(same, [0.09, 0.27, 0.27]),
                           "doubled": ensemble(double, [0.09, 0.27, 0.27]),
                           "far": ensemble(far, [0.045, 0.27])})
        self.assertEqual(h["reference"], "c-0.27")
        rows = {(r["group"], r["cycle"]): r for r in h["tests"]["perimeter_P"]}
        s2 = rows[("strong", 2)]
        self.assertAlmostEqual(s2["k_equivalent"], 2.5, delta=0.05)  # linear interpolation
        self.assertEqual(s2["verdict"], "agree")
        # Linear interpolation of the log curve: close to, not exactly, the true increment.
        self.assertLess(abs(s2["dl_pred"] - (ref_len(3.5) - ref_len(2.5))), 0.05)
        self.assertEqual(rows[("doubled", 2)]["verdict"], "disagree")
        self.assertEqual(rows[("doubled", 3)]["verdict"], "disagree")
        self.assertIn("beyond the reference", rows[("far", 2)]["note"])

    def test_needs_a_reference(self):
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "groups", "a"))
            with open(os.path.join(tmp, "groups", "a", "ensemble.json"), "w") as f:
                json.dump(ensemble([1, 2], [0.09, 0.27]), f)
            with open(os.path.join(tmp, "points.json"), "w") as f:
                json.dump({"points": [{"group": "a"}]}, f)
            r = subprocess.run([sys.executable, SCRIPT, "--points", os.path.join(tmp, "points.json"),
                                "--results", tmp, "--compaction", "0.27"],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)
            self.assertIn("needs that reference", r.stderr)

    def test_list_valued_grid_points(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "runs")
            r = subprocess.run([sys.executable, os.path.join(REPO, "pipeline", "sweeps",
                                                             "expand_sweep.py"),
                                os.path.join(REPO, "pipeline", "sweeps", "history.yaml"),
                                "--out-dir", out, "--results", os.path.join(tmp, "res")],
                               cwd=REPO, capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(out, "points.json")) as f:
                doc = json.load(f)
            self.assertEqual(doc["history"], 0.27)
            groups = [p["group"] for p in doc["points"]][::3]
            self.assertEqual(groups, ["compaction-0.27", "compaction-0.09-0.27",
                                      "compaction-0.45-0.27", "compaction-0.63-0.63-0.27"])
            self.assertIn("protocol.stages.compress.compaction=[0.63,0.63,0.27]",
                          doc["points"][-1]["args"])


if __name__ == "__main__":
    unittest.main()
