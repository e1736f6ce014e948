#!/usr/bin/env python3
"""The predictions of the calibrated simulation beside the experiments (issue 36, item 4;
docs/SCIENCE.md). The yield (an angle or a radius) is the one constant fitted (yield_calibration.py: P after
cycle 1 at compaction D equals the experiments' law); everything here is predicted with it,
from the compaction sweep (pipeline/sweeps/compaction.yaml) at that calibrated material:

1. P after cycles 1..N at D against the law c1 (1 - D) ln(1 + c2 n/D) (cycle 1 is the
   calibration, marked so): the ratio, whether it lies within ±20 % (the issue's goal) and
   whether the law lies within 2 s.e.m. of the simulation (the law has no published error).
2. n0 of the law fitted to that group alone (the increments fit of crumple-analyze ensemble)
   against the experiments' D/c2, within a factor 1.5 (the goal).
3. c1 and c2 of the law fitted to every compaction at once (crumple-analyze collapse) against
   52 and 0.1: c1 within 25 %, c2 within a factor 1.5 (the goals), and the collapse's chi2/dof.
4. The facet-area shape per cycle: a_fit (maximum likelihood, mean ± s.e.m. over seeds) against
   the fragmentation model's universal curve at the same mean area, a_univ: within 30 % (the
   goal); and the Kolmogorov-Smirnov test of phi(xi; a_fit) per run at 5 % (the family's shape): a cycle counts as
   not rejecting when fewer than half its runs reject (the goal: at least half the cycles).
5. (Section 4 of the report.) How the growth's shape depends on the crease threshold, a
   convention of the analysis: the same runs counted at the thresholds of their sensitivity
   table (F c0), each as P(n)/P(1) against the law's L(n)/L(1). Not a prediction (a threshold other than the protocol's would be
   calibrated to another yield, and other runs), but the size of what the convention can move.

Writes OUT/PREDICTIONS.md, OUT/predictions.json and the figure (-o). Exit 0; 2 bad input.
"""
import argparse
import json
import math
import os
import statistics
import sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import (add_figure_args, collapses, die, experiment, figure_output, load_ensemble,  # noqa: E402
                    load_json, ratio_of_means, save_figure)

P_BAND = 0.20        # P(n) within ±20 % of the law
N0_FACTOR = 1.5      # n0 within a factor 1.5
C1_BAND = 0.25       # c1 within 25 % of 52
C2_FACTOR = 1.5      # c2 within a factor 1.5 of 0.1
A_BAND = 0.30        # a within 30 % of the universal curve


def within_factor(x, ref, f):
    return x is not None and ref > 0 and x > 0 and ref / f <= x <= ref * f


def crease_rows(ens, law):
    rows = []
    by_n = {c["cycle"]: c for c in law["cycles"]}
    for c in ens["cycles"]:
        n = c["cycle"]
        m, s, ref = c["perimeter_P_mean"], c["perimeter_P_sem"], by_n[n]["law"]
        rows.append({"cycle": n, "P_mean": m, "P_sem": s, "law": ref, "ratio": m / ref,
                     "within_band": abs(m / ref - 1) <= P_BAND,
                     "z": (m - ref) / s if s > 0 else None,
                     "within_2sem": s > 0 and abs(m - ref) <= 2 * s,
                     "role": "calibrated" if n == 1 else "predicted"})
    return rows


