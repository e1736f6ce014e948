#!/usr/bin/python3
"""Two kept groups of the same configuration and different seeds pooled into one, per cycle,
from their groups.csv tables (issue 36: more seeds for a prediction without running the first
ones again; docs/studies/README.md). A group's table holds each statistic's mean and standard
deviation over its seeds; the pooled mean weighs each group by its runs, and the pooled standard
deviation adds the spread between the two means to the spread within each (the exact sample
variance of the union), so the pooled figures are those of one group holding all the seeds.
Refused (exit 2) when the seeds overlap or the compactions differ: pooling assumes independent
runs of one configuration, which the caller states by choosing the groups (the sweep files say
what each pins).

For each cycle this writes the pooled P (mean, s.d., s.e.m.), each group's P and its difference
(with the combined s.e.m.), and the law's value at the group's compaction; P is the crease
perimeter the comparisons with the experiments use.

usage: pool_groups.py A/groups.csv:GROUP B/groups.csv:GROUP -o OUT   (writes OUT.csv and OUT.md)
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, experiment, read_csv, write_csv  # noqa: E402

Q = "perimeter_P"


def load_group(spec):
    """{cycle: row} of GROUP in the groups.csv named by 'PATH:GROUP', with its seeds."""
    path, _, group = spec.rpartition(":")
    if not path or not group:
        die(f"{spec}: give PATH/groups.csv:GROUP")
    rows = [r for r in read_csv(path) if r.get("group") == group]
    if not rows:
        die(f"{path}: no group '{group}'")
    seeds = set(rows[0]["seeds"].split())
    return {int(r["cycle"]): r for r in rows}, seeds, f"{os.path.relpath(path)}:{group}"


def pooled(n1, m1, s1, n2, m2, s2):
    """Mean and sample s.d. of the union of two samples given by size, mean and sample s.d."""
    n = n1 + n2
    m = (n1 * m1 + n2 * m2) / n
    ss = (n1 - 1) * s1 ** 2 + (n2 - 1) * s2 ** 2 + n1 * n2 / n * (m1 - m2) ** 2
    return m, math.sqrt(ss / (n - 1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("groups", nargs=2, help="PATH/groups.csv:GROUP, twice")
    ap.add_argument("-o", "--output", required=True, help="OUT (writes OUT.csv and OUT.md)")
    a = ap.parse_args()
    (A, seeds_a, name_a), (B, seeds_b, name_b) = (load_group(g) for g in a.groups)
    if seeds_a & seeds_b:
        die(f"{name_a} and {name_b} share seeds {' '.join(sorted(seeds_a & seeds_b))}: "
            "pooling needs independent runs")
    rows = []
    for c in sorted(set(A) & set(B)):
        ra, rb = A[c], B[c]
        if ra["compaction"] != rb["compaction"]:
            die(f"cycle {c}: compaction {ra['compaction']} in {name_a}, {rb['compaction']} in "
                f"{name_b}")
        n1, n2 = int(ra["n_runs"]), int(rb["n_runs"])
        m1, m2 = float(ra[f"{Q}_mean"]), float(rb[f"{Q}_mean"])
        s1, s2 = float(ra[f"{Q}_std"] or 0), float(rb[f"{Q}_std"] or 0)
        m, s = pooled(n1, m1, s1, n2, m2, s2)
        law = experiment(float(ra["compaction"]), [c])
        law_c = law["cycles"][0]["law"] if law else None
        rows.append({"cycle": c, "compaction": ra["compaction"], "runs": n1 + n2,
                     "P_mean": m, "P_std": s, "P_sem": s / math.sqrt(n1 + n2),
                     "P_a_mean": m1, "P_a_sem": s1 / math.sqrt(n1),
                     "P_b_mean": m2, "P_b_sem": s2 / math.sqrt(n2),
                     "P_b_minus_a": m2 - m1,
                     "P_b_minus_a_sem": math.sqrt(s1 ** 2 / n1 + s2 ** 2 / n2),
                     "law": law_c, "P_over_law": m / law_c if law_c else None})
    if not rows:
        die(f"{name_a} and {name_b} have no cycle in common")
    write_csv(a.output + ".csv", rows,
              f"{name_a} (seeds {' '.join(sorted(seeds_a, key=int))}) pooled with {name_b} "
              f"(seeds {' '.join(sorted(seeds_b, key=int))}) by pipeline/sweeps/pool_groups.py")
    md = [f"# {name_a} and {name_b} pooled", "",
          f"Made by `pipeline/sweeps/pool_groups.py`: seeds {' '.join(sorted(seeds_a, key=int))} "
          f"(a) and {' '.join(sorted(seeds_b, key=int))} (b); P in L0, mean ± s.e.m. over seeds.",
          "", "| cycle | P, a | P, b | b − a | P, pooled | law | pooled / law |",
          "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        md.append(f"| {r['cycle']} | {r['P_a_mean']:.1f} ± {r['P_a_sem']:.1f} | "
                  f"{r['P_b_mean']:.1f} ± {r['P_b_sem']:.1f} | {r['P_b_minus_a']:+.1f} ± "
                  f"{r['P_b_minus_a_sem']:.1f} | {r['P_mean']:.1f} ± {r['P_sem']:.1f} | "
                  + (f"{r['law']:.1f} | {r['P_over_law']:.2f} |" if r["law"] else "– | – |"))
    with open(a.output + ".md.new", "w") as f:
        f.write("\n".join(md) + "\n")
    os.replace(a.output + ".md.new", a.output + ".md")
    print("\n".join(md[4:]))


if __name__ == "__main__":
    main()
