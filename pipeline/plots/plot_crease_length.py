#!/usr/bin/python3
"""Crease length against cycle number, compared with the experimental law at its absolute level
(docs/STATISTICS.md §2), in four panels:

(a) P, the facet-perimeter crease length of the experiments, P = (sum of facet perimeters -
    sheet outline) / (2 L0) (docs/STATISTICS.md §2.1), the primary quantity: each seed, the
    ensemble mean +- s.e.m. over seeds, the log-law fit to the per-cycle increments (primary
    fit), the fit to the cumulative values (correlated between cycles; shown for comparison),
    and the experimental law c1 (1 - D) ln(1 + c2 n/D) for the run's compaction D, unscaled
    (the reading without the factor (1 - D), docs/STATISTICS.md §2.4, as a faint line);
(b) the same for l/L0, the total length of creased mesh edges;
(c) the per-cycle increments dP_n and dl_n (mean +- s.e.m.), the data the primary fits use,
    with the fitted and the experimental increments;
(d) the dangling fraction 1 - P/(l/L0): the part of the crease length that does not separate
    two facets (crease ends inside a facet).

usage: plot_crease_length.py results/ensemble.json -o results/images/crease_length.png [--format png|svg]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, ensemble_cli, law_constants, save_figure  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
import numpy as np  # noqa: E402


def col(e, key):
    return np.array([np.nan if c.get(key) is None else c[key] for c in e["cycles"]], float)


def fit_label(f, what):
    if not f or "C" not in f:
        return None
    s = lambda v: "?" if v is None else f"{v:.2g}"  # noqa: E731
    return (f"{what}: C={f['C']:.3g}±{s(f['sigma_C'])}, n0={f['n0']:.3g}±{s(f['sigma_n0'])}, "
            f"χ²/dof={f['chi2']:.2g}/{f['dof']}")


def panel(ax, e, key, ylabel, title, law, law_nofactor, nn):
    fits = e["fits"].get(key, {})
    for i, r in enumerate(e["runs"]):
        n = [c["cycle"] for c in r["cycles"] if c.get(key) is not None]
        y = [c[key] for c in r["cycles"] if c.get(key) is not None]
        ax.plot([0] + n, [0] + y, "-", color="0.75", lw=0.9, label="seeds" if i == 0 else None)
    n = np.array([c["cycle"] for c in e["cycles"]], float)
    m, sem = col(e, key + "_mean"), col(e, key + "_sem")
    ax.errorbar(n, m, yerr=np.nan_to_num(sem), fmt="o", color="C0", capsize=3, zorder=5,
                label="simulation: mean ± s.e.m." if np.any(np.isfinite(sem)) else "simulation")
    f = fits.get("increments")
    lab = fit_label(f, "fit to increments")
    if lab:
        ax.plot(nn, f["C"] * np.log1p(nn / f["n0"]), "-", color="C1", label=lab)
    f = fits.get("cumulative")
    lab = fit_label(f, "fit to cumulative (correlated)")
    if lab:
        ax.plot(nn, f["C"] * np.log1p(nn / f["n0"]), "--", color="C2", lw=1, label=lab)
    if law is not None:
        ax.plot(nn, law, ":", color="C3", lw=2, label="experimental law (absolute, not scaled)")
        ax.plot(nn, law_nofactor, ":", color="C3", lw=0.8, alpha=0.6,
                label="law without (1 − D), §2.4 reading")
    ymax = np.nanmax(m) if np.any(np.isfinite(m)) else 0
    if law is not None and ymax > 0 and law[-1] / ymax > 10:
        ax.set_yscale("log")
        ax.set_ylim(bottom=max(np.nanmin(m[m > 0]) / 3, 1e-3) if np.any(m > 0) else 1e-3)
        title += " (log scale)"
    ax.set_xlabel("cycle n")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.set_xlim(0, nn[-1])
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.legend(fontsize=6.5, loc="upper left")


def main():
    args, e = ensemble_cli(__doc__)
    if not e.get("cycles"):
        die(f"{args.ensemble} has no cycles")

    n = np.array([c["cycle"] for c in e["cycles"]], float)
    nn = np.linspace(0, max(n.max(), 1) + 0.3, 300)
    D = e.get("compaction")
    law = law_nf = None
    if D is not None and 0 < D < 1:
        c1, c2 = law_constants()
        law = c1 * (1 - D) * np.log1p(c2 * nn / D)
        law_nf = law / (1 - D)
    dtxt = f"D = {D:g}" if D is not None else "compaction unknown: no experimental law"

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    panel(axes[0, 0], e, "perimeter_P", "P  (facet-perimeter crease length / L0)",
          f"(a) P against the experimental law, {dtxt}", law, law_nf, nn)
    panel(axes[0, 1], e, "crease_length_L0", "ℓ / L0  (creased-edge length)",
          f"(b) ℓ/L0 against the experimental law, {dtxt}", law, law_nf, nn)

    ax = axes[1, 0]
    for k, (key, name, colour) in enumerate((("perimeter_P", "ΔP", "C0"),
                                             ("crease_length_L0", "Δℓ/L0", "C4"))):
        m, sem = col(e, key + "_increment_mean"), col(e, key + "_increment_sem")
        ax.errorbar(n + (k - 0.5) * 0.12, m, yerr=np.nan_to_num(sem), fmt="o", color=colour,
                    capsize=3, label=f"{name}: mean ± s.e.m.")
        f = e["fits"].get(key, {}).get("increments")
        if f and "C" in f:
            ax.plot(n, f["C"] * (np.log1p(n / f["n0"]) - np.log1p((n - 1) / f["n0"])), "-",
                    color=colour, lw=1, label=f"{name}: fit to increments")
    if law is not None:
        c1, c2 = law_constants()
        ax.plot(n, c1 * (1 - D) * (np.log1p(c2 * n / D) - np.log1p(c2 * (n - 1) / D)), "s:",
                color="C3", ms=4, label="experimental law")
    ax.set_xlabel("cycle n")
    ax.set_ylabel("new crease length in cycle n / L0")
    ax.set_title("(c) per-cycle increments (the data of the primary fits)", fontsize=10)
    ax.set_xticks(n)
    ax.legend(fontsize=7)

    ax = axes[1, 1]
    for i, r in enumerate(e["runs"]):
        pts = [(c["cycle"], c["dangling_fraction"]) for c in r["cycles"]
               if c.get("dangling_fraction") is not None]
        if pts:
            ax.plot(*zip(*pts), "-", color="0.75", lw=0.9, label="seeds" if i == 0 else None)
    m, sem = col(e, "dangling_fraction_mean"), col(e, "dangling_fraction_sem")
    if np.any(np.isfinite(m)):
        ax.errorbar(n, m, yerr=np.nan_to_num(sem), fmt="o-", color="C0", capsize=3,
                    label="mean ± s.e.m.")
        ax.set_ylim(min(0, np.nanmin(m) - 0.05), 1)
        ax.legend(fontsize=7)
    else:
        ax.text(0.5, 0.5, "no dangling_fraction in these stats.json files\n(older crumple-analyze)",
                ha="center", va="center", transform=ax.transAxes)
    ax.set_xlabel("cycle n")
    ax.set_ylabel("1 − P / (ℓ/L0)")
    ax.set_title("(d) dangling fraction: crease length not bounding two facets", fontsize=10)
    ax.set_xticks(n)
    fig.suptitle(f"Crease length per cycle, {e['n_runs']} run(s); threshold "
                 f"|p| > {e.get('parameters', {}).get('threshold')}", fontsize=11)
    fig.tight_layout()
    save_figure(fig, args.output, args.format, dpi=110)
    print(f"plot_crease_length.py: wrote {args.output}")


if __name__ == "__main__":
    main()