def facet_rows(ens):
    rows = []
    for c in ens["cycles"]:
        af, au = c.get("a_fit_mean"), c.get("a_univ_mean")
        tested, rejected = c.get("ks_n_tested", 0), c.get("ks_n_rejected", 0)
        rows.append({"cycle": c["cycle"], "a_fit": af, "a_fit_sem": c.get("a_fit_sem"), "a_univ": au,
                     "ratio": af / au if af and au else None,
                     "within_band": bool(af and au and abs(af / au - 1) <= A_BAND),
                     "ks_tested": tested, "ks_rejected": rejected,
                     "ks_not_rejecting": tested > 0 and 2 * rejected < tested,
                     "single_triangle_fraction": c.get("single_triangle_fraction_mean"),
                     "n_facets": c.get("n_facets_mean"),
                     # The law cut at the mesh's resolution floor (analysis/fits/truncated_shape.hpp):
                     # a_fit there is null in a run whose fit ran to the edge of its range.
                     "n_facets_above_floor": c.get("n_facets_above_floor_mean"),
                     "a_fit_above_floor": c.get("a_fit_above_floor_mean"),
                     "a_fit_above_floor_sem": c.get("a_fit_above_floor_sem"),
                     "a_univ_above_floor": c.get("a_univ_above_floor_mean"),
                     "a_fit_above_floor_runs": c.get("a_fit_above_floor_n", 0),
                     "ks_above_floor_tested": c.get("ks_above_floor_n_tested", 0),
                     "ks_above_floor_rejected": c.get("ks_above_floor_n_rejected", 0),
                     "above_floor_edges": c.get("fit_above_floor_edges") or {}})
    return rows


def sensitivity_keys(ts):
    """The slots of one run's threshold-sensitivity table, keyed as crumple-analyze ensemble
    keys them (analysis/ensemble/ensemble_tables.cpp): by factor of c0 (6 digits) when every
    slot has one, else by threshold (9 digits). Runs may list different slots or another
    order, so a slot is found by its key, never by its position."""
    f, t = ts.get("factors_of_c0") or [], ts.get("thresholds") or []
    if f and len(f) == len(t) and all(x is not None for x in f):
        return [("factor", round(x, 6)) for x in f]
    return [("threshold", round(x, 9)) if x is not None else None for x in t]


def run_series(ens):
    """Per threshold, each run's P per cycle: the ensemble's sensitivity thresholds (each run's
    value found by the slot's key in that run's own table) and the analysis's own threshold
    (each run's cycles)."""
    ts = ens.get("threshold_sensitivity") or {}
    factors, thresholds = ts.get("factors_of_c0") or [], ts.get("thresholds_mean") or []
    runs = ens.get("runs") or []
    series = []
    for k, t in enumerate(thresholds):
        f = factors[k] if k < len(factors) else None
        key = (("factor", round(f, 6)) if f is not None else
               ("threshold", round(t, 9)) if t is not None else None)
        per_run = []
        for r in runs:
            own = r.get("threshold_sensitivity") or {}
            keys = sensitivity_keys(own)
            i = keys.index(key) if key is not None and key in keys else None
            vals = {}
            for c in own.get("cycles", []) if i is not None else []:
                ps = c.get("perimeter_P") or []
                if i < len(ps) and ps[i] is not None:
                    vals[c["cycle"]] = ps[i]
            per_run.append(vals)
        series.append({"factor_of_c0": f, "threshold": t, "role": "sensitivity",
                       "runs": per_run})
    own = ens.get("parameters", {}).get("threshold")
    series.append({"factor_of_c0": None, "threshold": own, "role": "the analysis's own",
                   "runs": [{c["cycle"]: c["perimeter_P"] for c in r.get("cycles", [])
                             if c.get("perimeter_P") is not None} for r in runs]})
    return series


