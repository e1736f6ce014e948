#!/usr/bin/python3
"""Ensemble statistics over several runs of one protocol: reads each run's stats.json
(crumple-analyze output) and writes ensemble.json plus ensemble.csv with

- per cycle, the mean, standard deviation and standard error of the mean (s.e.m.) over seeds of
  the crease length (plastic-edge length l/L0 and the facet-perimeter length P of
  docs/STATISTICS.md §2.1), their per-cycle increments, the dangling fraction 1 - P/(l/L0), the
  facet count, the single-triangle facet fraction, the shape parameters a_fit and a_univ and
  their difference, and the KS test results (docs/STATISTICS.md §3.7);
- per cycle and stage, the new crease length made in each stage and the share made after the
  last compress stage of the cycle;
- per cycle and crease threshold, the crease-threshold sensitivity of l, P and the facet count;
- the log law y = C ln(1 + n/n0) (docs/STATISTICS.md §2.2-2.3) fitted to P (the primary
  quantity) and to l/L0 in two ways:
    * increments (primary): the per-cycle increments dy_n = y_n - y_{n-1} of the ensemble mean,
      dy_n = C [ln(1 + n/n0) - ln(1 + (n-1)/n0)], weighted by the seed-to-seed s.e.m. of the
      increments. Increments of different cycles are nearly independent, so chi2/dof and the
      1-sigma errors mean what they say;
    * cumulative (correlated): y_n of the ensemble mean weighted by its s.e.m. The y_n share
      every earlier increment, so their errors are strongly correlated; chi2/dof is too small
      and the errors too optimistic. Kept for comparison only.
  With the run's compaction D known, c1 = C/(1 - D) and c2 = D/n0 with their errors.

Keys that older stats.json files lack (stages, threshold sensitivity, dangling and single-
triangle fractions) are reported as not available, with a note, instead of failing.

usage: ensemble.py -o results/ensemble.json runs/.../seed1.analysis/stats.json ...
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, law_constants, load_json  # noqa: E402

import numpy as np  # noqa: E402

KEYS = ["crease_length_L0", "crease_length_m", "new_crease_length_L0", "perimeter_P",
        "dangling_fraction", "n_facets", "n_single_triangle_facets", "single_triangle_fraction",
        "new_length_share_after_compress", "a_fit", "a_moment", "a_univ", "ks_distance",
        "ks_pvalue", "mean_area_x", "smallest_resolvable_xi"]
FIT_QUANTITIES = ["perimeter_P", "crease_length_L0"]  # P first: it is the primary quantity
KS_LEVEL = 0.05


def stats(values):
    """mean, sd, sem and count of the finite values (None where undefined)."""
    v = np.array([x for x in values if x is not None], float)
    v = v[np.isfinite(v)]
    n = len(v)
    return {"mean": float(v.mean()) if n else None,
            "std": float(v.std(ddof=1)) if n > 1 else None,
            "sem": float(v.std(ddof=1) / math.sqrt(n)) if n > 1 else None,
            "n": n}


def put(row, key, values):
    s = stats(values)
    for k in ("mean", "std", "sem"):
        row[f"{key}_{k}"] = s[k]
    return s


def law_increment(n, C, n0):
    n = np.asarray(n, float)
    return C * (np.log1p(n / n0) - np.log1p((n - 1) / n0))


def law_cumulative(n, C, n0):
    return C * np.log1p(np.asarray(n, float) / n0)


def fit_law(kind, n, y, sigma, D):
    """Fit y = C ln(1 + n/n0) (kind "cumulative") or its increments (kind "increments") by
    least squares; weighted by sigma (absolute) when every sigma is positive, otherwise
    unweighted with errors scaled by the residuals. Returns a dict (with "error" on failure)."""
    from scipy.optimize import curve_fit
    n, y = np.asarray(n, float), np.asarray(y, float)
    model = law_increment if kind == "increments" else law_cumulative
    label = ("increments: dy_n = C [ln(1 + n/n0) - ln(1 + (n-1)/n0)]" if kind == "increments"
             else "cumulative: y_n = C ln(1 + n/n0) (values correlated between cycles)")
    if len(n) < 3:
        return {"model": label, "error": f"needs at least 3 cycles, have {len(n)}"}
    if not np.any(y > 0):
        return {"model": label, "error": "no crease length in any cycle"}
    weighted = sigma is not None and all(s is not None and s > 0 for s in sigma)
    w = 1.0 / np.asarray(sigma, float) ** 2 if weighted else np.ones_like(y)
    # Start from the best n0 of a scan, with C solved linearly at each n0.
    best, best_r = None, np.inf
    for n0 in np.logspace(-3, 4, 281):
        g = model(n, 1.0, n0)
        C = np.sum(w * g * y) / np.sum(w * g * g)
        r = np.sum(w * (y - C * g) ** 2)
        if r < best_r:
            best, best_r = (C, n0), r
    try:
        p, cov = curve_fit(model, n, y, p0=[max(best[0], 1e-9), best[1]],
                           sigma=np.asarray(sigma, float) if weighted else None,
                           absolute_sigma=weighted, bounds=([0, 1e-6], [np.inf, 1e6]),
                           max_nfev=10000)
    except (RuntimeError, ValueError) as e:
        return {"model": label, "error": str(e)}
    C, n0 = float(p[0]), float(p[1])
    sC, sn0 = (math.sqrt(cov[i, i]) if np.isfinite(cov[i, i]) else None for i in (0, 1))
    res = (y - model(n, C, n0)) * (np.sqrt(w) if weighted else 1.0)
    out = {"model": label, "C": C, "sigma_C": sC, "n0": n0, "sigma_n0": sn0,
           "corr_C_n0": (float(cov[0, 1] / math.sqrt(cov[0, 0] * cov[1, 1]))
                         if sC and sn0 else None),
           "chi2": float(np.sum(res ** 2)), "dof": len(n) - 2, "weighted": bool(weighted),
           "n0_poorly_constrained": bool(n0 > 1e4 or n0 < 1e-5 or sn0 is None or sn0 > n0),
           "cycles": [int(k) for k in n], "values": [float(v) for v in y],
           "sigmas": [float(s) for s in sigma] if weighted else None,
           "weights_note": ("weighted by the seed-to-seed s.e.m." if weighted else
                            "unweighted (no seed-to-seed s.e.m.: fewer than 2 runs or a zero "
                            "spread); errors scaled by the residuals")}
    if D is not None and 0 < D < 1:
        out["c1"] = C / (1 - D)
        out["sigma_c1"] = sC / (1 - D) if sC is not None else None
        out["c2"] = D / n0
        out["sigma_c2"] = D * sn0 / n0 ** 2 if sn0 is not None else None
    return out


def run_record(path):
    s = load_json(path, "stats.json")
    if "cycles" not in s or not s["cycles"]:
        die(f"{path} has no cycles")
    p = s.get("parameters", {})
    cycles = sorted(s["cycles"], key=lambda c: c["cycle"])
    return {"stats_path": path, "analysis_dir": os.path.dirname(os.path.abspath(path)),
            "seed": s.get("input", {}).get("meta", {}).get("seed"),
            "compaction": s.get("input", {}).get("compaction"),
            "L0_m": s.get("sheet", {}).get("L0_m"),
            "px_per_m": s.get("sheet", {}).get("px_per_m"),
            "threshold": p.get("threshold"),
            "threshold_rule": p.get("threshold_rule"),
            "threshold_note": p.get("threshold_note"),
            "bootstrap_resamples": p.get("bootstrap_resamples"),
            "resolution": s.get("resolution"),
            "warnings": s.get("warnings", []),
            "log_fit": s.get("log_fit"),
            "has_stages": any(c.get("stages") for c in cycles),
            "threshold_sensitivity": s.get("threshold_sensitivity"),
            "cycles": cycles}


def stage_table(runs):
    """Per cycle and stage (index, type): the ensemble statistics of the stage's new and
    cumulative crease length, and of the cycle's share made after its last compress stage."""
    with_stages = [r for r in runs if r["has_stages"]]
    out = {"available": bool(with_stages), "n_runs_with_stages": len(with_stages), "cycles": []}
    if not with_stages:
        out["note"] = ("no per-stage data: the stats.json files have no 'stages' lists (run files "
                       "without /stage_ends, or an older crumple-analyze)")
        return out
    if len(with_stages) < len(runs):
        out["note"] = (f"per-stage data in {len(with_stages)} of {len(runs)} runs; the statistics "
                       "below use those runs only")
    by_cycle = {}
    for r in with_stages:
        for c in r["cycles"]:
            by_cycle.setdefault(c["cycle"], []).append(c)
    for n in sorted(by_cycle):
        cs = by_cycle[n]
        keys = []
        for c in cs:
            for st in c.get("stages") or []:
                k = (st["index"], st["stage"])
                if k not in keys:
                    keys.append(k)
        keys.sort()
        rows = []
        for idx, name in keys:
            vals = [next((st for st in (c.get("stages") or []) if st["index"] == idx and
                          st["stage"] == name), None) for c in cs]
            row = {"index": idx, "stage": name}
            put(row, "new_crease_length_L0", [v["new_crease_length_L0"] for v in vals if v])
            put(row, "crease_length_L0", [v["crease_length_L0"] for v in vals if v])
            # crease length that fell back below the threshold in the stage (when reported)
            put(row, "lost_crease_length_L0", [v.get("lost_crease_length_L0") for v in vals if v])
            row["n_runs"] = sum(1 for v in vals if v)
            rows.append(row)
        entry = {"cycle": n, "stages": rows}
        shares = [c.get("new_length_share_after_compress") for c in cs]
        put(entry, "share_after_compress", shares)
        finite = [s for s in shares if s is not None]
        entry["share_after_compress_max"] = max(finite) if finite else None
        entry["share_after_compress_values"] = shares
        put(entry, "new_crease_length_L0", [c.get("new_crease_length_L0") for c in cs])
        out["cycles"].append(entry)
    return out


