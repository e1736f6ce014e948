#!/usr/bin/python3
"""Facet-area distributions per cycle (docs/STATISTICS.md §3.7): the log-binned density of the
scaled area xi = x/<x> (bin ratio 1.55) pooled over the seeds of the ensemble (each run scaled by
its own mean), on log-log axes with Poisson error bars (density / sqrt(count)), against
phi(xi; a_fit) and phi(xi; a_univ) (docs/STATISTICS.md §3.3-3.4) with the ensemble means of
a_fit and a_univ. The axes are set by the data, not by the model curves. The grey band is
below the resolution floor (one mesh triangle: crease edges cannot enclose less); a panel title
in red means more than 20 % of that cycle's facets are single triangles.

usage: plot_facets.py results/ensemble.json -o results/images/facets.png [--format png|svg]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, ensemble_cli, phi, read_csv, save_figure  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RATIO = 1.55
SINGLE_TRIANGLE_WARN = 0.20  # the report's resolution warning (make_report.py)


def log_density(xi):
    xi = np.asarray(xi, float)
    xi = xi[xi > 0]
    k = np.floor(np.log(xi) / math.log(RATIO) + 1e-12)
    ks = np.arange(k.min(), k.max() + 1)
    lo, hi = RATIO ** ks, RATIO ** (ks + 1)
    counts = np.array([np.sum(k == j) for j in ks], float)
    return np.sqrt(lo * hi), counts / ((hi - lo) * len(xi)), counts


def main():
    args, e = ensemble_cli(__doc__)
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
    fig, axes = plt.subplots(rows, cols, figsize=(4.4 * cols, 3.9 * rows), squeeze=False)
    for ax, n in zip(axes.flat, cycles):
        xi = np.asarray(pooled[n], float)
        xi = xi[xi > 0]
        x, d, cnt = log_density(xi)
        ok = cnt > 0
        err = d[ok] / np.sqrt(cnt[ok])
        lo_err = np.minimum(err, 0.9 * d[ok])  # keep the lower bar above 0 on log axes
        ax.errorbar(x[ok], d[ok], yerr=[lo_err, err], fmt="o", ms=4, color="C0", capsize=2,
                    label=f"simulation ({len(xi)} facets)", zorder=5)
        # axes from the data, with a margin; the model curves are clipped to them
        xlo, xhi = RATIO ** np.floor(np.log(xi.min()) / math.log(RATIO)), xi.max() * RATIO
        ylo = np.min(d[ok]) / 5 if np.any(ok) else 1e-3
        yhi = np.max(d[ok] + err) * 2 if np.any(ok) else 1
        grid = np.logspace(math.log10(xlo / 1.5), math.log10(xhi * 1.5), 300)
        s = stats.get(n, {})
        for key, style, name in (("a_fit_mean", "-", "a_fit"), ("a_univ_mean", "--", "a_univ")):
            a = s.get(key)
            if a:
                ax.plot(grid, phi(grid, a), style, label=f"φ(ξ; {name} = {a:.2f})")
        if n in floors:
            fl = float(np.mean(floors[n]))
            ax.axvspan(xlo / 1.5, fl, color="0.85", zorder=0,
                       label=f"below one mean mesh triangle (ξ < {fl:.2g})")
            ax.axvline(fl, color="0.4", ls=":", lw=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(xlo / 1.5, xhi * 1.5)
        ax.set_ylim(ylo, yhi)
        title = f"cycle {n}"
        stf = s.get("single_triangle_fraction_mean")
        if stf is not None:
            title += f", single-triangle facets {100 * stf:.0f} %"
        if s.get("ks_n_tested"):
            title += f"\nKS vs φ(a_fit): rejected at 5 % in {s['ks_n_rejected']}/{s['ks_n_tested']} runs"
        ax.set_title(title, fontsize=9, color="C3" if (stf or 0) > SINGLE_TRIANGLE_WARN else "k")
        ax.set_xlabel("ξ = x / ⟨x⟩")
        ax.set_ylabel("density (count / bin width / total)")
        ax.legend(fontsize=6.5, loc="best")
    for ax in list(axes.flat)[len(cycles):]:
        ax.axis("off")
    # the red titles are a key of their own: say what they mean in the figure
    warned = any((stats.get(n, {}).get("single_triangle_fraction_mean") or 0) > SINGLE_TRIANGLE_WARN
                 for n in cycles)
    if warned:
        fig.text(0.5, 0.005, "Title in red: more than 20 % of that cycle's facets are single mesh "
                 "triangles; its small-facet end is set by the mesh, not by the crumpling.",
                 ha="center", va="bottom", fontsize=8, color="C3")
    fig.tight_layout(rect=(0, 0.25 / fig.get_figheight() if warned else 0, 1, 1))
    save_figure(fig, args.output, args.format, dpi=110)
    print(f"plot_facets.py: wrote {args.output}")


if __name__ == "__main__":
    main()
