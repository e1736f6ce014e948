#!/usr/bin/python3
"""Two ensembles of the same seeds compared run by run (issue 36: the causes of the slow crease
growth, docs/SCIENCE.md): a protocol change (the variant) against the protocol as it stands (the
baseline), both `crumple-analyze ensemble` files, at the same compaction and cycles.

A change moves both the level of P and the shape of its growth. The level is calibrated away
(the yield is fitted so that P after cycle 1 equals the law), so the question for the growth is
the shape. Per cycle n this writes:
  - P of each group (mean ± s.e.m. over seeds) and the law's value;
  - the variant over the baseline, mean(P_var) / mean(P_base) over the seeds both have, its
    error by the delta method with the seeds' covariance (the same seed shares its mesh, its
    roll axes and much of its history, so the pairs are correlated);
  - each group's shape, P(n)/P(1) over the law's L(n)/L(1) (a ratio of correlated means), and
    the change of shape seed by seed: the mean ± s.e.m. of (shape_var - shape_base) per seed.
A difference is called resolved where it exceeds twice its s.e.m.; with three seeds that band
covers about 82 % (Student's t, 2 degrees of freedom), not 95 %. The increments fit of each
group (n0, c1, c2 of crumple-analyze ensemble) is listed beside it.

Writes OUT.md and OUT.json. Exit 0; 2 bad input (different compactions, no shared seeds).

usage: compare_groups.py --baseline A/ensemble.json --variant B/ensemble.json
                         [--baseline-label TEXT] [--variant-label TEXT] -o OUT
"""
import argparse
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, experiment, load_ensemble, mean_sem, per_seed, ratio_of_means  # noqa: E402

RESOLVED_SEM = 2.0


def resolved(d, s):
    return None if d is None or s is None else abs(d) > RESOLVED_SEM * s


def compare(base, var):
    if base.get("compaction") != var.get("compaction"):
        die(f"the groups were crumpled to different compactions ({base.get('compaction')} and "
            f"{var.get('compaction')}): not a comparison of one change")
    pb, pv = per_seed(base, "perimeter_P"), per_seed(var, "perimeter_P")
    seeds = sorted(set(pb) & set(pv))
    if not seeds:
        die("the two ensembles share no seed: a paired comparison needs the same seeds")
    cycles = sorted(set.intersection(*(set(pb[s]) & set(pv[s]) for s in seeds)))
    if 1 not in cycles:
        die("the two ensembles have no cycle 1 in common: the shape P(n)/P(1) needs it")
    law = experiment(base.get("compaction"), cycles)
    L = {c["cycle"]: c["law"] for c in law["cycles"]} if law else {}
    rows = []
    for n in cycles:
        xb, xv = [pb[s][n] for s in seeds], [pv[s][n] for s in seeds]
        mb, sb = mean_sem(xb)
        mv, sv = mean_sem(xv)
        ratio, ratio_sem = ratio_of_means(xb, xv) if mb > 0 else (None, None)
        row = {"cycle": n, "law": L.get(n), "baseline": mb, "baseline_sem": sb, "variant": mv,
               "variant_sem": sv, "ratio": ratio, "ratio_sem": ratio_sem,
               "ratio_resolved": resolved(None if ratio is None else ratio - 1, ratio_sem)}
        if n != 1 and L:
            lr = L[n] / L[1]
            for name, p in (("baseline", pb), ("variant", pv)):
                p1 = [p[s][1] for s in seeds]
                if statistics.fmean(p1) > 0:
                    r, e = ratio_of_means(p1, [p[s][n] for s in seeds])
                    row[f"{name}_shape"] = r / lr
                    row[f"{name}_shape_sem"] = e / lr if e is not None else None
            both = [s for s in seeds if pb[s][1] > 0 and pv[s][1] > 0]
            d = [(pv[s][n] / pv[s][1] - pb[s][n] / pb[s][1]) / lr for s in both]
            row["shape_change"], row["shape_change_sem"] = mean_sem(d)
            row["shape_change_per_seed"] = d
            row["shape_change_resolved"] = resolved(row["shape_change"], row["shape_change_sem"])
        rows.append(row)
    return seeds, law, rows


def fit_of(ens):
    f = ((ens.get("fits") or {}).get("perimeter_P") or {}).get("increments") or {}
    return {k: f.get(k) for k in ("n0", "sigma_n0", "c1", "sigma_c1", "c2", "sigma_c2",
                                  "at_bound")}


def pm(v, s, fmt=".2f"):
    if v is None:
        return "–"
    return f"{v:{fmt}}" + (f" ± {s:{fmt}}" if s is not None else "")