def sensitivity_table(runs):
    """Per cycle and threshold (as a factor of c0, or as the absolute value when the factors are
    missing): the ensemble means and s.e.m. of l/L0, P and the facet count."""
    have = [r for r in runs if r.get("threshold_sensitivity")]
    out = {"available": bool(have), "n_runs": len(have), "cycles": []}
    if not have:
        out["note"] = ("no threshold-sensitivity data: the stats.json files have no "
                       "'threshold_sensitivity' (older crumple-analyze)")
        return out
    # key every threshold by its factor of c0 (same for all runs of one protocol); fall back to
    # the absolute threshold
    def keys_of(ts):
        f = ts.get("factors_of_c0")
        t = ts.get("thresholds") or []
        if f and len(f) == len(t):
            return [("factor", round(float(x), 6)) for x in f]
        return [("threshold", round(float(x), 9)) for x in t]
    all_keys = []
    for r in have:
        for k in keys_of(r["threshold_sensitivity"]):
            if k not in all_keys:
                all_keys.append(k)
    all_keys.sort(key=lambda k: k[1])
    out["key_kind"] = all_keys[0][0] if all_keys else None
    out["factors_of_c0"] = [k[1] if k[0] == "factor" else None for k in all_keys]
    thr = {k: [] for k in all_keys}
    data = {}
    for r in have:
        ts = r["threshold_sensitivity"]
        ks = keys_of(ts)
        for k, t in zip(ks, ts.get("thresholds") or []):
            thr[k].append(t)
        for c in ts.get("cycles") or []:
            d = data.setdefault(c["cycle"], {k: {"l": [], "P": [], "nf": []} for k in all_keys})
            for i, k in enumerate(ks):
                for src, dst in (("crease_length_L0", "l"), ("perimeter_P", "P"), ("n_facets", "nf")):
                    v = c.get(src) or []
                    if i < len(v):
                        d[k][dst].append(v[i])
    out["thresholds_mean"] = [stats(thr[k])["mean"] for k in all_keys]
    out["thresholds_spread"] = [(min(thr[k]), max(thr[k])) if thr[k] else None for k in all_keys]
    rule_factors = {(r.get("threshold_rule") or {}).get("factor") for r in runs}
    out["used_factor"] = rule_factors.pop() if len(rule_factors) == 1 else None
    for n in sorted(data):
        entry = {"cycle": n}
        for name, short in (("crease_length_L0", "l"), ("perimeter_P", "P"), ("n_facets", "nf")):
            st = [stats(data[n][k][short]) for k in all_keys]
            entry[name + "_mean"] = [s["mean"] for s in st]
            entry[name + "_sem"] = [s["sem"] for s in st]
        out["cycles"].append(entry)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("stats", nargs="+", help="stats.json files of crumple-analyze")
    ap.add_argument("-o", "--output", required=True, help="ensemble.json to write (CSV beside it)")
    args = ap.parse_args()

    runs = [run_record(p) for p in args.stats]
    compactions = {r["compaction"] for r in runs}
    compaction = compactions.pop() if len(compactions) == 1 else None
    notes = []
    if len({r["compaction"] for r in runs}) > 1:
        notes.append("the runs have different compactions; no experimental law is drawn")
    thresholds = {r["threshold"] for r in runs}
    if len(thresholds) > 1:
        notes.append(f"the runs use different crease thresholds: {sorted(thresholds)}")

    by_cycle = {}
    for r in runs:
        prev = {c["cycle"]: c for c in r["cycles"]}
        for c in r["cycles"]:
            n = c["cycle"]
            before = prev.get(n - 1) if n > 1 else {"crease_length_L0": 0.0, "perimeter_P": 0.0}
            inc = {}
            for q in FIT_QUANTITIES:
                if before is not None and c.get(q) is not None and before.get(q) is not None:
                    inc[q] = c[q] - before[q]
            d = (c["a_fit"] - c["a_univ"]) if (c.get("a_fit") is not None and
                                               c.get("a_univ") is not None) else None
            by_cycle.setdefault(n, []).append((r, c, inc, d))
    table = []
    for n in sorted(by_cycle):
        entries = by_cycle[n]
        row = {"cycle": n, "n_runs": len(entries)}
        for k in KEYS:
            put(row, k, [c.get(k) for _, c, _, _ in entries])
        for q in FIT_QUANTITIES:
            put(row, q + "_increment", [inc.get(q) for _, _, inc, _ in entries])
        put(row, "a_fit_minus_a_univ", [d for _, _, _, d in entries])
        # KS test per run: rejected at 5 % when p < 0.05; p at the bootstrap floor 1/(B+1)
        # means no resample was as far from phi as the data (p is at most the floor)
        ks = []
        for r, c, _, _ in entries:
            p = c.get("ks_pvalue")
            B = r.get("bootstrap_resamples")
            floor = 1.0 / (B + 1) if B else None
            ks.append({"seed": r["seed"], "p": p, "floor": floor,
                       "at_floor": bool(p is not None and floor is not None and p <= floor * (1 + 1e-9)),
                       "rejected": bool(p is not None and p < KS_LEVEL)})
        row["ks_tests"] = ks
        row["ks_n_tested"] = sum(1 for k in ks if k["p"] is not None)
        row["ks_n_rejected"] = sum(1 for k in ks if k["rejected"])
        row["ks_n_at_floor"] = sum(1 for k in ks if k["at_floor"])
        table.append(row)

    def series(key):
        rows = [t for t in table if t[key + "_mean"] is not None]
        sem = [t[key + "_sem"] for t in rows]
        return ([t["cycle"] for t in rows], [t[key + "_mean"] for t in rows],
                sem if all(s is not None and s > 0 for s in sem) else None)

    fits = {}
    for q in FIT_QUANTITIES:
        ni, yi, si = series(q + "_increment")
        nc, yc, sc = series(q)
        fits[q] = {"increments": fit_law("increments", ni, yi, si, compaction),
                   "cumulative": fit_law("cumulative", nc, yc, sc, compaction)}
    fits["note"] = ("increments: primary (errors from the seed-to-seed s.e.m. of each cycle's "
                    "increment; increments of different cycles are close to independent). "
                    "cumulative: the same law on the cumulative means; their errors are "
                    "correlated between cycles, so its chi2/dof and errors are too optimistic.")

    experiment = None
    if compaction is not None and 0 < compaction < 1:
        c1, c2 = law_constants()
        D = compaction
        experiment = {"c1": c1, "c2": c2, "D": D, "C": c1 * (1 - D), "n0": D / c2,
                      "note": "law l/L0 = c1 (1 - D) ln(1 + c2 n/D) (docs/STATISTICS.md §2.1); "
                              "no published uncertainty",
                      "cycles": [{"cycle": t["cycle"],
                                  "law": c1 * (1 - D) * math.log1p(c2 * t["cycle"] / D),
                                  "law_increment": c1 * (1 - D) * (math.log1p(c2 * t["cycle"] / D) -
                                                                   math.log1p(c2 * (t["cycle"] - 1) / D))}
                                 for t in table]}

    rules = {json.dumps(r.get("threshold_rule"), sort_keys=True) for r in runs}
    Bs = {r.get("bootstrap_resamples") for r in runs}
    out = {"compaction": compaction, "n_runs": len(runs), "seeds": [r["seed"] for r in runs],
           "notes": notes,
           "parameters": {"threshold": thresholds.pop() if len(thresholds) == 1 else None,
                          "threshold_rule": json.loads(rules.pop()) if len(rules) == 1 else None,
                          "threshold_note": runs[0].get("threshold_note"),
                          "bootstrap_resamples": Bs.pop() if len(Bs) == 1 else None,
                          "ks_level": KS_LEVEL},
           "runs": runs, "cycles": table,
           "stages": stage_table(runs),
           "threshold_sensitivity": sensitivity_table(runs),
           "fits": fits, "experiment": experiment}
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w") as f:
        json.dump(out, f, indent=2)
    csv_path = os.path.splitext(args.output)[0] + ".csv"
    flat = [{k: v for k, v in t.items() if not isinstance(v, (list, dict))} for t in table]
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(flat[0].keys()))
        w.writeheader()
        w.writerows(flat)
    print(f"ensemble.py: {len(runs)} runs, {len(table)} cycles -> {args.output}, {csv_path}")


if __name__ == "__main__":
    main()
