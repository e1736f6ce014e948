#!/usr/bin/python3
"""The figures of a sweep report (pipeline/sweep.mk), drawn from the group ensembles
(RESULTS/groups/GROUP/ensemble.json) and, when the sweep varies the compaction, the collapse
document (RESULTS/collapse.json) of `crumple-analyze collapse`; nothing is fitted here.

  crease_length.png  P per cycle (mean ± s.e.m. over seeds) of every group, and, where the
                     group has one compaction D, the experimental law c1 (1 - D) ln(1 + c2 n/D)
                     in the same colour, dashed (docs/STATISTICS.md §2)
  collapse.png       (collapse only) P/(1 - D) against n/D for every D on one axis, with the
                     experimental law c1 ln(1 + c2 x) and the global fit to the simulation

  convergence.png    (convergence ladder only) P per cycle against the mesh length h with its
                     Richardson estimate at h = 0, and each rung's relative error against it
                     with the presets' 15 % and 5 % bands (pipeline/sweeps/convergence.py)

usage: plot_sweep.py --points runs/sweeps/NAME/points.json --results results/NAME
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, law_constants, load_ensemble, load_json, sweep_groups  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

KEY = "perimeter_P"



def crease_length(points, results, out):
    c1, c2 = law_constants()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, g in enumerate(sweep_groups(points)):
        e = load_ensemble(os.path.join(results, "groups", g, "ensemble.json"))
        n = np.array([r["cycle"] for r in e["cycles"]], float)
        m = np.array([np.nan if r.get(KEY + "_mean") is None else r[KEY + "_mean"]
                      for r in e["cycles"]], float)
        s = np.array([0 if r.get(KEY + "_sem") is None else r[KEY + "_sem"]
                      for r in e["cycles"]], float)
        colour = f"C{i % 10}"
        ax.errorbar(n, m, yerr=s, fmt="o-", color=colour, capsize=3, ms=4, label=g)
        D = e.get("compaction")
        if D is not None and 0 < D < 1:
            nn = np.linspace(0, max(n.max(), 1), 100)
            ax.plot(nn, c1 * (1 - D) * np.log1p(c2 * nn / D), "--", color=colour, lw=1)
    ax.set_xlabel("cycle n")
    ax.set_ylabel("crease length P (units of L0)")
    ax.set_title(f"sweep {points['name']}: simulation (points, mean ± s.e.m.) and "
                 f"experimental law (dashed)", fontsize=9)
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def collapse(results, out):
    doc = load_json(os.path.join(results, "collapse.json"), "collapse document")
    if "points" not in doc or KEY not in doc["points"]:
        die(f"{results}/collapse.json is not a collapse document of `crumple-analyze collapse`")
    c1, c2 = law_constants()
    pts = doc["points"][KEY]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ratios = sorted({p["compaction"] for p in pts}, reverse=True)
    xmax = max(p["x"] for p in pts)
    for i, D in enumerate(ratios):
        mine = [p for p in pts if p["compaction"] == D]
        ax.errorbar([p["x"] for p in mine], [p["y"] for p in mine],
                    yerr=[p["y_sem"] or 0 for p in mine], fmt="o", ms=4, capsize=2,
                    color=f"C{i % 10}", label=f"D = {D:g}")
    xx = np.logspace(np.log10(min(p["x"] for p in pts)) - 0.2, np.log10(xmax) + 0.1, 200)
    ax.plot(xx, c1 * np.log1p(c2 * xx), "k--", lw=1.2,
            label=f"experiment: {c1:g} ln(1 + {c2:g} x)")
    f = doc["fits"][KEY]["increments"]
    if "c1" in f and f["c1"] is not None:
        s = lambda v: "?" if v is None else f"{v:.2g}"  # noqa: E731
        ax.plot(xx, f["c1"] * np.log1p(f["c2"] * xx), "-", color="0.3", lw=1.2,
                label=f"global fit: c1={f['c1']:.3g}±{s(f['sigma_c1'])}, "
                      f"c2={f['c2']:.3g}±{s(f['sigma_c2'])}")
    ax.set_xscale("log")
    ax.set_xlabel("n / D")
    ax.set_ylabel("P / (1 - D)  (units of L0)")
    ax.set_title("the collapse: every compaction on one curve?", fontsize=9)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def convergence(results, out):
    doc = load_json(os.path.join(results, "convergence.json"), "convergence document")
    rows = [r for r in doc.get("rows", []) if r["quantity"] == KEY]
    if not rows:
        die(f"{results}/convergence.json has no {KEY} rows (make it with convergence.py)")
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.2))
    for i, r in enumerate(rows):
        colour = f"C{i % 10}"
        h = np.array([g["h_m"] * 1e3 for g in r["rungs"]])
        m = np.array([np.nan if g["mean"] is None else g["mean"] for g in r["rungs"]])
        s = np.array([g["sem"] or 0 for g in r["rungs"]])
        ax.errorbar(h, m, yerr=s, fmt="o-", ms=4, capsize=3, color=colour,
                    label=f"cycle {r['cycle']}")
        if r.get("estimate") is not None:
            ax.errorbar([0], [r["estimate"]], yerr=[r["estimate_sem"] or 0], fmt="s", mfc="none",
                        ms=6, capsize=3, color=colour)
            ax.plot([0, h[-1]], [r["estimate"], m[-1]], ":", color=colour, lw=1)
            nodes = [g["nodes"] for g in r["rungs"]]
            rel = np.array([np.nan if g["rel_error"] is None else 100 * g["rel_error"]
                            for g in r["rungs"]])
            rs = np.array([0 if g["rel_error_sem"] is None else 100 * g["rel_error_sem"]
                           for g in r["rungs"]])
            bx.errorbar(nodes, rel, yerr=rs, fmt="o-", ms=4, capsize=3, color=colour,
                        label=f"cycle {r['cycle']}")
    ax.set_xlim(left=-0.1)
    ax.set_xlabel("mesh length h = sqrt(area / triangles)  (mm)")
    ax.set_ylabel("crease length P  (units of L0)")
    ax.set_title("P per cycle against resolution; squares: Richardson estimate (h = 0)",
                 fontsize=9)
    ax.legend(fontsize=7)
    for tol, style in ((15, "--"), (5, ":")):
        for sign in (1, -1):
            bx.axhline(sign * tol, color="0.5", ls=style, lw=1)
    bx.axhline(0, color="k", lw=0.6)
    bx.set_xscale("log")
    bx.set_xlabel("nodes")
    bx.set_ylabel("(P - estimate) / estimate  (%)")
    bx.set_title("relative error per rung; bands: 15 % (quick), 5 % (paper)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", help="runs/sweeps/NAME/points.json")
    ap.add_argument("--results", required=True, help="results/NAME")
    ap.add_argument("--collapse-only", action="store_true",
                    help="only collapse.png, from RESULTS/collapse.json alone (a study kept in "
                         "docs/studies/NAME/ without its runs)")
    ap.add_argument("--convergence-only", action="store_true",
                    help="only convergence.png, from RESULTS/convergence.json alone")
    a = ap.parse_args()
    if a.collapse_only or a.convergence_only:
        if a.collapse_only:
            collapse(a.results, os.path.join(a.results, "collapse.png"))
        if a.convergence_only:
            convergence(a.results, os.path.join(a.results, "convergence.png"))
        return
    if not a.points:
        die("give --points (or --collapse-only)")
    points = load_json(a.points, "sweep points file")
    crease_length(points, a.results, os.path.join(a.results, "crease_length.png"))
    if points.get("collapse"):
        collapse(a.results, os.path.join(a.results, "collapse.png"))
    if points.get("convergence"):
        convergence(a.results, os.path.join(a.results, "convergence.png"))


if __name__ == "__main__":
    main()
