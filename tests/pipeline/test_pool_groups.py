#!/usr/bin/python3
"""pipeline/sweeps/pool_groups.py: two groups.csv groups of disjoint seeds pooled give the mean and
sample s.d. of the union (checked against the pooled raw values), each group's P and their
difference beside the law; shared seeds, different compactions and a missing group exit 2.

usage: test_pool_groups.py   (from the repository root)
"""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(REPO, "pipeline", "sweeps", "pool_groups.py")


def groups_csv(path, group, seeds, D, per_cycle):
    """A kept groups.csv with one group: per cycle the raw P of each seed, summarised."""
    with open(path, "w", newline="") as f:
        f.write("# test\n")
        w = csv.writer(f)
        w.writerow(["group", "compaction", "cycle", "n_runs", "seeds", "perimeter_P_mean",
                    "perimeter_P_std", "perimeter_P_sem"])
        for c, xs in enumerate(per_cycle, start=1):
            s = statistics.stdev(xs)
            w.writerow([group, D, c, len(xs), " ".join(map(str, seeds)), statistics.mean(xs), s,
                        s / len(xs) ** 0.5])


class PoolGroups(unittest.TestCase):
    A = [[10.0, 12.0, 15.0], [18.0, 20.0, 27.0]]
    B = [[7.0, 8.0, 9.5], [20.0, 24.0, 25.0]]

    def run_pool(self, tmp, seeds_b=(4, 5, 6), D_b=0.27):
        a, b = os.path.join(tmp, "a.csv"), os.path.join(tmp, "b.csv")
        groups_csv(a, "g", (1, 2, 3), 0.27, self.A)
        groups_csv(b, "h", seeds_b, D_b, self.B)
        out = os.path.join(tmp, "pooled")
        return subprocess.run([sys.executable, SCRIPT, a + ":g", b + ":h", "-o", out],
                              capture_output=True, text=True), out

    def test_pooled_is_the_union(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, out = self.run_pool(tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out + ".csv") as f:
                rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
            self.assertEqual(len(rows), 2)
            for row, xa, xb in zip(rows, self.A, self.B):
                union = xa + xb
                self.assertAlmostEqual(float(row["P_mean"]), statistics.mean(union))
                self.assertAlmostEqual(float(row["P_std"]), statistics.stdev(union))
                self.assertAlmostEqual(float(row["P_sem"]), statistics.stdev(union) / 6 ** 0.5)
                self.assertAlmostEqual(float(row["P_b_minus_a"]),
                                       statistics.mean(xb) - statistics.mean(xa))
                self.assertEqual(row["runs"], "6")
            # The law at 0.27: 52 (1 - 0.27) ln(1 + 0.1 n / 0.27), 11.96 L0 after cycle 1.
            self.assertAlmostEqual(float(rows[0]["law"]), 11.96, places=2)
            with open(out + ".md") as f:
                self.assertIn("| 1 | 12.3 ± 1.5 | 8.2 ± 0.7 | -4.2 ± 1.6 |", f.read())

    def test_refusals(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _ = self.run_pool(tmp, seeds_b=(3, 4, 5))
            self.assertEqual(r.returncode, 2)
            self.assertIn("share seeds 3", r.stderr)
            r, _ = self.run_pool(tmp, D_b=0.45)
            self.assertEqual(r.returncode, 2)
            self.assertIn("compaction 0.27", r.stderr)
            r = subprocess.run([sys.executable, SCRIPT, os.path.join(tmp, "a.csv") + ":zz",
                                os.path.join(tmp, "b.csv") + ":h", "-o", os.path.join(tmp, "x")],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)
            self.assertIn("no group 'zz'", r.stderr)


if __name__ == "__main__":
    unittest.main()
