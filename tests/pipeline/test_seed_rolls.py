#!/usr/bin/python3
"""pipeline/sweeps/seed_rolls.py on a runs.csv written here: each run's first roll measured from
the nearer side of the sheet, each later roll's novelty beside its increment of P, the rank
correlations with an exact p-value for few runs (three runs in perfect order: p = 1/3, not 0),
the means of repeated and new rolls; a one-cycle study reports its first rolls only; a file without roll axes, or not a runs.csv, exits 2.

usage: test_seed_rolls.py   (from the repository root)
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "seed_rolls.py")
HEADER = ("group,seed,cycle,compaction,perimeter_P,crease_length_L0,new_crease_length_L0,n_facets,"
          "single_triangle_fraction,a_fit,dangling_fraction,creased_hinge_share,roll_axis_deg,"
          "novelty_deg\n")


def row(seed, cycle, P, axis, novelty=""):
    return f"g,{seed},{cycle},0.27,{P},,,,,,,,{axis},{novelty}\n"


# Three runs: first rolls 24, 17.4 (162.6) and 10.6 (100.6) degrees from a side, P(1) rising as
# the roll nears the side; second rolls 0.5, 9.6 and 65.3 degrees from the first.
RUNS = ("# a kept study's runs.csv\n" + HEADER +
        row(1, 1, 10, 24.1) + row(1, 2, 12, 24.6, 0.5) + row(1, 3, 25, 81.2, 56.7) +
        row(2, 1, 11, 162.6) + row(2, 2, 14, 153.0, 9.6) + row(2, 3, 16, 141.1, 12.0) +
        row(3, 1, 15, 100.6) + row(3, 2, 27, 35.2, 65.3) + row(3, 3, 29, 106.2, 5.7))


def run(tmp, text, *extra):
    path = os.path.join(tmp, "runs.csv")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(tmp, "out")
    r = subprocess.run([sys.executable, SCRIPT, "--runs", path, "-o", out, *extra],
                       capture_output=True, text=True)
    return r, out


def report(test, text):
    """The Markdown and JSON seed_rolls.py writes for a runs.csv that it must accept."""
    with tempfile.TemporaryDirectory() as tmp:
        r, out = run(tmp, text)
        test.assertEqual(r.returncode, 0, r.stderr)
        with open(out + ".md") as f, open(out + ".json") as g:
            return f.read(), json.load(g)


class SeedRolls(unittest.TestCase):
    def test_table_and_correlations(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, out = run(tmp, RUNS)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out + ".json") as f:
                doc = json.load(f)
            sides = [x["first_roll_to_side_deg"] for x in doc["runs"]]
            self.assertEqual(sides, [24.1, 17.4, 10.6])
            self.assertEqual(doc["runs"][2]["cycles"][0],
                             {"cycle": 2, "novelty_deg": 65.3, "P_increment": 12.0})
            s = doc["summary"]
            self.assertAlmostEqual(s["spearman_P1_vs_first_roll_to_side"], -1.0)
            self.assertAlmostEqual(s["p_P1"], 1.0 / 3.0)
            self.assertEqual(s["pairs_increment"], 6)
            self.assertGreater(s["spearman_increment_vs_novelty"], 0.5)
            self.assertAlmostEqual(s["mean_increment_novelty_below_10"], (2 + 3 + 2) / 3)
            self.assertAlmostEqual(s["mean_increment_novelty_above_30"], (13 + 12) / 2)
            self.assertAlmostEqual(s["mean_second_roll_novelty_deg"], (0.5 + 9.6 + 65.3) / 3)
            with open(out + ".md") as f:
                md = f.read()
            self.assertIn("| g | 3 | 10.6° | 15.0 | 65.3°, +12.0 | 5.7°, +2.0 |", md)
            self.assertIn("to the side: -1.00 (p = 0.333) over 3 runs", md)

    def test_one_cycle_study(self):
        """A calibration keeps one cycle: the table has no cycle columns and the report no
        statements about later rolls (none were rolled)."""
        one = "".join(line for line in RUNS.splitlines(keepends=True)
                      if not line.startswith(("g,1,2", "g,1,3", "g,2,2", "g,2,3", "g,3,2", "g,3,3")))
        md, doc = report(self, one)
        self.assertIn("| group | seed | first roll to side | P(1) |\n| --- | --- | --- | --- |\n", md)
        self.assertIn("| g | 3 | 10.6° | 15.0 |\n", md)
        self.assertNotIn("novelty:", md.split("\n\n")[-1])
        self.assertNotIn("increment", md.split("| g | 3")[1])
        self.assertEqual(doc["summary"]["pairs_increment"], 0)

    def test_a_vanishing_p_is_written_as_a_bound(self):
        # Twenty run-cycles whose increment rises with the novelty: scipy's p is far below 1e-3,
        # which three decimals would print as 0.000.
        text = "# runs.csv\n" + HEADER + "".join(
            row(k, 1, 10, 30) + row(k, 2, 10 + 2 * k, 30 + 3 * k, 3 * k)
            + row(k, 3, 10 + 2 * k + 2 * k + 1, 30 + 3 * k + 3 * k + 1.5, 3 * k + 1.5)
            for k in range(1, 11))
        md, _ = report(self, text)
        self.assertIn("novelty: 1.00 (p < 0.001) over 20 run-cycles", md)

    def test_bad_input(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _ = run(tmp, RUNS.replace(",24.1,\n", ",,\n"))  # an axis not recorded
            self.assertEqual(r.returncode, 2)
            self.assertIn("no roll axis recorded", r.stderr)
            r, _ = run(tmp, "a,b\n1,2\n")
            self.assertEqual(r.returncode, 2)
            self.assertIn("not a runs.csv", r.stderr)
            r, _ = run(tmp, RUNS, "--group", "h")
            self.assertEqual(r.returncode, 2)
            self.assertIn("no runs in group h", r.stderr)


if __name__ == "__main__":
    unittest.main()