def report(doc):
    b, v = doc["baseline_label"], doc["variant_label"]
    L = [f"# {v} against {b}", "",
         f"Compaction {doc['compaction']}, seeds {', '.join(str(s) for s in doc['seeds'])} in both "
         f"groups, each seed paired with itself (pipeline/sweeps/compare_groups.py). P in L0, mean ± "
         f"s.e.m. over the seeds; the law is c1 (1 - D) ln(1 + c2 n/D) with the experiments' "
         f"constants. *Ratio* is mean P of the variant over the baseline's (delta method, with the "
         f"seeds' covariance). *Shape* is P(n)/P(1) over the law's L(n)/L(1): 1 is the law's shape "
         f"of growth, whatever the level. *Change of shape* is the per-seed difference of shapes, "
         f"variant minus baseline. A figure is marked * where it is more than "
         f"{RESOLVED_SEM:g} s.e.m. from no change; with {len(doc['seeds'])} seeds that band is "
         f"narrow (about 82 % coverage at 3 seeds).", "",
         f"| cycle | law | {b} | {v} | ratio | shape, {b} | shape, {v} | change of shape | per seed |",
         "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in doc["rows"]:
        star = lambda flag: " *" if flag else ""  # noqa: E731
        per = ", ".join(f"{x:+.2f}" for x in r.get("shape_change_per_seed", [])) or "–"
        L.append(f"| {r['cycle']} | {pm(r['law'], None, '.1f')} | {pm(r['baseline'], r['baseline_sem'])} | "
                 f"{pm(r['variant'], r['variant_sem'])} | "
                 f"{pm(r['ratio'], r['ratio_sem'])}{star(r['ratio_resolved'])} | "
                 f"{pm(r.get('baseline_shape'), r.get('baseline_shape_sem'))} | "
                 f"{pm(r.get('variant_shape'), r.get('variant_shape_sem'))} | "
                 f"{pm(r.get('shape_change'), r.get('shape_change_sem'))}{star(r.get('shape_change_resolved'))} | "
                 f"{per} |")
    L += ["", f"Made from `{doc['baseline']}` (baseline) and `{doc['variant']}` (variant)."]
    L += ["", "The law fitted to each group's increments of P (crumple-analyze ensemble), against "
          f"the experiments' n0 = {doc['law_n0']:.2f}, c1 = 52 and c2 = 0.1:" if doc["law_n0"] else "", "",
          "| group | n0 | c1 | c2 |", "| --- | --- | --- | --- |"]
    for label, f in ((b, doc["baseline_fit"]), (v, doc["variant_fit"])):
        if f.get("at_bound"):
            # n0 on the edge of its search: the increments fall faster than any n0 in range
            # describes (or slower), and c1, c2 computed from it mean nothing.
            L.append(f"| {label} | {f['n0']:.3g} (on its search bound: not determined) | – | – |")
            continue
        L.append(f"| {label} | {pm(f['n0'], f['sigma_n0'])} | {pm(f['c1'], f['sigma_c1'], '.1f')} | "
                 f"{pm(f['c2'], f['sigma_c2'], '.3f')} |")
    L.append("")
    return "\n".join(L)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--baseline", required=True, help="the protocol as it stands: ensemble.json")
    ap.add_argument("--variant", required=True, help="the changed protocol: ensemble.json")
    ap.add_argument("--baseline-label", default="baseline")
    ap.add_argument("--variant-label", default="variant")
    ap.add_argument("-o", "--output", required=True, help="OUT: writes OUT.md and OUT.json")
    a = ap.parse_args()
    base, var = load_ensemble(a.baseline), load_ensemble(a.variant)
    seeds, law, rows = compare(base, var)
    doc = {"baseline": a.baseline, "variant": a.variant, "baseline_label": a.baseline_label,
           "variant_label": a.variant_label, "compaction": base.get("compaction"), "seeds": seeds,
           "law_n0": law["n0"] if law else None, "rows": rows,
           "baseline_fit": fit_of(base), "variant_fit": fit_of(var)}
    os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
    for ext, text in ((".json", json.dumps(doc, indent=1)), (".md", report(doc))):
        with open(a.output + ext + ".new", "w") as f:
            f.write(text)
        os.replace(a.output + ext + ".new", a.output + ext)
    print(f"compare_groups.py: {len(seeds)} seeds, {len(rows)} cycles -> {a.output}.md, "
          f"{a.output}.json")


if __name__ == "__main__":
    main()
