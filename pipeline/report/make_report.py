#!/usr/bin/python3
"""Writes results/REPORT.md from ensemble.json (`crumple-analyze ensemble`) and the figures of
the plot scripts (crease_length, stages, facets and maps, as .png or .svg after --format, which
must be in images/ beside the report): a plain-words verdict on each compared quantity, the
crease definition and its threshold sensitivity, crease length against the experimental law with
the log-law fits, where the creases were made (per stage), the facet-area statistics with the KS
tests and a resolution warning, the crease maps of one seed, and at the end an index of every
file in images/ with a line on what it shows. The shown seed's crease and facet images of
crumple-analyze are copied into images/ too. Every comparison is stated as agree or disagree
with the distance in standard errors of the simulated ensemble mean; references point at
docs/STATISTICS.md. Links are relative, so the folder can be copied elsewhere whole.

usage: make_report.py --ensemble results/ensemble.json --runs runs/.../seed1.analysis \
                      --preset quick --protocol protocols/axial_crumpling.yaml [--format svg] \
                      -o results/REPORT.md
"""
import argparse
import glob
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import FIG_FORMATS, die, experiment, load_ensemble, load_json  # noqa: E402

AGREE_SEM = 2.0        # agreement: within this many standard errors
SINGLE_TRIANGLE_WARN = 0.20
SHARE_TARGET = 0.15
IMAGES = "images"      # the figures' folder beside the report; links are relative to the report
# the plot scripts' figures (file stem: script, caption in the images index)
FIGURES = {
    "crease_length": ("plot_crease_length.py",
                      "P and ℓ/L0 per cycle: each seed, the ensemble mean ± s.e.m., the log-law fits "
                      "and the experimental law; the per-cycle increments; the dangling fraction"),
    "stages": ("plot_stages.py",
               "new crease length made in each stage of each cycle (ensemble mean ± s.e.m.) and the "
               "share made after compression against the 15 % target"),
    "facets": ("plot_facets.py",
               "facet-area distributions per cycle: density of ξ = x/⟨x⟩ against φ(ξ; a_fit) and "
               "φ(ξ; a_univ), with the one-triangle resolution floor"),
    "maps": ("plot_maps.py",
             "crease maps (red and blue: the two fold senses) and facets coloured by area (mm², "
             "log scale) of the shown seed at the end of each cycle, with scale bars and keys"),
}


def fmt(v, spec=".3g"):
    return "–" if v is None or (isinstance(v, float) and not math.isfinite(v)) else format(v, spec)


def pm(m, s, spec=".3g"):
    if m is None:
        return "–"
    return fmt(m, spec) if s is None else f"{fmt(m, spec)} ± {fmt(s, '.2g')}"


def pct(v):
    return "–" if v is None else f"{100 * v:.0f} %"


def pct_pm(m, s):
    """'19 ± 1.2 %'; the error with two significant digits."""
    if m is None:
        return "–"
    return f"{100 * m:.1f} %" if s is None else f"{100 * m:.1f} ± {100 * s:.2g} %"


def distance(sim, sem, ref):
    """|sim - ref| / sem, or None without a positive s.e.m."""
    if sim is None or ref is None or not sem:
        return None
    return abs(sim - ref) / sem


def judgement(sim, sem, ref, inline=False):
    """'agree (0.8 s.e.)' / 'disagree (5.1 s.e.)' / why it cannot be judged; inline=True gives
    'disagree, 5.1 s.e.' for use inside parentheses."""
    z = distance(sim, sem, ref)
    if z is None:
        return ("not judged: no seed-to-seed spread" if inline else
                "cannot be judged in standard errors (no seed-to-seed spread: fewer than 2 runs)")
    w = "agree" if z <= AGREE_SEM else "disagree"
    return f"{w}, {z:.1f} s.e." if inline else f"{w} ({z:.1f} s.e.)"


def word(sim, sem, ref):
    z = distance(sim, sem, ref)
    return None if z is None else ("agree" if z <= AGREE_SEM else "disagree")


def rule_text(p):
    rule = p.get("threshold_rule")
    t = p.get("threshold")
    if isinstance(rule, dict) and rule.get("kind") == "fraction_of_c0":
        return (f"|p| > {fmt(rule.get('factor'))} c0 = {fmt(rule.get('factor'))} × "
                f"{fmt(rule.get('c0'))} = {fmt(t)}: a fixed fraction of the run's yield curvature "
                "c0 (`integrator.plastic_c0`)")
    if isinstance(rule, dict) and rule.get("kind") == "crease_angle":
        where = ("the protocol's `output.crease_angle`" if rule.get("angle_source") == "config"
                 else "`--crease-angle`")
        return (f"|p| > {fmt(t)} = 2 sin({fmt(rule.get('angle_deg'))}°/2): a permanent fold of more "
                f"than {fmt(rule.get('angle_deg'))} degrees, the same on every mesh ({where})")
    if isinstance(rule, dict) and rule.get("kind") == "absolute":
        return f"|p| > {fmt(t)}, an absolute value given on the command line (`--threshold`)"
    return (f"|p| > {fmt(t)}; the rule it was derived by is not recorded in these stats.json "
            "files (older crumple-analyze)")


