#!/usr/bin/python3
"""The convergence table of a sweep over node count (pipeline/sweeps/convergence.yaml; issue 36):
for each statistic and cycle, the ensemble mean ± s.e.m. at every resolution, a Richardson
estimate of the converged value and each resolution's relative error against it.

Resolution is measured by the mesh's length scale h = sqrt(A / T) (sheet area over triangle
count, from each run's stats.json), so h ∝ N^-1/2. A statistic is modelled as
    Q(h) = Q* + C h^p.
With three or more rungs the order p is solved from the finest three (any ratios, by bisection);
it is accepted when the differences keep their sign and 0.5 <= p <= 4, and the estimate is then
Q* = Q3 + (Q3 - Q2) / ((h2/h3)^p - 1) from the finest two. When the step between the finest
rungs is no smaller than the one before (same sign), nothing converges yet and there is no
estimate. Otherwise (two rungs, or a non-monotone or out-of-range order) p = 1 is assumed and
the row says so; with a single rung there is no estimate. The errors come from the ladder
re-drawn 4000 times, each rung's mean normal about itself with its s.e.m. (independent
ensembles), and the estimate made again each time: Q*'s s.e.m., and each rung's relative error
(Q - Q*) / Q* with its s.e.m., as half the central 68 % interval of the re-drawn values. That
counts the rung's own noise, Q*'s (including the observed order's, so the third-finest rung
enters too), their correlation where the rung is one Q* is made from, and, where the s.e.m. is
as large as the steps between rungs, re-drawn ladders whose method changes (observed <-> assumed
order, or no estimate): a row whose method fewer than 84 % of them keep is marked unstable, and
one that fewer than 84 % of them give an estimate shows no rung within a tolerance. Where the
change between the finest two rungs is within twice their combined s.e.m. the row says the
difference is not resolved by the seeds (the extrapolation is then mostly noise).

Paired by seed: the rungs run the same seeds, and where a seed makes the same random choices on
every mesh (the axial protocol's roll axes; the mesh has its own seed), a seed's runs at two
rungs share what those choices do to them. Each statistic's ratio fine / coarse is therefore
also taken seed by seed between neighbouring rungs, over the seeds both ran: its mean and the
s.e.m. of that mean over the seeds (convergence.json "paired_steps", convergence_paired.csv).
Where the choices make most of the seed-to-seed spread, as in axial crumpling, the paired
ratio is far tighter than the ratio of two independent means; where they do not, it is no worse.

Writes RESULTS/convergence.json and RESULTS/convergence.csv, and names the coarsest rung from
which on P per cycle is within 15 % and within 5 % of its estimate in every cycle and at every
finer rung (the presets' rule): at face value, and shown, where the error and twice its s.e.m.
together stay within the tolerance (a ladder whose seeds cannot tell the tolerance from zero,
or that has no s.e.m., shows no rung, whatever its means say). Both trust the model Q* + C h^p:
an assumed order, or a step marked as noise, makes every error less certain than quoted.

usage: convergence.py --points runs/sweeps/NAME/points.json --results results/NAME
       convergence.py --refresh-kept docs/studies/NAME   (a kept study, from the means it holds)
"""
import argparse
import csv
import json
import math
import os
import sys
import zlib

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, load_ensemble, load_json, mean_sem, per_seed, sweep_groups  # noqa: E402

# (ensemble key, label, unit): the statistics the issue asks for, in the report's order.
QUANTITIES = [("perimeter_P", "P (facet perimeters)", "L0"),
              ("crease_length_L0", "l (creased edges)", "L0"),
              ("n_facets", "facet count", "1"),
              ("single_triangle_fraction", "single-triangle facets", "fraction"),
              ("a_fit", "a (facet-area shape)", "1"),
              ("dangling_fraction", "dangling crease share", "fraction"),
              # How much the sheet folded, whatever the threshold and however many hinge rows
              # carry a fold (analysis/creases/crease_edges.hpp), and the creases' share of it.
              ("plastic_rotation_L0", "plastic rotation (sum of fold angle x length)", "rad L0"),
              ("creased_rotation_share", "creased share of the plastic rotation", "fraction"),
              # How full the mesh's hinge network is: near saturation the mesh, not the sheet,
              # bounds the crease length (analysis/run/analyze_run.hpp).
              ("creased_hinge_share", "creased share of the mesh's hinge length", "fraction")]
