#!/usr/bin/python3
"""Ensemble statistics over several runs: reads each run's stats.json (crumple-analyze output),
gives per-cycle mean, standard deviation and standard error over seeds of the crease length
(plastic-edge length and the perimeter-based P of statistics.md section 2.1), facet counts and
shape parameters, fits the log law l = C ln(1 + n/n0) to the ensemble mean weighted by its
standard error (statistics.md section 2.3), and writes ensemble.json plus ensemble.csv.

usage: ensemble.py -o results/ensemble.json runs/.../seed1.analysis/stats.json ...
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, load_json  # noqa: E402

import numpy as np  # noqa: E402

KEYS = ["crease_length_L0", "crease_length_m", "new_crease_length_L0", "perimeter_P", "n_facets",
        "a_fit", "a_moment", "a_univ", "ks_distance", "ks_pvalue", "mean_area_x"]


def fit_log_law(n, y, sigma=None):
    """Least-squares fit of y = C ln(1 + n/n0); returns dict with 1-sigma errors or None."""
    from scipy.optimize import curve_fit
    n, y = np.asarray(n, float), np.asarray(y, float)
    if len(n) < 3 or not np.any(y > 0):
        return None
    f = lambda k, C, n0: C * np.log1p(k / n0)  # noqa: E731
    best = min(np.logspace(-3, 4, 141), key=lambda n0: np.sum(
        (y - f(n, np.dot(np.log1p(n / n0), y) / np.dot(np.log1p(n / n0), np.log1p(n / n0)), n0)) ** 2))
    g = np.log1p(n / best)
    p0 = [np.dot(g, y) / np.dot(g, g), best]
    absolute = sigma is not None and np.all(np.asarray(sigma) > 0)
    try:
        p, cov = curve_fit(f, n, y, p0=p0, sigma=sigma if absolute else None,
                           absolute_sigma=absolute, bounds=([0, 1e-6], [np.inf, 1e6]))
    except (RuntimeError, ValueError) as e:
        return {"error": str(e)}
    r = (y - f(n, *p)) / (np.asarray(sigma) if absolute else 1.0)
    return {"C": p[0], "sigma_C": math.sqrt(cov[0, 0]), "n0": p[1], "sigma_n0": math.sqrt(cov[1, 1]),
            "chi2": float(np.sum(r ** 2)), "dof": len(n) - 2, "weighted": bool(absolute)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("stats", nargs="+", help="stats.json files of crumple-analyze")
    ap.add_argument("-o", "--output", required=True, help="ensemble.json to write (CSV beside it)")
    args = ap.parse_args()

    runs = []
    for path in args.stats:
        s = load_json(path, "stats.json")
        if "cycles" not in s or not s["cycles"]:
            die(f"{path} has no cycles")
        runs.append({"stats_path": path, "analysis_dir": os.path.dirname(path),
                     "seed": s.get("input", {}).get("meta", {}).get("seed"),
                     "compaction": s.get("input", {}).get("compaction"),
                     "L0_m": s.get("sheet", {}).get("L0_m"),
                     "log_fit": s.get("log_fit"), "cycles": s["cycles"]})
    compactions = {r["compaction"] for r in runs}
    compaction = compactions.pop() if len(compactions) == 1 else None

    by_cycle = {}
    for r in runs:
        for c in r["cycles"]:
            by_cycle.setdefault(c["cycle"], []).append(c)
    table = []
    for n in sorted(by_cycle):
        row = {"cycle": n, "n_runs": len(by_cycle[n])}
        for k in KEYS:
            v = np.array([c[k] for c in by_cycle[n] if c.get(k) is not None], float)
            v = v[np.isfinite(v)]
            row[k + "_mean"] = float(v.mean()) if len(v) else None
            row[k + "_std"] = float(v.std(ddof=1)) if len(v) > 1 else None
            row[k + "_sem"] = float(v.std(ddof=1) / math.sqrt(len(v))) if len(v) > 1 else None
        table.append(row)

    def series(key):
        rows = [t for t in table if t[key + "_mean"] is not None]
        n = [t["cycle"] for t in rows]
        y = [t[key + "_mean"] for t in rows]
        sem = [t[key + "_sem"] for t in rows]
        return n, y, (sem if all(s is not None and s > 0 for s in sem) else None)

    out = {"compaction": compaction, "n_runs": len(runs), "runs": runs, "cycles": table,
           "fit_crease_length_L0": fit_log_law(*series("crease_length_L0")),
           "fit_perimeter_P": fit_log_law(*series("perimeter_P"))}
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    import json
    with open(args.output, "w") as f:
        json.dump(out, f, indent=2)
    csv_path = os.path.splitext(args.output)[0] + ".csv"
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        w.writerows(table)
    print(f"ensemble.py: {len(runs)} runs, {len(table)} cycles -> {args.output}, {csv_path}")


if __name__ == "__main__":
    main()