def check_figures(img_dir, fig_format):
    """{stem: link} of the plot scripts' figures in `fig_format`; dies naming the first one missing
    (and the format it exists in, if another)."""
    links = {}
    for stem, (script, _) in FIGURES.items():
        path = os.path.join(img_dir, f"{stem}.{fig_format}")
        if not os.path.isfile(path):
            other = [f for f in FIG_FORMATS if f != fig_format and
                     os.path.isfile(os.path.join(img_dir, f"{stem}.{f}"))]
            hint = f"; there is a {stem}.{other[0]}: give --format {other[0]}?" if other else ""
            die(f"missing figure {path} (draw it with pipeline/plots/{script} -o {path} "
                f"--format {fig_format}){hint}")
        links[stem] = f"{IMAGES}/{stem}.{fig_format}"
    return links


def edge_counts(c):
    """The fits above the floor that stopped on an edge of their search, per edge, or –."""
    e = c.get("fit_above_floor_edges") or {}
    parts = [f"{n} {k}" for k, n in (("a_min", e.get("a_min", 0)), ("a_max", e.get("a_max", 0)),
                                      ("θ", e.get("theta", 0))) if n]
    return ", ".join(parts) or "–"


def image_caption(name, shown):
    """One line on what the image `name` in images/ shows."""
    stem, ext = os.path.splitext(name)
    if stem in FIGURES and ext.lstrip(".") in FIG_FORMATS:
        return FIGURES[stem][1] + "."
    m = re.match(r"(crease|facets)_(\d+)\.png$", name)
    if not m:
        return "not drawn by this report (left in images/ by something else)."
    seed = shown.get("input", {}).get("meta", {}).get("seed")
    sheet = shown.get("sheet", {})
    size = ""
    if sheet.get("image_width_px") and sheet.get("px_per_m"):
        size = (f", {sheet['image_width_px']} × {sheet.get('image_height_px', '?')} px at "
                f"{fmt(sheet['px_per_m'] / 100)} px per cm")
    if m.group(1) == "crease":
        what, key = "crease map", ("red p > 0 and blue p < 0 creases, light-grey uncreased sheet, "
                                   "black outline")
    else:
        what, key = "facets", "one arbitrary colour per facet (areas: the maps figure, facets.csv)"
    return (f"{what} of seed {seed} at the end of cycle {int(m.group(2))} as crumple-analyze "
            f"draws it (flat reference configuration{size}): {key}.")


