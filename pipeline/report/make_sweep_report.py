#!/usr/bin/python3
"""Writes a sweep's REPORT.md (pipeline/sweep.mk) from its points file, the group ensembles
(RESULTS/groups/GROUP/ensemble.json, `crumple-analyze ensemble`), the collapse document
(RESULTS/collapse.json, `crumple-analyze collapse`, when the sweep varies the compaction) and the
figures of pipeline/plots/plot_sweep.py. It fits nothing: every number comes from those files.
Each comparison with the experiments is stated as agree or disagree with the distance in
standard errors of the simulation (the main report's rule, make_report.py AGREE_SEM).

usage: make_sweep_report.py --points runs/sweeps/NAME/points.json --results results/NAME \
                            -o results/NAME/REPORT.md
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import collapses, die, law_constants, load_ensemble, load_json, sweep_groups  # noqa: E402
from make_report import AGREE_SEM, fmt, pm  # noqa: E402

KEYS = [("perimeter_P", "P (facet perimeters, the experiments' measure)"),
        ("crease_length_L0", "l/L0 (creased mesh edges)")]


def verdict(sim, sigma, ref, undetermined=False):
    """'agree (0.8 σ)' / 'disagree (5.1 σ)' / 'not judged (...)', σ the fit's own error.
    `undetermined`: the fit stopped on a bound of its search or its error exceeds the value, so
    the data do not fix the constant and no agreement is claimed."""
    if sim is None or ref is None:
        return "not judged (no fit)"
    if undetermined:
        return "not determined by these cycles (fit on its bound or error > value)"
    if not sigma:
        return "not judged (no uncertainty)"
    z = abs(sim - ref) / sigma
    return f"{'agree' if z <= AGREE_SEM else 'disagree'} ({z:.1f} σ)"


def ratio(sim, ref):
    return "–" if sim is None or not ref else f"{sim / ref:.3g}"


def c2_undetermined(f):
    return bool(f.get("at_bound")) or not f.get("sigma_c2") or f["sigma_c2"] > f["c2"]



def pct(v, s=None):
    if v is None:
        return "–"
    return f"{100 * v:+.1f} %" if s is None else f"{100 * v:+.1f} ± {100 * s:.1f} %"


def convergence_section(add, doc):
    """The ladder's table (pipeline/sweeps/convergence.py): per statistic and cycle, each rung's
    mean ± s.e.m. and relative error against the Richardson estimate."""
    rungs = doc["rungs"]
    add("## Convergence in resolution\n")
    add("Each statistic per cycle at every rung (mean ± s.e.m. over seeds; below it, the relative "
        "error against the estimate), and the Richardson estimate of its converged value with "
        "the order used (`pipeline/sweeps/convergence.py`: Q(h) = Q* + C h^p, h = "
        "sqrt(area / triangles); the order is observed from the finest three rungs when they "
        "converge monotonically, else assumed 1; no estimate where the step between the finest "
        "rungs is no smaller than the one before, or where the extrapolation leaves the "
        "quantity's range). A step between the finest two rungs within "
        "twice their combined s.e.m. is marked *noise*: the seeds do not resolve it. The s.e.m. "
        "of the estimate and of each error is the spread (half the central 68 %) of ladders "
        "re-drawn within the rungs' s.e.m.; an estimate marked *unstable (x %)* is one whose "
        "method (observed or assumed order, or an estimate at all) changes in x % of them; "
        "where more than 16 % of them have no estimate, no rung is shown within a tolerance.\n")
    add("| rung | nodes | h (mm) | runs (seeds) |")
    add("| --- | --- | --- | --- |")
    for r in rungs:
        add(f"| {r['group']} | {r['nodes']} | {1e3 * r['h_m']:.3g} | {r['runs']} "
            f"({', '.join(str(s) for s in r['seeds'])}) |")
    add("")
    labels = {}
    for row in doc["rows"]:
        labels.setdefault(row["quantity"], (row["label"], row["unit"]))
    for q, (label, unit) in labels.items():
        add(f"**{label}** ({unit})\n")
        add("| cycle | " + " | ".join(f"{r['nodes']}" for r in rungs) + " | estimate | order |")
        add("| --- | " + " | ".join("---" for _ in rungs) + " | --- | --- |")
        for row in (x for x in doc["rows"] if x["quantity"] == q):
            cells = [f"{pm(g['mean'], g['sem'])}<br>{pct(g['rel_error'])}" for g in row["rungs"]]
            est = (pm(row["estimate"], row["estimate_sem"])
                   + {True: "", False: " *noise*", None: " (no s.e.m.)"}[row.get("finest_step_resolved", True)]
                   + unstable_note(row.get("redrawn"))
                   if row.get("estimate") is not None else
                   "– (extrapolates out of range)" if "leaves the quantity's range" in row["method"]
                   else "– (no convergence seen)" if row["method"].startswith("no convergence")
                   else "–")
            order = "–" if row.get("order") is None else (
                f"{row['order']:.2f}" + (" (assumed)" if "assumed" in row["method"] else ""))
            add(f"| {row['cycle']} | " + " | ".join(cells) + f" | {est} | {order} |")
        add("")
    add("![convergence of P](convergence.png)\n")
    paired_section(add, doc.get("paired_steps") or [])
    pre = doc.get("presets", {})
    lines = []
    for name, v in pre.items():
        n = v.get("coarsest_nodes")
        text = (f"`{name}` (P within {100 * v['tolerance']:g} % of the estimate in every "
                "cycle): " + (f"{n} nodes at face value" if n else "no rung of this ladder"))
        if n and "coarsest_nodes_shown" in v:
            shown = v["coarsest_nodes_shown"]
            text += (f", shown within the seeds' errors at {shown} nodes" if shown == n else
                     f", shown within the seeds' errors (error + 2 s.e.m.) only from {shown} nodes"
                     if shown else ", but no rung is shown within it by the seeds' errors")
        lines.append(text)
    if lines:
        bounds = doc.get("error_bound_2sem") or {}
        bound = "; ".join(f"{n} nodes {100 * b:.0f} %" for n, b in bounds.items() if b is not None)
        runs = [r.get("runs") for r in doc.get("rungs", []) if r.get("runs")]
        cover = ""
        if runs and min(runs) >= 2:
            cover = (f" With {min(runs)} seeds per rung, ±2 s.e.m. covers about "
                     f"{100 * t_coverage(2.0, min(runs) - 1):.0f} % of the spread of a mean "
                     f"(Student's t, {min(runs) - 1} degrees of freedom), not 95 %.")
        add("**Presets from the ladder.** " + "; ".join(lines) + ". The estimate is only as good "
            "as the finest rungs: where the order is assumed or the finest step is marked "
            "*noise*, the rungs' errors are less certain than their quoted s.e.m."
            + (f" Largest |error| + 2 s.e.m. of P over the cycles: {bound}." if bound else "")
            + cover + "\n")


def paired_section(add, steps):
    """Each statistic's ratio between neighbouring rungs taken seed by seed (convergence.py's
    paired_steps): a table per step, cycles down, statistics across."""
    steps = [s for s in steps if s["rows"]]
    if not steps:
        return
    add("**Paired by seed.** Each seed's ratio of a statistic between neighbouring rungs, fine / "
        "coarse, mean ± s.e.m. over the seeds both rungs ran. A seed that makes the same random "
        "choices on every mesh (the axial protocol's roll axes) shares their effect at both "
        "rungs, so the paired ratio leaves out the spread they cause between seeds, which the "
        "independent means above carry. * marks a ratio more than 2 s.e.m. from 1: a change with "
        "resolution that the seeds resolve.\n")
    for step in steps:
        labels = {}
        for r in step["rows"]:
            labels.setdefault(r["quantity"], r["label"])
        add(f"{step['fine']} / {step['coarse']} nodes (seeds "
            f"{', '.join(str(s) for s in step['seeds'])}):\n")
        add("| cycle | " + " | ".join(labels.values()) + " |")
        add("| --- | " + " | ".join("---" for _ in labels) + " |")
        by = {(r["quantity"], r["cycle"]): r for r in step["rows"]}
        for n in sorted({r["cycle"] for r in step["rows"]}):
            cells = []
            for q in labels:
                r = by.get((q, n))
                if r is None or r["mean"] is None:
                    cells.append("–")
                    continue
                mark = " *" if r["sem"] and abs(r["mean"] - 1) > 2 * r["sem"] else ""
                cells.append(pm(r["mean"], r["sem"]) + mark)
            add(f"| {n} | " + " | ".join(cells) + " |")
        add("")


def unstable_note(redrawn):
    """' *unstable (x %)*' for an estimate whose method the re-drawn ladders change, else ''."""
    if not redrawn or redrawn.get("stable", True):
        return ""
    share = redrawn["no_estimate_share"] + redrawn["other_method_share"]
    return f" *unstable ({100 * share:.0f} %)*"


def t_coverage(k, nu):
    """P(|T| < k) for Student's t with nu degrees of freedom: how much a band of k s.e.m. from
    nu + 1 seeds covers."""
    from scipy.stats import t
    return float(t.cdf(k, nu) - t.cdf(-k, nu))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", required=True)
    ap.add_argument("--results", required=True)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    pts = load_json(a.points, "sweep points file")
    figures = (["crease_length.png"] + (["collapse.png"] if pts.get("collapse") else [])
               + (["convergence.png"] if pts.get("convergence") else []))
    for f in figures:
        if not os.path.isfile(os.path.join(a.results, f)):
            die(f"missing figure {os.path.join(a.results, f)} (run pipeline/plots/plot_sweep.py "
                "first)")
    c1_exp, c2_exp = law_constants()
    groups = sweep_groups(pts)
    ens = {g: load_ensemble(os.path.join(a.results, "groups", g, "ensemble.json")) for g in groups}
    # Every program version and revision the runs record, with how many runs each (a sweep
    # resumed or extended after a commit mixes builds; the report says so rather than name one).
    builds = {}
    for p in pts["points"]:
        st = load_json(os.path.join(p["analysis"], "stats.json"), "stats.json")
        meta = st.get("input", {}).get("meta", {})
        b = f"{meta.get('program_version', '?')} ({meta.get('git_revision', '?')})"
        builds[b] = builds.get(b, 0) + 1
    program = ("program " + next(iter(builds)) if len(builds) == 1 else
               "programs " + "; ".join(f"{b} for {n} run{'' if n == 1 else 's'}" for b, n in builds.items()))

    L = []
    add = L.append
    add(f"# Sweep `{pts['name']}`\n")
    if pts.get("description"):
        add(f"{pts['description']}.\n")
    add(f"- sweep file: `{pts['file']}`; protocol `{pts['protocol']}`; preset `{pts['preset']}` "
        f"({' '.join(pts['preset_sets']) or 'no settings'})")
    if pts.get("runs_of"):
        add(f"- **the runs of the sweep `{pts['runs_of']}`** (made by its rules, the same files), "
            "analysed again here")
    if pts.get("analyze"):
        add(f"- analysed with `crumple-analyze {' '.join(pts['analyze'])}`")
    if pts["set"]:
        add("- fixed on top of the preset: " +
            ", ".join(f"`{s['key']} = {s['value']}`" for s in pts["set"]))
    for g in pts["grid"]:
        add(f"- grid: `{g['key']}` ∈ {{{', '.join(g['values'])}}}")
    add(f"- seeds: {', '.join(str(s) for s in pts['seeds'])}; {len(pts['points'])} runs in "
        f"{len(groups)} group{'' if len(groups) == 1 else 's'}; {program}")
    rest = [s for s in pts.get("sweep_seeds", pts["seeds"]) if s not in pts["seeds"]]
    if rest:
        add(f"- **part of the sweep**: seeds {', '.join(rest)} of the sweep file are not run yet "
            f"(`SWEEP_SEEDS`); `make sweep SWEEP={pts['name']}` completes it, reusing these runs")
    left = [g for g in pts.get("sweep_groups", []) if g not in groups]
    if left:
        add(f"- **part of the sweep**: the groups {', '.join(left)} of the sweep file are not in "
            f"this report (`SWEEP_GROUPS`); `make sweep SWEEP={pts['name']}` completes it, "
            "reusing these runs")
    add("- each run's resolved configuration, seed and program version are in its run file "
        "(`/config`, `/meta`); the runs are listed in "
        f"`{os.path.relpath(a.points, os.path.dirname(a.output) or '.')}`\n")

    add("## Per group\n")
    add("Crease length P at the last cycle (mean ± s.e.m. over seeds), and each group's own fit "
        "of the law to the increments of P (docs/STATISTICS.md §2.3), converted to the "
        f"experiments' constants (c1 = {c1_exp:g}, c2 = {c2_exp:g}; docs/STATISTICS.md §2.1).\n")
    add("| group | D | runs | cycles | P at last cycle | experiment | c1 | c2 |")
    add("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for g in groups:
        e = ens[g]
        D = e.get("compaction")
        last = e["cycles"][-1]
        law = (c1_exp * (1 - D) * __import__("math").log1p(c2_exp * last["cycle"] / D)
               if D and 0 < D < 1 else None)
        f = e["fits"]["perimeter_P"]["increments"]
        c1 = pm(f.get("c1"), f.get("sigma_c1")) if "error" not in f else f"– ({f['error']})"
        c2 = pm(f.get("c2"), f.get("sigma_c2")) if "error" not in f else "–"
        add(f"| {g} | {fmt(D)} | {e['n_runs']} | {len(e['cycles'])} | "
            f"{pm(last.get('perimeter_P_mean'), last.get('perimeter_P_sem'))} | {fmt(law)} | "
            f"{c1} | {c2} |")
    add("")
    add("![crease length per group](crease_length.png)\n")

    if pts.get("collapse"):
        col = load_json(os.path.join(a.results, "collapse.json"), "collapse document")
        add("## The collapse: one law for every compaction\n")
        add("The law l = c1 (1 − D) ln(1 + c2 n/D) fitted to every group at once "
            "(`crumple-analyze collapse`: least squares on the per-cycle increments of the "
            "ensemble means, weighted by their seed-to-seed s.e.m., c1 exact and c2 searched; "
            "the cumulative fit is shown for comparison, its errors are too small because the "
            "cumulative values are correlated between cycles).\n")
        for note in col.get("notes", []):
            add(f"- note: {note}")
        add("")
        add("| measure | fit | c1 | c1 / 52 | c1 against experiment | c2 | c2 / 0.1 | "
            "c2 against experiment | χ²/dof |")
        add("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        summary = {}
        for key, label in KEYS:
            for kind in ("increments", "cumulative"):
                f = col["fits"][key][kind]
                if "error" in f:
                    add(f"| {label} | {kind} | – ({f['error']}) | | | | | | |")
                    continue
                add(f"| {label} | {kind} | {pm(f['c1'], f['sigma_c1'])} | "
                    f"{ratio(f['c1'], c1_exp)} | {verdict(f['c1'], f['sigma_c1'], c1_exp)} | "
                    f"{pm(f['c2'], f['sigma_c2'])} | {ratio(f['c2'], c2_exp)} | "
                    f"{verdict(f['c2'], f['sigma_c2'], c2_exp, c2_undetermined(f))} | "
                    f"{fmt(f['chi2'])}/{f['dof']} |")
                if kind == "increments":
                    summary[key] = f
        add("")
        f = summary.get("perimeter_P")
        if f:
            add("**In plain words.** On P, the experiments' measure, the global fit gives "
                f"c1 = {pm(f['c1'], f['sigma_c1'])} against the experiments' {c1_exp:g} "
                f"({verdict(f['c1'], f['sigma_c1'], c1_exp)}) and c2 = "
                f"{pm(f['c2'], f['sigma_c2'])} against {c2_exp:g} "
                f"({verdict(f['c2'], f['sigma_c2'], c2_exp, c2_undetermined(f))}). "
                + (f"With one compaction ratio this is that group's own fit (χ²/dof = "
                   f"{fmt(f['chi2'])}/{f['dof']}): it tests the growth at that ratio, not a "
                   "collapse, and c1 and c2 trade against each other within it."
                   if len(col.get("compactions", [])) < 2 else
                   f"χ²/dof = {fmt(f['chi2'])}/{f['dof']} says "
                   + ("the law describes all groups within their errors."
                      if collapses(f) else
                      "the groups do not fall on one curve of this law within their errors."))
                + " The experimental constants carry no published uncertainty, and the level "
                "of c1 depends on the reading of the (1 − D) factor (docs/STATISTICS.md §2.4): "
                "the shape (c2, the collapse) is the firmer comparison.\n")
        add("![the collapse](collapse.png)\n")
        add("Per group, the same law fitted to that group alone (from its ensemble):\n")
        add("| D | c1 (P) | c2 (P) | c1 (l/L0) | c2 (l/L0) |")
        add("| --- | --- | --- | --- | --- |")
        for g in col["groups"]:
            fp, fl = g["fits"]["perimeter_P"], g["fits"]["crease_length_L0"]
            cell = lambda f, k: ("– (" + f["error"] + ")" if "error" in f  # noqa: E731
                                 else pm(f.get(k), f.get("sigma_" + k)))
            add(f"| {fmt(g['compaction'])} | {cell(fp, 'c1')} | {cell(fp, 'c2')} | "
                f"{cell(fl, 'c1')} | {cell(fl, 'c2')} |")
        add("")
    if pts.get("convergence"):
        convergence_section(add, load_json(os.path.join(a.results, "convergence.json"),
                                           "convergence document"))
    if pts.get("history") is not None:
        h = load_json(os.path.join(a.results, "history.json"), "history test")
        add(f"## History independence at D = {h['compaction']:g}\n")
        add("The experiments found that the crease length a cycle adds depends only on the length "
            "already there and on that cycle's compaction (docs/STATISTICS.md §2.3). Each row is "
            f"a cycle crumpled at D = {h['compaction']:g} after a different history; the "
            f"reference `{h['reference']}` (D = {h['compaction']:g} in every cycle) predicts the "
            "increment of a sheet with the same length from its own mean curve "
            "(`pipeline/sweeps/history_test.py`); agreement means within "
            f"{AGREE_SEM:g} combined standard errors.\n")
        for note in h.get("notes", []):
            add(f"- note: {note}")
        for key, label in KEYS:
            rows = h["tests"].get(key, [])
            if not rows:
                continue
            add(f"**{label}**\n")
            add("| group | cycle | history before | length before | added | predicted | "
                "added / predicted | verdict |")
            add("| --- | --- | --- | --- | --- | --- | --- | --- |")
            for r in rows:
                hist = ", ".join(f"{c:g}" for c in r["history"])
                if "dl_pred" in r:
                    verdict_text = (f"{r['verdict']} ({r['z']:.1f} s.e.)" if r["z"] is not None
                                    else "not judged (no spread)")
                    add(f"| {r['group']} | {r['cycle']} | {hist} | "
                        f"{pm(r['l_pre'], r['l_pre_sem'])} | {pm(r['dl'], r['dl_sem'])} | "
                        f"{pm(r['dl_pred'], r['dl_pred_sem'])} | {fmt(r['ratio'])} | "
                        f"{verdict_text} |")
                else:
                    add(f"| {r['group']} | {r['cycle']} | {hist} | "
                        f"{pm(r['l_pre'], r['l_pre_sem'])} | {pm(r['dl'], r['dl_sem'])} | – | – | "
                        f"{r['note']} |")
            add("")
        judged = [r for r in h["tests"].get("perimeter_P", []) if r.get("verdict")]
        if judged:
            agree = sum(r["verdict"] == "agree" for r in judged)
            add(f"**In plain words.** On P, {agree} of {len(judged)} history comparisons agree "
                "with history independence within their errors"
                + ("." if agree == len(judged) else
                   "; the others say the added length depends on more than the length already "
                   "there and the compaction.") + "\n")
    add("## Files\n")
    add("- `groups/GROUP/ensemble.json`: each group's ensemble statistics and fits"
        + ("; `collapse.json`: the global fit and the collapsed points" if pts.get("collapse")
           else "")
        + ("; `convergence.json` and `convergence.csv`: the ladder's table"
           if pts.get("convergence") else ""))
    runs_dir = os.path.dirname(pts["points"][0]["run"]).rsplit("/", 1)[0]
    analyses_dir = os.path.dirname(pts["points"][0]["analysis"]).rsplit("/", 1)[0]
    add(f"- the runs and their analyses: `{runs_dir}/GROUP/seedS.h5` and "
        + ("`.analysis/`" if runs_dir == analyses_dir else f"`{analyses_dir}/GROUP/seedS.analysis/`"))
    kept = [p for p in pts["points"] if p.get("kept")]
    if kept:
        metas = [load_json(p["kept"], "kept run summary")["stats"].get("input", {}).get("meta", {})
                 for p in kept]
        versions = sorted({f"{m.get('program_version', '?')} ({str(m.get('git_revision', '?'))[:12]})"
                           for m in metas})
        add(f"- {len(kept)} of the {len(pts['points'])} runs were not made here but analysed from "
            f"the summaries they were kept as (`make keep-runs`; crumple-sim "
            f"{', '.join(versions)}): " + ", ".join(p["name"] for p in kept))
    os.makedirs(os.path.dirname(a.output) or ".", exist_ok=True)
    tmp = a.output + ".new"
    with open(tmp, "w") as f:
        f.write("\n".join(L) + "\n")
    os.replace(tmp, a.output)
    print(f"make_sweep_report.py: wrote {a.output}")


if __name__ == "__main__":
    main()
