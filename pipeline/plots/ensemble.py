#!/usr/bin/python3
"""Tabulates the ensemble of runs that `crumple-analyze ensemble` computed: reads its
ensemble.json and writes ensemble.csv (one row per cycle: every scalar of the per-cycle table,
i.e. the mean, seed-to-seed standard deviation and standard error of the mean of each quantity,
then the experimental law and its increment at the ensemble's compaction, when it has one), and
prints the log-law fits.

Nothing is computed here: the ensemble statistics and the fits (y = C ln(1 + n/n0) to the
per-cycle increments and to the cumulative means, weighted by the s.e.m., docs/STATISTICS.md
§2.3) have one implementation, in analysis/ensemble/ (C++); the experimental law is
data/crease_length_law_constants.csv evaluated by common.experiment.

usage: ensemble.py results/ensemble.json [-o results/ensemble.csv]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, experiment, load_ensemble  # noqa: E402


def fit_line(q, kind, f):
    if "C" not in f:
        return f"  {q:<17} {kind:<11} not fitted: {f.get('error', 'no fit')}"
    s = lambda v: "?" if v is None else f"{v:.3g}"  # noqa: E731
    line = (f"  {q:<17} {kind:<11} C = {f['C']:.4g} ± {s(f['sigma_C'])}, "
            f"n0 = {f['n0']:.4g} ± {s(f['sigma_n0'])}, chi2/dof = {f['chi2']:.3g}/{f['dof']}")
    if f.get("c1") is not None:
        line += f", c1 = {f['c1']:.4g} ± {s(f.get('sigma_c1'))}, c2 = {f['c2']:.3g} ± {s(f.get('sigma_c2'))}"
    return line + ("" if f.get("weighted") else " (unweighted)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ensemble", help="ensemble.json written by crumple-analyze ensemble")
    ap.add_argument("-o", "--output", help="CSV to write (default: ensemble.csv beside the JSON)")
    args = ap.parse_args()
    e = load_ensemble(args.ensemble)
    if not e["cycles"]:
        die(f"{args.ensemble} has no cycles")
    out = args.output or os.path.splitext(args.ensemble)[0] + ".csv"

    law = experiment(e.get("compaction"), [c["cycle"] for c in e["cycles"]])
    law_by_cycle = {c["cycle"]: c for c in (law or {}).get("cycles", [])}
    rows = []
    for c in e["cycles"]:
        row = {k: v for k, v in c.items() if not isinstance(v, (list, dict))}
        ref = law_by_cycle.get(c["cycle"], {})
        row["law"] = ref.get("law")
        row["law_increment"] = ref.get("law_increment")
        rows.append(row)
    fields = []
    for r in rows:
        fields += [k for k in r if k not in fields]
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)

    print(f"ensemble.py: {e['n_runs']} runs, {len(rows)} cycles of {args.ensemble} -> {out}")
    for n in e.get("notes", []):
        print(f"  note: {n}")
    for q in ("perimeter_P", "crease_length_L0"):
        for kind in ("increments", "cumulative"):
            print(fit_line(q, kind, e["fits"].get(q, {}).get(kind) or {}))
    if law:
        print(f"  experiment        law         C = {law['C']:.4g}, n0 = {law['n0']:.3g} "
              f"(c1 = {law['c1']:g}, c2 = {law['c2']:g}, D = {law['D']:g})")


if __name__ == "__main__":
    main()