def images_index(img_dir, shown):
    """The report's last section: a table of every image file in images/, the plot scripts'
    figures first, each linked (relative) with a caption."""
    names = sorted(f for f in os.listdir(img_dir) if f.lower().endswith((".png", ".svg")))
    order = list(FIGURES)
    names.sort(key=lambda f: (order.index(os.path.splitext(f)[0])
                              if os.path.splitext(f)[0] in order else len(order), f))
    rows = ["## Images\n",
            f"Every image file in `{IMAGES}/` beside this report (links are relative: copy the "
            "folder with the report).\n",
            "| file | what it shows |", "|---|---|"]
    rows += [f"| [{f}]({IMAGES}/{f}) | {image_caption(f, shown)} |" for f in names]
    return "\n".join(rows) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ensemble", required=True)
    ap.add_argument("--runs", required=True, help="analysis folder of the seed whose maps are shown")
    ap.add_argument("--preset", default="?")
    ap.add_argument("--protocol", default="?")
    ap.add_argument("--format", choices=FIG_FORMATS, default=FIG_FORMATS[0],
                    help="the figures' format, as given to the plot scripts (default png)")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()

    e = load_ensemble(args.ensemble)
    out_dir = os.path.dirname(os.path.abspath(args.output))
    img_dir = os.path.join(out_dir, IMAGES)
    fig = check_figures(img_dir, args.format)
    shown = load_json(os.path.join(args.runs, "stats.json"), "stats.json of the shown seed")
    images = sorted(glob.glob(os.path.join(args.runs, "crease_*.png")) +
                    glob.glob(os.path.join(args.runs, "facets_*.png")))
    for p in images:
        shutil.copy(p, img_dir)

    D = e.get("compaction")
    par = e.get("parameters", {})
    cycles = e["cycles"]
    S = e["n_runs"]
    exp = experiment(D, [c["cycle"] for c in cycles]) or {}
    law = {c["cycle"]: c["law"] for c in exp.get("cycles", [])}
    fitsP = e["fits"].get("perimeter_P", {})
    fitsL = e["fits"].get("crease_length_L0", {})
    B = par.get("bootstrap_resamples")
    floor = 1.0 / (B + 1) if B else None
    st = e["stages"]
    ts = e["threshold_sensitivity"]

    L = []
    add = L.append
    add("# crumple: results\n")
    add(f"Preset `{args.preset}`, protocol `{args.protocol}`, {S} run(s) (seeds "
        f"{', '.join(str(s) for s in e.get('seeds', []))}), compaction D = {fmt(D)} (final / "
        f"initial piston gap). Crease threshold {rule_text(par)}. Generated by "
        "`pipeline/report/make_report.py` from `ensemble.json` (the ensemble statistics and fits "
        "of `crumple-analyze ensemble`); the experimental law and constants "
        "are in `data/` (sources in each file's `.md`; background in docs/STATISTICS.md).\n")
    add(f"Throughout, **s.e.m.** is the standard error of the ensemble mean over the {S} seeds "
        "(standard deviation / √seeds), and **s.e.** distances are |simulation − experiment| / "
        "s.e.m. of the simulation (for the fitted C and n0: their 1σ fit errors). A quantity "
        f"**agrees** when it is within {AGREE_SEM:g} s.e. "
        "The experimental law has no published uncertainty (docs/STATISTICS.md §2.1, §8), so the "
        "distances count the simulation's seed-to-seed spread only.\n")
    for n in e.get("notes", []):
        add(f"Note: {n}.\n")

    # ------------------------------------------------------------------ verdict
    V = []
    if law:
        zs = []
        for c in cycles:
            m, s, ref = c["perimeter_P_mean"], c["perimeter_P_sem"], law.get(c["cycle"])
            if m is None or ref is None:
                continue
            zs.append((c["cycle"], m, s, ref, word(m, s, ref), distance(m, s, ref)))
        if zs:
            n_dis = sum(1 for z in zs if z[4] == "disagree")
            parts = "; ".join(f"cycle {n}: {fmt(m)} vs {fmt(ref)} "
                              f"({'below' if m < ref else 'above'}, {judgement(m, s, ref, inline=True)})"
                              for n, m, s, ref, w, z in zs)
            if all(z[4] is None for z in zs):
                head = "cannot be judged in standard errors (fewer than 2 runs)"
            elif n_dis == 0:
                head = f"**agree** in all {len(zs)} cycles"
            else:
                head = f"**disagree** in {n_dis} of {len(zs)} cycles"
            alt = [word(m, s, ref / (1 - D)) for _, m, s, ref, _, _ in zs]
            alt_txt = ""
            if all(a is not None for a in alt):
                k = sum(1 for a in alt if a == "disagree")
                alt_txt = (f" Against that reading P disagrees in {k} of {len(alt)} cycles." if k
                           else " Against that reading P agrees in every cycle.")
            V.append(f"- **P per cycle against the experimental law** (primary comparison, absolute "
                     f"level, no scaling): {head}. {parts}. (Read without the (1 − D) factor of "
                     f"docs/STATISTICS.md §2.4 the law is {1 / (1 - D):.2f} × higher.{alt_txt})")
        lz = []
        for c in cycles:
            m, s, ref = c["crease_length_L0_mean"], c["crease_length_L0_sem"], law.get(c["cycle"])
            if m is not None and ref is not None:
                lz.append(f"cycle {c['cycle']}: {fmt(m)} vs {fmt(ref)} ({judgement(m, s, ref, inline=True)})")
        dang = [c["dangling_fraction_mean"] for c in cycles if c.get("dangling_fraction_mean") is not None]
        if lz:
            V.append("- ℓ/L0 (creased-edge length, beside P; the experiments measure P): "
                     + "; ".join(lz) + "." +
                     (f" Between {pct(min(dang))} and {pct(max(dang))} of ℓ dangles (ends inside a "
                      "facet and bounds no facet), so P < ℓ/L0." if dang else
                      " The dangling fraction is not in these stats.json files."))
    else:
        V.append("- P against the experimental law: not compared (compaction D unknown or not the "
                 "same in all runs).")
    fi = fitsP.get("increments") or {}
    if "C" in fi and exp:
        V.append(f"- **n0** (fit to the per-cycle increments of P): {pm(fi['n0'], fi['sigma_n0'])} "
                 f"against D/c2 = {fmt(exp['n0'])}: **{judgement(fi['n0'], fi['sigma_n0'], exp['n0'])}**"
                 + (f" (n0 is poorly constrained by these cycles: ±{100 * fi['sigma_n0'] / fi['n0']:.0f} %)"
                    if fi.get("sigma_n0") and fi["n0"] > 0 and fi["sigma_n0"] > 0.3 * fi["n0"] else "")
                 + ".")
        V.append(f"- **C** (same fit): {pm(fi['C'], fi['sigma_C'])} L0 against c1 (1 − D) = "
                 f"{fmt(exp['C'])} L0: **{judgement(fi['C'], fi['sigma_C'], exp['C'])}** "
                 f"(χ²/dof of the fit {fmt(fi['chi2'], '.3g')}/{fi['dof']}).")
    else:
        why = fi.get("error") or "no compaction known"
        V.append(f"- **n0** and **C**: not available ({why}).")
    az = []
    for c in cycles:
        d, s = c.get("a_fit_minus_a_univ_mean"), c.get("a_fit_minus_a_univ_sem")
        if d is not None:
            az.append(f"cycle {c['cycle']}: {fmt(c['a_fit_mean'])} vs {fmt(c['a_univ_mean'])} "
                      f"({judgement(d, s, 0.0, inline=True)})")
    V.append("- **a_fit against a_univ** (shape fitted to the facets against the shape the "
             "universal curve of docs/STATISTICS.md §3.4 gives for the same mean facet area; "
             "s.e. of the per-seed difference): " + ("; ".join(az) if az else "not available") + ".")
    kz = []
    for c in cycles:
        if c.get("ks_n_tested"):
            t = f"cycle {c['cycle']}: rejected in {c['ks_n_rejected']} of {c['ks_n_tested']} runs"
            if c.get("ks_n_at_floor"):
                t += f" ({c['ks_n_at_floor']} with p at the bootstrap floor)"
            kz.append(t)
    if kz:
        tot_r = sum(c.get("ks_n_rejected", 0) for c in cycles)
        tot = sum(c.get("ks_n_tested", 0) for c in cycles)
        if tot_r == 0:
            head = f"**agree**: φ(ξ; a_fit) is not rejected at 5 % in any of the {tot} tests"
        elif 2 * tot_r >= tot:
            head = f"**disagree**: φ(ξ; a_fit) is rejected at 5 % in {tot_r} of {tot} tests"
        else:
            head = (f"**mixed**: φ(ξ; a_fit) is rejected at 5 % in {tot_r} of {tot} tests "
                    f"(about {0.05 * tot:.1g} expected by chance if φ were right)")
        fl = ""
        if any(c.get("ks_n_at_floor") for c in cycles):
            fl = (f" A p at the bootstrap floor 1/(B+1) = {fmt(floor, '.2g')} (B = {B}) means no "
                  "resample was as far from φ as the data; the bootstrap cannot resolve smaller p, so "
                  f"it says p < {fmt(floor, '.2g')}: a clear rejection.")
        V.append(f"- **Facet-area distribution** (KS test of each run's ξ against φ(ξ; a_fit), "
                 f"parametric-bootstrap p, docs/STATISTICS.md §3.7): {head}. " + "; ".join(kz) + "." + fl)
    else:
        V.append("- **Facet-area distribution**: no KS tests (too few facets).")
    fl_t = sum(c.get("ks_above_floor_n_tested", 0) for c in cycles)
    if fl_t:
        fl_r = sum(c.get("ks_above_floor_n_rejected", 0) for c in cycles)
        fl_s = sum(c.get("a_fit_above_floor_n", 0) for c in cycles)
        edges = {k: sum((c.get("fit_above_floor_edges") or {}).get(k, 0) for c in cycles)
                 for k in ("a_min", "a_max", "theta")}
        V.append(f"- **Facets above the resolution floor** (the law cut at the floor, scale free; "
                 f"section Facet areas): a shape measured in {fl_s} of {fl_t} run-cycles; fits on an "
                 f"edge of the search: {edges['a_min']} at a_min (steeper than any member of the "
                 f"family), {edges['a_max']} at a_max, {edges['theta']} on the scale's range; the "
                 f"cut φ rejected at 5 % in {fl_r} of {fl_t}.")
    if st.get("available"):
        sh = [(c["cycle"], c["share_after_compress_mean"], c["share_after_compress_sem"],
               c.get("share_after_compress_max")) for c in st["cycles"]
              if c.get("share_after_compress_mean") is not None]
        if sh:
            over = [x for x in sh if x[1] > SHARE_TARGET]
            seeds_over = [x for x in sh if x[3] is not None and x[3] > SHARE_TARGET]
            def rel(m, s):
                if not s:
                    return ""
                z = (m - SHARE_TARGET) / s
                return f" ({abs(z):.1f} s.e. {'above' if z > 0 else 'below'} the target)"
            txt = "; ".join(f"cycle {n}: {pct_pm(m, s)}{rel(m, s)}" for n, m, s, _ in sh)
            verdict = ("meets the issue's target of at most 15 % in every cycle (ensemble mean)"
                       if not over else f"misses the issue's target of at most 15 % in {len(over)} of "
                       f"{len(sh)} cycles (ensemble mean)")
            if seeds_over and not over:
                verdict += f"; single seeds exceed it in {len(seeds_over)} cycle(s)"
            V.append(f"- **Share of each cycle's new crease length made after compression ended**: "
                     f"{verdict}. {txt}.")
        else:
            V.append("- **Share made after compression**: not defined (no compress stage or no new creases).")
    else:
        V.append(f"- **Share made after compression**: not available ({st.get('note', 'no per-stage data')}); "
                 "the issue's 15 % target cannot be checked.")
    warn = [c for c in cycles if (c.get("single_triangle_fraction_mean") or 0) > SINGLE_TRIANGLE_WARN]
    if warn:
        V.append(f"- **Resolution**: in {len(warn)} of {len(cycles)} cycles more than 20 % of the facets "
                 "are single mesh triangles, so the facet statistics of those cycles are limited by "
                 "the mesh, not by the physics (see Facet areas).")
    elif not any(c.get("single_triangle_fraction_mean") is not None for c in cycles):
        V.append("- **Resolution**: the single-triangle facet fraction is not in these stats.json "
                 "files (older crumple-analyze); the resolution limit of the facet statistics is unchecked.")
    add("## Verdict\n")
    add("\n".join(V) + "\n")

    # ------------------------------------------------------------------ crease definition
    add("## Crease definition and threshold\n")
    add(f"A hinge is a crease when its plastic rest curvature p (curvature units 2 sin(θ/2) of "
        f"the model) exceeds the threshold: {rule_text(par)}. "
        + (f"The analysis says: “{par.get('threshold_note')}”. " if par.get("threshold_note") else "")
        + "ℓ is the summed rest length of the creased hinges' edges; P is measured as the "
        "experiments measure it, from the perimeters of the facets the crease map separates "
        "(docs/STATISTICS.md §2.1, §5). Crease segments that end inside a facet count in ℓ but "
        "not in P; the dangling fraction 1 − P/(ℓ/L0) measures that part.\n")
    warns = sorted({w for r in e["runs"] for w in (r.get("warnings") or [])})
    if warns:
        add("Warnings of crumple-analyze: " + "; ".join(f"“{w}”" for w in warns) + ".\n")

    add("## Crease-threshold sensitivity\n")
    if ts.get("available") and ts.get("cycles"):
        fac = ts.get("factors_of_c0") or []
        thr = ts.get("thresholds_mean") or []
        used = ts.get("used_factor")
        heads = []
        for f, t in zip(fac, thr):
            h = (f"{fmt(f)} c0 = {fmt(t)}" if f is not None else f"{fmt(t)}")
            t_used = par.get("threshold")
            if ((f is not None and used is not None and abs(f - used) < 1e-9) or
                    (used is None and t is not None and t_used is not None and
                     abs(t - t_used) <= 1e-9 * max(1.0, abs(t_used)))):
                h += " (used)"
            heads.append(h)
        add(f"Ensemble means over {ts['n_runs']} run(s) of ℓ/L0 and P at the end of each cycle "
            "when the same plastic field is segmented again at each threshold |p| > threshold "
            "(columns; c0 is the yield curvature).\n")
        add("| cycle | quantity | " + " | ".join(heads) + " |")
        add("|---|---|" + "---|" * len(heads))
        for c in ts["cycles"]:
            for key, name in (("crease_length_L0", "ℓ/L0"), ("perimeter_P", "P"), ("n_facets", "facets")):
                add(f"| {c['cycle']} | {name} | " +
                    " | ".join(pm(m, s) for m, s in zip(c[key + "_mean"], c[key + "_sem"])) + " |")
        add("")
        last = ts["cycles"][-1]
        for key, name in (("crease_length_L0", "ℓ/L0"), ("perimeter_P", "P")):
            v = [x for x in last[key + "_mean"] if x is not None]
            if v and min(v) > 0:
                add(f"At cycle {last['cycle']}, {name} ranges from {fmt(min(v))} to {fmt(max(v))} "
                    f"over these thresholds (factor {max(v) / min(v):.3g}).")
        add("\nThe absolute crease length depends strongly on the threshold; compare the shape "
            "(n0) before the absolute level (docs/STATISTICS.md §2.3, §5).\n")
    else:
        add(f"Not available: {ts.get('note', 'no threshold-sensitivity data')}.\n")

    # ------------------------------------------------------------------ crease length
    add("## Crease length against the experimental law\n")
    add(f"![crease length against cycle number]({fig['crease_length']})\n")
    add("*What is measured and how.* (a) P, the facet-perimeter crease length of the experiments "
        "(Σ facet perimeters − sheet outline)/(2 L0) (docs/STATISTICS.md §2.1), at the end of "
        "each cycle after the sheet is flattened: each seed (grey), the ensemble mean ± s.e.m., "
        "the law C ln(1 + n/n0) fitted to the per-cycle increments (primary fit), the same law "
        "fitted to the cumulative values (correlated between cycles, for comparison only), and "
        f"the experimental law c1 (1 − D) ln(1 + c2 n/D) with c1 = {fmt(exp.get('c1'))}, "
        f"c2 = {fmt(exp.get('c2'))} at D = {fmt(D)}, drawn at its absolute level without any "
        "scaling; the faint line is the law read without the (1 − D) factor (docs/STATISTICS.md "
        "§2.4). (b) The same for ℓ/L0, the creased-edge length. (c) The per-cycle increments with "
        "their s.e.m., the data of the primary fits. (d) The dangling fraction 1 − P/(ℓ/L0).\n")
    add("| cycle | P (mean ± s.e.m.) | law | P: s.e. from law | law without (1 − D) | "
        "ℓ/L0 (mean ± s.e.m.) | ℓ: s.e. from law | dangling fraction |")
    add("|---|---|---|---|---|---|---|---|")
    for c in cycles:
        n = c["cycle"]
        ref = law.get(n)
        ref2 = ref / (1 - D) if ref is not None else None
        zP = distance(c["perimeter_P_mean"], c["perimeter_P_sem"], ref)
        zL = distance(c["crease_length_L0_mean"], c["crease_length_L0_sem"], ref)
        add(f"| {n} | {pm(c['perimeter_P_mean'], c['perimeter_P_sem'])} | {fmt(ref)} | "
            f"{fmt(zP, '.1f')} | {fmt(ref2)} | "
            f"{pm(c['crease_length_L0_mean'], c['crease_length_L0_sem'])} | {fmt(zL, '.1f')} | "
            f"{pm(c.get('dangling_fraction_mean'), c.get('dangling_fraction_sem'), '.2f')} |")
    add("")
    if not any(c.get("dangling_fraction_mean") is not None for c in cycles):
        add("The dangling fraction is not in these stats.json files (older crumple-analyze).\n")

    add("### Log-law fits\n")
    add("Fits of y = C ln(1 + n/n0) (docs/STATISTICS.md §2.2–2.3). **Increments** (primary): "
        "the increments Δy_n = y_n − y_{n−1} of the ensemble mean, Δy_n = C [ln(1 + n/n0) − "
        "ln(1 + (n−1)/n0)], weighted by the seed-to-seed s.e.m. of each increment; increments of "
        "different cycles are close to independent, so χ²/dof and the 1σ errors mean what they "
        "say. **Cumulative** (correlated): the cumulative means weighted by their s.e.m.; each "
        "value shares all earlier increments, so its χ²/dof is too small and its errors too "
        "optimistic. c1 = C/(1 − D), c2 = D/n0"
        + (f" (not given here: {e['compaction_note']})" if e.get("compaction_note") else "")
        + ". Fitted by `crumple-analyze ensemble` (weighted least squares, n0 within 10⁻⁶ to 10⁶ "
        "cycles; analysis/README.md).\n")
    add("| quantity | fit | C (L0) | n0 (cycles) | χ²/dof | c1 | c2 | weights |")
    add("|---|---|---|---|---|---|---|---|")
    for q, fits in (("P", fitsP), ("ℓ/L0", fitsL)):
        for kind, label in (("increments", "increments (primary)"), ("cumulative", "cumulative (correlated)")):
            f = fits.get(kind) or {}
            if "C" in f:
                add(f"| {q} | {label} | {pm(f['C'], f['sigma_C'])} | {pm(f['n0'], f['sigma_n0'])} | "
                    f"{fmt(f['chi2'], '.3g')}/{f['dof']} | {pm(f.get('c1'), f.get('sigma_c1'))} | "
                    f"{pm(f.get('c2'), f.get('sigma_c2'))} | "
                    f"{'s.e.m.' if f.get('weighted') else 'unweighted, residual-scaled'} |")
            else:
                add(f"| {q} | {label} | – | – | – | – | – | {f.get('error', 'not available')} |")
    if exp:
        add(f"| experiment | law | {fmt(exp['C'])} | {fmt(exp['n0'])} | – | {fmt(exp['c1'])} | "
            f"{fmt(exp['c2'])} | no published uncertainty |")
    add("")
    per_seed = []
    for r in e["runs"]:
        f = (r.get("log_fit") or {}).get("perimeter_P_increments")
        if f and f.get("n0") is not None:
            sn0 = f.get("sigma_n0")
            if sn0 is None or sn0 > f["n0"] or f["n0"] > 1e3:
                per_seed.append(f"seed {r['seed']}: n0 not constrained (n0 = {pm(f['n0'], sn0)}; "
                                "the increments do not clearly decrease)")
            else:
                per_seed.append(f"seed {r['seed']}: C = {pm(f.get('C'), f.get('sigma_C'))}, "
                                f"n0 = {pm(f.get('n0'), sn0)}")
    if per_seed:
        add("Per-seed increment fits of P by crumple-analyze (unweighted, one run each): "
            + "; ".join(per_seed) + ".\n")

    # ------------------------------------------------------------------ stages
    add("## Where the creases were made\n")
    add(f"![new crease length by stage]({fig['stages']})\n")
    add("*What is measured and how.* The run file stores the plastic field at the end of every "
        "stage, and the creases (at the threshold above) are found at each stage end. A cycle's new "
        "creases are the hinges creased at its end and not at the previous cycle's end; each is "
        "attributed to the stage from whose end on it stays creased to the end of the cycle, so "
        "the stages' new lengths add up to the cycle's new length (a hinge flattened by one stage "
        "and creased again later counts once, at the later stage). Crease length that falls back "
        "below the threshold at a stage end is counted as lost. Left: stacked bars of the "
        "ensemble mean of each stage's new length (ℓ/L0) per cycle, with the s.e.m. of each stage "
        "at the top of its segment (hatched bars below zero: lost length). Right: the share of "
        "each cycle's new crease length made after the last compress stage of the cycle ended, per "
        "seed and mean ± s.e.m., against the ""15 % target.\n")
    if st.get("available"):
        if st.get("note"):
            add(f"Note: {st['note']}.\n")
        keys = sorted({(s["index"], s["stage"]) for c in st["cycles"] for s in c["stages"]})
        has_lost = any(r.get("lost_crease_length_L0_mean") is not None
                       for c in st["cycles"] for r in c["stages"])
        add("| cycle | " + " | ".join(f"{name} (new ℓ/L0)" for _, name in keys) +
            " | cycle total (new ℓ/L0) |" + (" lost in the cycle (ℓ/L0) |" if has_lost else "") +
            " share after compress | largest seed share |")
        add("|---|" + "---|" * (len(keys) + 3 + has_lost))
        for c in st["cycles"]:
            cells = []
            for k in keys:
                row = next((r for r in c["stages"] if (r["index"], r["stage"]) == k), None)
                cells.append(pm(row["new_crease_length_L0_mean"], row["new_crease_length_L0_sem"]) if row else "–")
            sh, ss = c.get("share_after_compress_mean"), c.get("share_after_compress_sem")
            share = pct_pm(sh, ss)
            lost = ""
            if has_lost:
                v = [r.get("lost_crease_length_L0_mean") for r in c["stages"]]
                lost = f" {fmt(sum(x for x in v if x is not None))} |"
            add(f"| {c['cycle']} | " + " | ".join(cells) +
                f" | {pm(c.get('new_crease_length_L0_mean'), c.get('new_crease_length_L0_sem'))} |"
                f"{lost} {share} | {pct(c.get('share_after_compress_max'))} |")
        add("")
    else:
        add(f"Not available: {st.get('note', 'no per-stage data')}.\n")

    # ------------------------------------------------------------------ facets
    add("## Facet areas\n")
    add(f"![facet-area distributions]({fig['facets']})\n")
    add("*What is measured and how.* The crease map of each cycle is segmented into facets "
        "(connected sheet regions the creases separate, grown over the crease pixels so they tile "
        "the sheet; docs/STATISTICS.md §5); x is a facet's area as a fraction of the sheet in the "
        "flat reference configuration and ξ = x/⟨x⟩. The log-binned density of ξ (bin ratio 1.55) "
        "is pooled over the seeds, with Poisson error bars, against φ(ξ; a_fit) (maximum "
        "likelihood) and φ(ξ; a_univ) (the universal curve for the same mean area) "
        "(docs/STATISTICS.md §3.3, §3.4, §3.7). The grey band lies below the mean area of one mesh "
        "triangle, about the smallest facet the mesh can make. The KS test compares each run's ξ with φ(ξ; a_fit); a "
        f"is refitted on every resample of the parametric bootstrap (B = {fmt(B)}), so the "
        f"smallest p it can give is 1/(B+1) = {fmt(floor, '.2g')}.\n")
    add("| cycle | facets (mean) | single-triangle facets | a_fit (mean ± s.e.m.) | "
        "a_univ (mean ± s.e.m.) | a_fit − a_univ: s.e. | KS distance | KS p per run | KS at 5 % |")
    add("|---|---|---|---|---|---|---|---|---|")
    for c in cycles:
        ps = []
        for k in c.get("ks_tests", []):
            if k["p"] is None:
                continue
            ps.append(f"< {fmt(k['floor'], '.2g')} (floor)" if k["at_floor"] else fmt(k["p"], ".2g"))
        ks = (f"rejected in {c['ks_n_rejected']}/{c['ks_n_tested']}" if c.get("ks_n_tested") else "–")
        if c.get("ks_n_tested") and c["ks_n_rejected"] == 0:
            ks = f"not rejected ({c['ks_n_tested']}/{c['ks_n_tested']})"
        stf = c.get("single_triangle_fraction_mean")
        add(f"| {c['cycle']} | {fmt(c['n_facets_mean'], '.4g')} | "
            f"{pct(stf)}{' ⚠' if (stf or 0) > SINGLE_TRIANGLE_WARN else ''} | "
            f"{pm(c['a_fit_mean'], c['a_fit_sem'])} | {pm(c['a_univ_mean'], c['a_univ_sem'])} | "
            f"{fmt(distance(c.get('a_fit_minus_a_univ_mean'), c.get('a_fit_minus_a_univ_sem'), 0.0), '.1f')} | "
            f"{fmt(c['ks_distance_mean'])} | {', '.join(ps) or '–'} | {ks} |")
    add("")
    for c in warn:
        add(f"**Resolution warning, cycle {c['cycle']}:** {pct(c['single_triangle_fraction_mean'])} of "
            "the facets are single mesh triangles (area below 1.5 × the mean triangle area), above "
            "the 20 % limit: the small-facet end of the distribution, and with it a_fit and the KS "
            "test, is set by the mesh resolution rather than by the crumpling.\n")
    fl_rows = [c for c in cycles if c.get("ks_above_floor_n_tested")]
    if fl_rows:
        ff = shown.get("parameters", {}).get("facet_floor_triangles")
        add(f"*Above the resolution floor.* The same law cut at the floor (facets of at least "
            f"{fmt(ff)} mean mesh triangles) and fitted to the facets above it with its scale free "
            "(docs/STATISTICS.md §3.7, analysis/fits/truncated_shape.hpp); a_univ is the universal "
            "curve at the fitted law's mean area. A fit that stops on an edge of its search measures "
            "no shape (counted per edge: *a_min*, the facets above the floor fall off more steeply "
            "than any member of the family allows; *a_max*, narrower than a = 50; *θ*, the scale's "
            "range); the KS test is then of the edge's law, and approximate.\n")
        add("| cycle | facets above the floor (mean) | runs with a shape | a_fit | a_univ | "
            "fits on an edge | KS at 5 % |")
        add("|---|---|---|---|---|---|---|")
        for c in fl_rows:
            a = (pm(c["a_fit_above_floor_mean"], c["a_fit_above_floor_sem"])
                 if c.get("a_fit_above_floor_mean") is not None else "–")
            au = (pm(c["a_univ_above_floor_mean"], c["a_univ_above_floor_sem"])
                  if c.get("a_univ_above_floor_mean") is not None else "–")
            add(f"| {c['cycle']} | {fmt(c.get('n_facets_above_floor_mean'), '.4g')} | "
                f"{c.get('a_fit_above_floor_n', 0)}/{c['ks_above_floor_n_tested']} | {a} | {au} | "
                f"{edge_counts(c)} | "
                f"rejected in {c['ks_above_floor_n_rejected']}/{c['ks_above_floor_n_tested']} |")
        add("")
    if not any(c.get("single_triangle_fraction_mean") is not None for c in cycles):
        add("The single-triangle facet fraction is not in these stats.json files (older "
            "crumple-analyze), so no resolution warning could be computed.\n")
    res = shown.get("resolution", {})
    add(f"Smallest resolvable facet: {fmt(res.get('smallest_resolvable_x'))} of the sheet (mesh "
        f"floor {fmt(res.get('mean_triangle_area_m2'))} m², pixel floor "
        f"{fmt(res.get('pixel_floor_m2'))} m²); the experiments resolve about 10⁻⁷ of the sheet "
        "(docs/STATISTICS.md §3.7).\n")

    # ------------------------------------------------------------------ maps
    add("## Crease maps and facets of one seed\n")
    add(f"![crease maps and facets]({fig['maps']})\n")
    add(f"*What is shown.* From `{args.runs}` (seed {shown.get('input', {}).get('meta', {}).get('seed')}), "
        "at the end of each cycle, in the flat reference configuration, each map with a scale bar "
        "(the sheet's side is L0 = "
        f"{fmt(100 * shown.get('sheet', {}).get('L0_m', 0.1))} cm). Top: the crease map, creased "
        "hinges drawn along their mesh edges, red for p > 0 and blue for p < 0 (plastic rest "
        "curvature of opposite sense), on the light-grey sheet with its outline in black. Bottom: "
        "the facets segmented from it, each filled by its area in mm² on a logarithmic colour "
        "scale (the colour bar; its mark is the mean area of one mesh triangle), with the facet "
        "boundaries in dark grey. The full-resolution crease and facet images of every cycle are "
        "listed under Images.\n")

    add("## References\n")
    add("- docs/STATISTICS.md §1 (experimental protocol), §2.1–2.4 (crease-length law, P, fitting "
        "recipe, the (1 − D) ambiguity), §3.3–3.7 (facet-area statistics and comparison recipe), "
        "§5 (crease and facet definitions in the simulation).\n"
        "- O. Gottesman et al., Commun. Phys. 1, 70 (2018) (crease-length law); J. Andrejevic et al., "
        "Nat. Commun. 12, 1470 (2021) (fragmentation model, facet statistics); J. Andrejevic and "
        "C. H. Rycroft, J. Comput. Phys. (2022) (the simulation model, docs/MODEL.md).\n")

    add(images_index(img_dir, shown))
    with open(args.output, "w") as f:
        f.write("\n".join(L))
    print(f"make_report.py: wrote {args.output}")


if __name__ == "__main__":
    main()