ORDER_RANGE = (0.5, 4.0)
ASSUMED_ORDER = 1.0
PRESET_TOLERANCES = {"quick": 0.15, "paper": 0.05}


def has_mean(m):
    """Whether a rung's mean is a number the ladder can use (not missing, not NaN)."""
    return m is not None and math.isfinite(m)


def solve_order(h, q):
    """p with (q1 - q2)/(q2 - q3) = (h1^p - h2^p)/(h2^p - h3^p), h1 > h2 > h3; None when the
    differences change sign or no p in ORDER_RANGE fits."""
    d12, d23 = q[0] - q[1], q[1] - q[2]
    if d12 == 0 or d23 == 0 or (d12 > 0) != (d23 > 0):
        return None
    target = d12 / d23

    def g(p):
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - target

    lo, hi = ORDER_RANGE
    if g(lo) * g(hi) > 0:
        return None
    for _ in range(60):  # g rises with p for h1 > h2 > h3
        mid = 0.5 * (lo + hi)
        if g(lo) * g(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def extrapolate(rungs):
    """rungs: [(h, mean, sem)] coarse to fine. Returns the estimate row (dict)."""
    rungs = [r for r in rungs if has_mean(r[1])]
    if len(rungs) < 2:
        return {"estimate": None, "method": "single rung: no estimate"}
    p, method = None, None
    if len(rungs) >= 3:
        h3 = [r[0] for r in rungs[-3:]]
        q3 = [r[1] for r in rungs[-3:]]
        p = solve_order(h3, q3)
        if p is not None:
            method = f"Richardson, observed order {p:.2f} (finest three rungs)"
        else:
            d12, d23 = q3[0] - q3[1], q3[1] - q3[2]
            if d12 and d23 and (d12 > 0) == (d23 > 0) and abs(d23) >= abs(d12):
                # The quantity keeps moving as fast or faster with each refinement: nothing to
                # extrapolate from, and an assumed order would invent a limit.
                return {"estimate": None, "method": "no convergence seen: the step between the "
                        f"finest rungs ({-d23:+.3g}) is not smaller than the one before "
                        f"({-d12:+.3g})"}
    if p is None:
        p = ASSUMED_ORDER
        method = (f"Richardson, order {ASSUMED_ORDER:g} assumed ("
                  + ("two rungs" if len(rungs) == 2 else
                     "the finest three rungs do not converge monotonically at an order in "
                     f"{ORDER_RANGE[0]:g}-{ORDER_RANGE[1]:g}") + ")")
    (h2, q2, s2), (h3, q3_, s3) = rungs[-2], rungs[-1]
    k = 1.0 / ((h2 / h3) ** p - 1.0)
    est = q3_ + k * (q3_ - q2)
    # Without the finest two rungs' s.e.m. (a single seed) whether the seeds resolve the step
    # is unknown, not zero.
    known = s2 is not None and s3 is not None
    step = abs(q3_ - q2)
    resolved = step > 2 * math.hypot(s2, s3) if known else None
    return {"estimate": est, "order": p, "method": method, "order_observed": "observed" in method,
            "finest_step_resolved": resolved, "extrapolation_k": k}


REDRAWS = 4000
# Half the central 68.27 % interval of the re-drawn values: one standard deviation for a normal
# spread, and not blown up by the few re-drawn ladders whose order lands near the bottom of its
# range and throws Q* far away.
CENTRAL = (15.865, 84.135)
# A method (observed or assumed order, or an estimate at all) kept by fewer than this share of
# the re-drawn ladders changes within one s.e.m. of the rungs: the estimate is then partly a
# choice the seeds' noise makes (marked unstable); where fewer than this share have an estimate
# at all, no rung is shown within a tolerance by it.
STABLE_SHARE = 0.84


def used_rungs(ladder):
    """Indices of the rungs `extrapolate` can depend on: the finest three with a mean (the third
    through the order, observed or, when its ladder does not converge, assumed)."""
    finite = [i for i, (_, m, _) in enumerate(ladder) if has_mean(m)]
    return finite[-3:]


def half_width(values):
    lo, hi = np.percentile(values, CENTRAL)
    return float(0.5 * (hi - lo))


def redraw(ladder, est, unit, seed):
    """The errors of Q* and of every rung's relative error r_i = Q_i / Q* - 1, from the ladder
    re-drawn REDRAWS times with each rung's mean normal about itself with its s.e.m. (the rungs
    are independent ensembles). Q* is not linear in the rungs once the order is observed, and
    where the s.e.m. is as large as the steps between rungs (three seeds) a re-drawn ladder may
    change method (observed <-> assumed order) or have no estimate at all, which a derivative at
    the means cannot see; the re-drawn spread counts all of it, including Q* in r_i's
    denominator and its correlation with the rungs it is made from.

    Returns (estimate_sem, [rel_error_sem per rung], summary) with the s.e.m. as half the central
    68 % interval of the re-drawn values that have an estimate, and summary the shares of
    re-drawn ladders with no estimate or another method. A missing s.e.m. at a rung Q* uses
    leaves Q*'s s.e.m. and every error unknown; one at another rung only that rung's error."""
    n = len(ladder)
    used = used_rungs(ladder)
    if any(ladder[i][2] is None for i in used):
        return None, [None] * n, None
    rng = np.random.default_rng(seed)
    kind = est["order_observed"]
    estimates, rels = [], []
    no_est = other = 0
    noise = rng.standard_normal((REDRAWS, n))
    for z in noise:
        moved = [(h, m + s * zj if (s is not None and has_mean(m)) else m, s)
                 for (h, m, s), zj in zip(ladder, z)]
        got = within_range(extrapolate(moved), unit)
        e = got.get("estimate")
        if e is None or e == 0:
            no_est += 1
            continue
        if got["order_observed"] != kind:
            other += 1
        estimates.append(e)
        rels.append([m / e - 1 if has_mean(m) else math.nan for _, m, _ in moved])
    summary = {"redraws": REDRAWS, "no_estimate_share": no_est / REDRAWS,
               "other_method_share": other / REDRAWS}
    summary["stable"] = 1 - summary["no_estimate_share"] - summary["other_method_share"] \
        >= STABLE_SHARE
    # A change between observed and assumed order is inside the spread; re-drawn ladders with
    # no estimate are not, and where they are many the spread is not Q*'s.
    summary["mostly_estimable"] = 1 - summary["no_estimate_share"] >= STABLE_SHARE
    if len(estimates) < REDRAWS / 2:  # mostly no estimate: no spread to quote
        return None, [None] * n, summary
    rels = np.array(rels)
    rel_sems = [half_width(rels[:, i]) if has_mean(m) and s is not None else None
                for i, (_, m, s) in enumerate(ladder)]
    return half_width(estimates), rel_sems, summary


def within_range(est, unit):
    """A share extrapolated outside [0, 1] (or a count below 0) is no estimate: the rungs are
    not in the asymptotic range (a jump between rungs, e.g. where a resolution floor of the
    analysis moves), and the row says so rather than print an impossible value."""
    e = est.get("estimate")
    if e is None:
        return est
    if (unit == "fraction" and not 0.0 <= e <= 1.0) or (unit in ("1", "L0") and e < 0):
        return {"estimate": None, "method": f"{est['method']}; no estimate: the extrapolation "
                f"({e:.3g}) leaves the quantity's range, the rungs are not in the asymptotic range"}
    return est


def rung_of(points, group, results):
    """(nodes, h) of a group from its first run's stats.json."""
    for p in points["points"]:
        if p["group"] == group:
            st = load_json(os.path.join(p["analysis"], "stats.json"), "stats.json")["sheet"]
            return st["nodes"], math.sqrt(st["area_m2"] / st["triangles"])
    die(f"{results}: group {group} has no points")


def convergence_row(key, label, unit, cycle, rungs, vals):
    """One statistic at one cycle: rungs [{"nodes", ...}] coarse to fine, vals [(h, mean, sem,
    runs)] alike. The estimate, its s.e.m. and every rung's relative error with its s.e.m."""
    ladder = [(h, m, s) for h, m, s, _ in vals]
    est = within_range(extrapolate(ladder), unit)
    e = est.get("estimate")
    if e is not None and e != 0:
        # Seeded by the row, so a table made twice is the same table.
        seed = zlib.crc32(f"{key}/{cycle}".encode())
        est["estimate_sem"], rel_sems, est["redrawn"] = redraw(ladder, est, unit, seed)
    else:
        est["estimate_sem"], rel_sems = None, [None] * len(vals)
    per_rung = []
    for r, (h, m, s, n), rel_sem in zip(rungs, vals, rel_sems):
        finite = has_mean(m)
        rel = (m - e) / e if (e is not None and e != 0 and finite) else None
        per_rung.append({"nodes": r["nodes"], "h_m": h, "runs": n, "mean": m, "sem": s,
                         "rel_error": rel, "rel_error_sem": rel_sem if rel is not None else None})
    return {"quantity": key, "label": label, "unit": unit, "cycle": cycle, "rungs": per_rung,
            **est}


def table(points, results):
    groups = sweep_groups(points)
    rungs = []
    for g in groups:
        nodes, h = rung_of(points, g, results)
        rungs.append({"group": g, "nodes": nodes, "h_m": h,
                      "ensemble": load_ensemble(os.path.join(results, "groups", g, "ensemble.json"))})
    rungs.sort(key=lambda r: -r["h_m"])  # coarse to fine
    n_cycles = min(len(r["ensemble"]["cycles"]) for r in rungs)
    rows = []
    for key, label, unit in QUANTITIES:
        for c in range(n_cycles):
            vals = []
            for r in rungs:
                cyc = r["ensemble"]["cycles"][c]
                vals.append((r["h_m"], cyc.get(key + "_mean"), cyc.get(key + "_sem"),
                             r["ensemble"]["n_runs"]))
            rows.append(convergence_row(key, label, unit,
                                        rungs[0]["ensemble"]["cycles"][c]["cycle"], rungs, vals))
    return rungs, rows


def paired_steps(rungs):
    """Between each pair of neighbouring rungs (coarse to fine), per statistic and cycle, each
    common seed's ratio fine / coarse from the runs the rungs' ensembles hold, with the mean and
    s.e.m. over those seeds. A seed whose coarse value is zero or either value missing is left
    out of that row (its "seeds" say which entered); one seed gives a mean without an s.e.m."""
    steps = []
    for lo, hi in zip(rungs, rungs[1:]):
        rows = []
        seeds = sorted({r["seed"] for r in lo["ensemble"]["runs"]}
                       & {r["seed"] for r in hi["ensemble"]["runs"]})
        for key, label, unit in QUANTITIES:
            a, b = per_seed(lo["ensemble"], key), per_seed(hi["ensemble"], key)
            common = [a.get(s, {}).keys() & b.get(s, {}).keys() for s in seeds]
            for n in sorted(set.intersection(*map(set, common)) if common else ()):
                used = [s for s in seeds if has_mean(a[s].get(n)) and has_mean(b[s].get(n))
                        and a[s][n] != 0]
                ratios = [b[s][n] / a[s][n] for s in used]
                mean, sem = mean_sem(ratios)
                rows.append({"quantity": key, "label": label, "cycle": n, "seeds": used,
                             "ratios": ratios, "mean": mean, "sem": sem})
        steps.append({"coarse": lo["nodes"], "fine": hi["nodes"], "seeds": seeds, "rows": rows})
    return steps


def recompute(doc):
    """The rows of a kept convergence.json made again from the rungs' means and s.e.m. it
    holds (a kept study keeps no runs): how a change to the estimate or its errors reaches the
    studies already in the repository."""
    rows = []
    for old in doc["rows"]:
        vals = [(g["h_m"], g["mean"], g["sem"], g["runs"]) for g in old["rungs"]]
        rows.append(convergence_row(old["quantity"], old["label"], old["unit"], old["cycle"],
                                    old["rungs"], vals))
    return rows


def error_bound(rung, margin):
    """|error| + margin s.e.m. of one rung's row, None when either is unknown (a rung without a
    mean, or without an s.e.m. where one is asked for): unknown is not within any tolerance."""
    rel, sem = rung["rel_error"], rung["rel_error_sem"]
    if rel is None or (margin and sem is None):
        return None
    return abs(rel) + (margin * sem if margin else 0.0)


def coarsest_within(rows, rungs, key, tol, margin=0.0):
    """The coarsest rung from which on every rung's `key` is within tol of its estimate in every
    cycle (a rung within it while a finer one is not is a crossing, not convergence), or None;
    with margin k, |error| + k s.e.m. of the error must be, in rows that keep an estimate under
    the seeds' noise (k = 2: shown within the seeds' errors)."""
    mine = [r for r in rows if r["quantity"] == key and r.get("estimate") is not None]
    if not mine:
        return None

    def ok(i):
        return all((b := error_bound(r["rungs"][i], margin)) is not None and b <= tol
                   and (not margin or mostly_estimable(r)) for r in mine)
    for i, rung in enumerate(rungs):
        if all(ok(j) for j in range(i, len(rungs))):
            return rung["nodes"]
    return None


def mostly_estimable(row):
    """Whether most ladders re-drawn within the seeds' noise have an estimate (unknown: no), so
    that the re-drawn spread is the estimate's."""
    return bool((row.get("redrawn") or {}).get("mostly_estimable"))


def largest_error_bound(rows, rungs, key, nodes):
    """Over the cycles, the largest |error| + 2 s.e.m. of the rung with `nodes`: how close to
    the estimate the seeds show that rung to be. None when no cycle has an estimate or any
    cycle's bound is unknown."""
    i = [r["nodes"] for r in rungs].index(nodes)
    b = [error_bound(r["rungs"][i], 2.0)
         for r in rows if r["quantity"] == key and r.get("estimate") is not None]
    return max(b) if b and None not in b else None


def document(sweep, rungs, rows, paired=None):
    """convergence.json: rungs [{"group", "nodes", "h_m", "runs", "seeds"}] coarse to fine;
    paired: paired_steps' list (a kept study made before it has none)."""
    return {"sweep": sweep,
            "paired_steps": paired or [],
            "resolution_note": "h = sqrt(sheet area / triangles), m; Q(h) = Q* + C h^p",
            "rungs": rungs,
            "presets": {name: {"tolerance": tol,
                               "coarsest_nodes": coarsest_within(rows, rungs, "perimeter_P", tol),
                               "coarsest_nodes_shown": coarsest_within(rows, rungs, "perimeter_P",
                                                                       tol, margin=2.0)}
                        for name, tol in PRESET_TOLERANCES.items()},
            "error_bound_2sem": {str(r["nodes"]): largest_error_bound(rows, rungs, "perimeter_P",
                                                                      r["nodes"]) for r in rungs},
            "rows": rows}


def write(results, doc):
    """convergence.json and convergence.csv into `results`, each replaced whole."""
    os.makedirs(results, exist_ok=True)
    out = os.path.join(results, "convergence.json")
    with open(out + ".new", "w") as f:
        json.dump(doc, f, indent=1)
    os.replace(out + ".new", out)
    out_csv = os.path.join(results, "convergence.csv")
    with open(out_csv + ".new", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["quantity", "unit", "cycle", "nodes", "h_m", "runs", "mean", "sem",
                    "estimate", "estimate_sem", "order", "rel_error", "rel_error_sem"])
        for r in doc["rows"]:
            for g in r["rungs"]:
                w.writerow([r["quantity"], r["unit"], r["cycle"], g["nodes"], f"{g['h_m']:.6g}",
                            g["runs"], g["mean"], g["sem"], r.get("estimate"),
                            r.get("estimate_sem"), r.get("order"), g["rel_error"],
                            g["rel_error_sem"]])
    os.replace(out_csv + ".new", out_csv)
    outs = (out, out_csv)
    if doc.get("paired_steps"):
        out_pair = os.path.join(results, "convergence_paired.csv")
        with open(out_pair + ".new", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["quantity", "cycle", "coarse_nodes", "fine_nodes", "seeds", "mean_ratio",
                        "sem", "ratios"])
            for step in doc["paired_steps"]:
                for r in step["rows"]:
                    w.writerow([r["quantity"], r["cycle"], step["coarse"], step["fine"],
                                " ".join(str(s) for s in r["seeds"]), r["mean"], r["sem"],
                                " ".join(f"{x:.6g}" for x in r["ratios"])])
        os.replace(out_pair + ".new", out_pair)
        outs += (out_pair,)
    return outs


def refresh_kept(folder):
    """A kept study (docs/studies/NAME, `make keep-study`): its table made again from the means
    it holds, and its REPORT.md's convergence section rewritten to match."""
    src = os.path.join(folder, "convergence.json")
    old = load_json(src, "kept convergence table")
    doc = document(old["sweep"], old["rungs"], recompute(old), old.get("paired_steps"))
    outs = write(folder, doc)
    report = os.path.join(folder, "REPORT.md")
    if os.path.isfile(report):
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                        "report"))
        from make_sweep_report import convergence_section
        with open(report) as f:
            text = f.read()
        head = "## Convergence in resolution\n"
        if head not in text:
            die(f"{report}: no '{head.strip()}' section to refresh")
        start = text.index(head)
        end = text.find("\n## ", start + len(head))
        lines = []
        convergence_section(lines.append, doc)
        text = text[:start] + "\n".join(lines) + (text[end:] if end >= 0 else "\n")
        with open(report + ".new", "w") as f:
            f.write(text)
        os.replace(report + ".new", report)
        outs += (report,)
    return doc, outs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", help="runs/sweeps/NAME/points.json")
    ap.add_argument("--results", help="results/NAME (groups/GROUP/ensemble.json)")
    ap.add_argument("--refresh-kept", metavar="FOLDER",
                    help="docs/studies/NAME: remake a kept study's table and report section "
                    "from the means it holds (no runs needed)")
    a = ap.parse_args()
    if a.refresh_kept:
        doc, outs = refresh_kept(a.refresh_kept)
        print(f"convergence.py: {len(doc['rows'])} rows refreshed -> {', '.join(outs)}")
        return
    if not (a.points and a.results):
        ap.error("--points and --results are required (or --refresh-kept FOLDER)")
    points = load_json(a.points, "sweep points file")
    keys = [g["key"] for g in points["grid"]]
    if keys != ["mesh.nodes"]:
        die(f"{a.points}: a convergence ladder varies mesh.nodes alone (grid: {', '.join(keys)})")
    rungs, rows = table(points, a.results)
    doc = document(points["name"],
                   [{k: r[k] for k in ("group", "nodes", "h_m")}
                    | {"runs": r["ensemble"]["n_runs"], "seeds": r["ensemble"]["seeds"]}
                    for r in rungs], rows, paired_steps(rungs))
    outs = write(a.results, doc)
    print(f"convergence.py: {len(rungs)} rungs ({', '.join(str(r['nodes']) for r in rungs)} "
          f"nodes), {len(rows)} rows -> {', '.join(outs)}")


if __name__ == "__main__":
    main()