def shape_rows(ens, law):
    """Section 4: per threshold of the ensemble's sensitivity table, and for the analysis's own
    threshold, P(n)/P(1) divided by the law's L(n)/L(1), with P(n) and P(1) the means over
    every run that has both (a run with no crease at cycle 1 counts, with P(1) = 0: leaving it
    out would bias the ratio up). Its error is that of a ratio of correlated means
    (ratio_of_means). Each run's own ratio is listed where its P(1) > 0 (None where it is 0).
    Rows whose mean P(1) is 0, or without a cycle 1 and a later cycle, are left out; the report
    says so."""
    by_n = {c["cycle"]: c["law"] for c in law["cycles"]}
    rows = []
    for s in run_series(ens):
        runs = [v for v in s["runs"] if 1 in v]
        if s["threshold"] is None or not runs:
            continue
        p1s = [v[1] for v in runs]
        m1 = statistics.fmean(p1s)
        if m1 <= 0:
            continue
        cyc = []
        for n in sorted({n for v in runs for n in v}):
            if n == 1 or n not in by_n:
                continue
            pairs = [(v[1], v[n]) for v in runs if n in v]
            if statistics.fmean(a for a, _ in pairs) <= 0:
                continue
            r, sig = ratio_of_means([a for a, _ in pairs], [b for _, b in pairs])
            law_ratio = by_n[n] / by_n[1]
            cyc.append({"cycle": n, "shape_ratio": r / law_ratio,
                        "sigma": sig / law_ratio if sig is not None else None,
                        "n_runs": len(pairs),
                        "per_run": [b / a / law_ratio if a > 0 else None for a, b in pairs]})
        if not cyc:
            continue
        t = s["threshold"]
        e1 = statistics.stdev(p1s) / math.sqrt(len(p1s)) if len(p1s) > 1 else None
        rows.append({"role": s["role"], "factor_of_c0": s["factor_of_c0"], "threshold": t,
                     "fold_angle_deg": math.degrees(2 * math.asin(min(1.0, t / 2))),
                     "P1_mean": m1, "P1_sem": e1, "n_runs": len(runs), "cycles": cyc,
                     "within_band": all(abs(c["shape_ratio"] - 1) <= P_BAND for c in cyc)})
    return sorted(rows, key=lambda r: r["threshold"])


def set_value(point, key):
    """The value a sweep point gave `key` on its command line, or None: its last --set key=...
    (the sweep's own settings come after the preset's, and the last one given wins, as in
    crumple-sim)."""
    given = [arg.split("=", 1)[1] for arg in point["args"] if arg.startswith(key + "=")]
    return given[-1] if given else None


def material_of(points, key):
    """{value of `key` each point ran with}: its --set value, else the protocol file's."""
    values = set()
    for pt in points["points"]:
        given = set_value(pt, key)
        if given is not None:
            values.add(float(given))
            continue
        path = points.get("protocol")
        if not path:
            die(f"the points file gives neither {key} nor the protocol file it ran")
        try:
            with open(path) as f:
                node = yaml.safe_load(f)
            for part in key.split("."):
                node = node[part]
            values.add(float(node))
        except (OSError, KeyError, TypeError, ValueError, yaml.YAMLError) as e:
            die(f"{path}: cannot read {key} the sweep's points ran with ({e})")
    return values


def check_material(points, cal, points_path, cal_path):
    """Predictions are of the calibrated material: every point must have run with the value the
    calibration found (a compaction sweep of another material, or the wrong calibration, would
    otherwise be reported as predicted)."""
    key = cal["calibrated"].get("key") or cal.get("key")
    want = cal["calibrated"].get("key_value")
    if key is None or want is None:
        return
    ran = material_of(points, key)
    off = sorted(v for v in ran if not math.isclose(v, want, rel_tol=1e-9))
    if off:
        die(f"{points_path}: the sweep ran {key} = {', '.join(f'{v:g}' for v in off)}, but "
            f"{cal_path} calibrated {want:g}: the predictions need the calibrated material")


def fmt(x, sig=3):
    return "–" if x is None else f"{x:.{sig}g}"


def yes(b):
    return "yes" if b else "no"


def material_text(cal):
    """The calibrated yield in words, from yield_calibration.py's "calibrated" block (or the
    older one that knew only the angle)."""
    if "angle_deg" in cal:
        return f"The yield fold angle {cal['angle_deg']} ± {cal['sigma_deg']} degrees (c0 = {cal['c0']:.3f})"
    name = cal["key"].split(".")[-1].replace("_", " ")
    c0 = f" (c0 = {cal['c0']:.3f})" if cal.get("c0") is not None else ""
    return f"The {name} {cal['value']} ± {cal['sigma']} {cal['unit']}{c0}"


