#!/usr/bin/python3
"""Facet-area distributions per cycle (statistics.md section 3.7): the log-binned density of the
scaled area xi = x/<x> (bin ratio 1.55) pooled over the seeds of the ensemble (each run scaled by
its own mean), on log-log axes, against phi(xi; a_fit) and phi(xi; a_univ) with the ensemble
means of a_fit and a_univ. The dotted vertical line is the smallest resolvable xi.

usage: plot_facets.py results/ensemble.json -o results/facets.png
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, load_json, phi, read_csv  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RATIO = 1.55


def log_density(xi):
    xi = np.asarray(xi, float)
    xi = xi[xi > 0]
    k = np.floor(np.log(xi) / math.log(RATIO) + 1e-12)
    ks = np.arange(k.min(), k.max() + 1)
    lo, hi = RATIO ** ks, RATIO ** (ks + 1)
    counts = np.array([np.sum(k == j) for j in ks], float)
    return np.sqrt(lo * hi), counts / ((hi - lo) * len(xi)), counts


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ensemble", help="ensemble.json from ensemble.py")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    e = load_json(args.ensemble, "ensemble file")
    pooled = {}
    floors = {}
    for r in e["runs"]:
        path = os.path.join(r["analysis_dir"], "facets.csv")
        for row in read_csv(path):
            pooled.setdefault(int(row["cycle"]), []).append(float(row["xi"]))
        for c in r["cycles"]:
            if c.get("smallest_resolvable_xi") is not None:
                floors.setdefault(c["cycle"], []).append(c["smallest_resolvable_xi"])
    if not pooled:
        die("no facets in any run")
    stats = {c["cycle"]: c for c in e["cycles"]}
    cycles = sorted(pooled)
    cols = min(3, len(cycles))
    rows = math.ceil(len(cycles) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.6 * rows), squeeze=False)
    for ax, n in zip(axes.flat, cycles):
        x, d, cnt = log_density(pooled[n])
        ok = cnt > 0
        ax.loglog(x[ok], d[ok], "o", color="C0", label=f"simulation ({len(pooled[n])} facets)")
        grid = np.logspace(math.log10(max(min(pooled[n]) / 3, 1e-6)), math.log10(max(pooled[n]) * 3), 200)
        s = stats.get(n, {})
        for key, style, name in (("a_fit_mean", "-", "a_fit"), ("a_univ_mean", "--", "a_univ")):
            a = s.get(key)
            if a:
                ax.loglog(grid, phi(grid, a), style, label=f"φ(ξ; {name}={a:.2f})")
        if n in floors:
            ax.axvline(float(np.mean(floors[n])), color="0.5", ls=":", lw=1)
        ax.set_title(f"cycle {n}")
        ax.set_xlabel("ξ = x / ⟨x⟩")
        ax.set_ylabel("density")
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(cycles):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"plot_facets.py: wrote {args.output}")


if __name__ == "__main__":
    main()