def report(doc, fig_name):
    L = ["# Predictions of the calibrated simulation against the experiments", ""]
    cal = doc["calibration"]
    L += [f"{material_text(cal)} "
          f"was fitted so that P after cycle 1 at D = {doc['compaction']} equals the experiments' law "
          f"({doc['law_note']}). Nothing else is fitted: every other row is a prediction at that "
          f"material. Resolution: {doc['resolution']}. Uncertainties are the s.e.m. over "
          f"{doc['n_runs']} seeds; the experimental law carries none.", ""]
    L += ["## Goals", "", "| goal | result | reached |", "| --- | --- | --- |"]
    for g in doc["goals"]:
        L.append(f"| {g['goal']} | {g['result']} | {g['reached']} |")
    L += ["", f"## 1. P per cycle at D = {doc['compaction']}", "",
          "| cycle | role | simulation P (L0) | law (L0) | simulation / law | within ±20 % | law within 2 s.e.m. |",
          "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in doc["P"]:
        L.append(f"| {r['cycle']} | {r['role']} | {r['P_mean']:.2f} ± {r['P_sem']:.2f} | {r['law']:.2f} | "
                 f"{r['ratio']:.2f} | {yes(r['within_band'])} | {yes(r['within_2sem'])} |")
    n0 = doc["n0"]
    L += ["", f"The law fitted to this group alone (increments of P): C = {fmt(n0.get('C'))} ± "
          f"{fmt(n0.get('sigma_C'))} L0, n0 = {fmt(n0.get('n0'))} ± {fmt(n0.get('sigma_n0'))} against the "
          f"experiments' C = {doc['law_C']:.1f} L0 and n0 = {doc['law_n0']:.2f}.", "",
          f"![P per cycle against the law]({fig_name})", "", "## 2. The compaction sweep: c1, c2 and the collapse", ""]
    g = doc["global"]
    if g:
        L += [f"Compactions in the fit: {', '.join(str(d) for d in g['compactions'])}. The law fitted to "
              f"every compaction at once (increments of P): c1 = {g['c1']:.3g} ± {g['sigma_c1']:.2g} "
              f"(experiments 52), c2 = {g['c2']:.3g} ± {g['sigma_c2']:.2g} (experiments 0.1), "
              f"χ²/dof = {g['chi2']:.0f}/{g['dof']}"
              + (": the groups collapse onto one curve." if collapses(g) else
                 ": the groups do not collapse onto one curve of the law within their errors."), ""]
    else:
        L += ["The compaction sweep's results hold fewer than two compactions: c1 and c2 (a fit over "
              "compactions) are not predicted.", ""]
    L += ["## 3. Facet-area shape per cycle", "",
          "| cycle | a_fit | a_univ | a_fit / a_univ | within 30 % | KS rejects φ(ξ; a_fit) (runs) | single-triangle facets |",
          "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in doc["facets"]:
        L.append(f"| {r['cycle']} | {fmt(r['a_fit'])} ± {fmt(r['a_fit_sem'], 2)} | {fmt(r['a_univ'])} | "
                 f"{fmt(r['ratio'])} | {yes(r['within_band'])} | {r['ks_rejected']} of {r['ks_tested']} | "
                 f"{fmt(r['single_triangle_fraction'], 2)} |")
    L.append("")
    floor_rows = [r for r in doc["facets"] if r.get("ks_above_floor_tested")]
    if floor_rows:
        L += ["Above the mesh's resolution floor (facets of at least the analysis's "
              "`--facet-floor-triangles` mean triangles, 4 by default), the same law cut at the floor and "
              "fitted with its scale free (docs/STATISTICS.md §3.7): a_fit and the universal a at that "
              "law's mean area where the fit found a maximum inside its range. A fit that stops on "
              "the small-a edge of its search (*a_min*) says the facets above the floor fall off more "
              "steeply than any member of the family allows; no shape is measured there.", "",
              "| cycle | facets above the floor | a_fit | a_univ | runs with a shape | fits at a_min | "
              "KS rejects the cut φ (runs) |",
              "| --- | --- | --- | --- | --- | --- | --- |"]
        for r in floor_rows:
            n_est = r.get("a_fit_above_floor_runs") or 0
            a = (f"{fmt(r['a_fit_above_floor'])} ± {fmt(r['a_fit_above_floor_sem'], 2)}"
                 if r.get("a_fit_above_floor") is not None else "–")
            L.append(f"| {r['cycle']} | {fmt(r['n_facets_above_floor'])} | {a} | "
                     f"{fmt(r['a_univ_above_floor'])} | {n_est} of {r['ks_above_floor_tested']} | "
                     f"{(r.get('above_floor_edges') or {}).get('a_min', 0)} | "
                     f"{r['ks_above_floor_rejected']} of {r['ks_above_floor_tested']} |")
        L.append("")
    rows = doc.get("threshold_shape") or []
    L += ["## 4. The growth's shape against the crease threshold", ""]
    if not rows:
        L += ["No crease threshold of the runs has a mean P > 0 at cycle 1 and a later cycle (or the "
              "ensemble has no per-run threshold-sensitivity table): not tabulated.", ""]
        return "\n".join(L)
    last = max(c["cycle"] for r in rows for c in r["cycles"])
    L += ["A crease is a hinge whose permanent fold exceeds a threshold, a convention (the "
          "experiments' curvature threshold is not published). The same runs counted at other "
          "thresholds give other shapes of growth: below, P(n)/P(1) of the simulation (means over "
          "the seeds) divided by L(n)/L(1) of the law (1 is the law's shape). Only the analysis's "
          "own threshold is calibrated (P(1) = the law's first cycle); at any other the yield "
          "would have to be calibrated again, on other runs, so these rows show how far the "
          "convention can move the growth, not predictions. Errors are those of a ratio of means "
          "whose numerator and denominator are correlated across the seeds (delta method); with "
          "few seeds they are themselves uncertain. The means are over every seed, a seed without "
          "creases at cycle 1 included; the last column gives each seed's own ratio (– where "
          "its P(1) is 0).", "",
          f"| threshold | fold angle (deg) | P(1) (L0) | shape ratio, cycle 2 | cycle {last} | "
          f"range over cycles 2-{last} | within ±20 % | cycle {last} per seed |",
          "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        by = {c["cycle"]: c for c in r["cycles"]}
        t = f"{r['threshold']:.3f}" + (f" ({r['factor_of_c0']:g} c0)" if r["factor_of_c0"] is not None else "")
        name = f"**{t} ({r['role']})**" if r["role"] != "sensitivity" else t

        def cell(n):
            if n not in by:
                return "–"
            c = by[n]
            return f"{c['shape_ratio']:.2f}" + (f" ± {c['sigma']:.2f}" if c["sigma"] is not None else "")
        lo = min(c["shape_ratio"] for c in r["cycles"])
        hi = max(c["shape_ratio"] for c in r["cycles"])
        seeds = (", ".join("–" if x is None else f"{x:.2f}" for x in by[last]["per_run"])
                 if last in by else "–")
        p1 = f"{r['P1_mean']:.2f}" + (f" ± {r['P1_sem']:.2f}" if r["P1_sem"] is not None else "")
        L.append(f"| {name} | {r['fold_angle_deg']:.1f} | {p1} | "
                 f"{cell(2)} | {cell(last)} | {lo:.2f}-{hi:.2f} | {yes(r['within_band'])} | {seeds} |")
    if not any(r["role"] != "sensitivity" for r in rows):
        L.append("")
        L.append("The analysis's own threshold has no mean P > 0 at cycle 1 and a later cycle: not tabulated.")
    L.append("")
    return "\n".join(L)


def plot(doc, path, fmt_):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(9.5, 3.8))
    n = [r["cycle"] for r in doc["P"]]
    law = [r["law"] for r in doc["P"]]
    a1.fill_between(n, [v * (1 - P_BAND) for v in law], [v * (1 + P_BAND) for v in law], color="0.85",
                    label="law ± 20 %")
    a1.plot(n, law, "k--", label="experiments' law")
    a1.errorbar(n, [r["P_mean"] for r in doc["P"]], yerr=[r["P_sem"] for r in doc["P"]], fmt="o",
                color="C0", capsize=3, label="simulation (cycle 1 calibrated)")
    a1.set_xlabel("cycle n")
    a1.set_ylabel(f"P (L0) at D = {doc['compaction']}")
    a1.legend(fontsize=8)
    f = [r for r in doc["facets"] if r["a_fit"] is not None]
    a2.errorbar([r["cycle"] for r in f], [r["a_fit"] for r in f], yerr=[r["a_fit_sem"] or 0 for r in f],
                fmt="o", color="C0", capsize=3, label="a_fit (simulation)")
    a2.plot([r["cycle"] for r in f], [r["a_univ"] for r in f], "k--", label="universal curve a_univ")
    a2.fill_between([r["cycle"] for r in f], [r["a_univ"] * (1 - A_BAND) for r in f],
                    [r["a_univ"] * (1 + A_BAND) for r in f], color="0.85", label="± 30 %")
    a2.set_xlabel("cycle n")
    a2.set_ylabel("facet-area shape a")
    a2.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path, fmt_, 150)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sweep-results", help="results/compaction_flat_unfold (make sweep SWEEP=compaction_flat_unfold)")
    ap.add_argument("--calibration", help="calibration.json of make calibrate-yield")
    ap.add_argument("--replot", metavar="PREDICTIONS_JSON",
                    help="only redraw the figure from a kept predictions.json (make study-figures)")
    ap.add_argument("--points", help="runs/sweeps/compaction/points.json (for the resolution)")
    ap.add_argument("--compaction", type=float, default=0.27)
    ap.add_argument("--group", help="the sweep's group crumpled to --compaction (default "
                    "compaction-D, a compaction sweep's name; a one-group sweep names its own)")
    ap.add_argument("--out")
    add_figure_args(ap)
    a = ap.parse_args()
    a.output, a.format = figure_output(a)
    if a.replot:
        plot(load_json(a.replot, "predictions file"), a.output, a.format)
        return
    if not (a.sweep_results and a.calibration and a.out):
        die("give --sweep-results, --calibration and --out (or --replot PREDICTIONS_JSON)")
    cal = load_json(a.calibration, "yield calibration")
    if "calibrated" not in cal:
        die(f"{a.calibration}: the calibration found no yield")
    points = load_json(a.points, "points file") if a.points else {"points": []}
    if a.points:
        check_material(points, cal, a.points, a.calibration)
    name = a.group or f"compaction-{a.compaction:g}"
    group = os.path.join(a.sweep_results, "groups", name, "ensemble.json")
    ens = load_ensemble(group)
    if ens.get("compaction") != a.compaction:
        die(f"{group}: crumpled to {ens.get('compaction')}, not {a.compaction}")
    # The group's points (optional): the resolution and the analysis options they ran with.
    own = [pt for pt in points["points"] if pt["group"] == name]
    analyze = own[0].get("analyze_args", []) if own else []
    nodes = sorted({n for n in (set_value(pt, "mesh.nodes") for pt in own) if n is not None})
    law = experiment(a.compaction, [c["cycle"] for c in ens["cycles"]])
    P = crease_rows(ens, law)
    facets = facet_rows(ens)
    fit = ens.get("fits", {}).get("perimeter_P", {}).get("increments", {})
    n0 = {k: fit.get(k) for k in ("C", "sigma_C", "n0", "sigma_n0", "c1", "c2")}
    glob = None
    cpath = os.path.join(a.sweep_results, "collapse.json")
    col = load_json(cpath, "collapse file") if os.path.isfile(cpath) else None
    if col and len(col.get("compactions", [])) >= 2:
        gf = col["fits"]["perimeter_P"]["increments"]
        glob = {"compactions": sorted(col["compactions"]), **{k: gf[k] for k in
                ("c1", "sigma_c1", "c2", "sigma_c2", "chi2", "dof", "at_bound")}}
    shape = shape_rows(ens, law)
    predicted = [r for r in P if r["role"] == "predicted"]
    goals = [
        {"goal": f"P(n) within ±20 % of the law, predicted cycles n = 2..{P[-1]['cycle']}",
         "result": f"{sum(r['within_band'] for r in predicted)} of {len(predicted)} cycles "
                   f"(ratios {min(r['ratio'] for r in predicted):.2f}-"
                   f"{max(r['ratio'] for r in predicted):.2f}; cycle 1, the calibration, {P[0]['ratio']:.2f})",
         "reached": yes(bool(predicted) and all(r["within_band"] for r in predicted))},
        {"goal": f"n0 within a factor 1.5 of {law['n0']:.2f}",
         "result": f"{fmt(n0['n0'])} ± {fmt(n0['sigma_n0'])}",
         "reached": yes(within_factor(n0["n0"], law["n0"], N0_FACTOR))},
    ]
    if glob:
        goals += [
            {"goal": "global c1 within 25 % of 52", "result": f"{glob['c1']:.3g} ± {glob['sigma_c1']:.2g}",
             "reached": yes(abs(glob["c1"] / law["c1"] - 1) <= C1_BAND)},
            {"goal": "global c2 within a factor 1.5 of 0.1", "result": f"{glob['c2']:.3g} ± {glob['sigma_c2']:.2g}",
             "reached": yes(within_factor(glob["c2"], law["c2"], C2_FACTOR))}]
    else:
        goals.append({"goal": "global c1 and c2", "result": "fewer than two compactions in the sweep's "
                      "results", "reached": "not tested"})
    nf = len(facets)
    goals += [
        {"goal": "facet shape a within 30 % of the universal curve",
         "result": f"{sum(r['within_band'] for r in facets)} of {nf} cycles", "reached":
         yes(nf > 0 and all(r["within_band"] for r in facets))},
        {"goal": "KS not rejecting φ(ξ; a) at 5 % in at least half the cycles",
         "result": f"{sum(r['ks_not_rejecting'] for r in facets)} of {nf} cycles",
         "reached": yes(2 * sum(r["ks_not_rejecting"] for r in facets) >= nf > 0)}]
    doc = {"what": "predictions of the calibrated simulation beside the experiments",
           "calibration": cal["calibrated"], "compaction": a.compaction, "law_note": law["note"],
           "law_C": law["C"], "law_n0": law["n0"], "n_runs": ens["n_runs"], "seeds": ens.get("seeds"),
           "resolution": (f"{nodes[0]} nodes, analysed at {' '.join(analyze) or 'the default raster'}"
                          if len(nodes) == 1 else "as the compaction sweep's points give it"),
           "source": os.path.relpath(group), "P": P, "n0": n0, "global": glob, "facets": facets,
           "goals": goals, "threshold_shape": shape, "predicted_cycles_within_band": sum(r["within_band"] for r in predicted)}
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "predictions.json"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    plot(doc, a.output, a.format)
    with open(os.path.join(a.out, "PREDICTIONS.md"), "w") as f:
        f.write(report(doc, os.path.relpath(a.output, a.out)))
    print(f"predictions: {a.out}/PREDICTIONS.md")


if __name__ == "__main__":
    main()
