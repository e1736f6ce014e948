#!/usr/bin/python3
"""Crease length against cycle number (statistics.md section 2): each seed, the ensemble mean with
its spread (one standard deviation over seeds), the log-law fit l = C ln(1 + n/n0) of the mean,
and the experimental law c1 (1 - D) ln(1 + c2 n/D) for the run's compaction D.

The absolute level of the simulated length depends on mesh resolution and on the crease threshold
(statistics.md section 2.3), so the right panel compares shapes: each curve divided by its value at
the last simulated cycle. The left panel shows the experimental law scaled by the same factor that
makes it equal to the simulated mean at the last cycle; the factor is printed in the legend.

usage: plot_crease_length.py results/ensemble.json -o results/crease_length.png
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, experimental_law, load_json  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ensemble", help="ensemble.json from ensemble.py")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    e = load_json(args.ensemble, "ensemble file")
    if not e.get("cycles"):
        die(f"{args.ensemble} has no cycles")

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for r in e["runs"]:
        n = [c["cycle"] for c in r["cycles"]]
        ax.plot(n, [c["crease_length_L0"] for c in r["cycles"]], "-", color="0.7", lw=1,
                label="seeds" if r is e["runs"][0] else None)
    n = np.array([c["cycle"] for c in e["cycles"]], float)
    m = np.array([c["crease_length_L0_mean"] for c in e["cycles"]], float)
    sd = np.array([c["crease_length_L0_std"] or 0.0 for c in e["cycles"]], float)
    ax.fill_between(n, m - sd, m + sd, color="C0", alpha=0.25, label="mean ± 1 s.d.")
    ax.plot(n, m, "o-", color="C0", label="ensemble mean")
    nn = np.linspace(0, max(n.max(), 1), 200)
    fit = e.get("fit_crease_length_L0")
    if fit and "C" in fit:
        ax.plot(nn, fit["C"] * np.log1p(nn / fit["n0"]), "--", color="C1",
                label=f"fit C={fit['C']:.3g}±{fit['sigma_C']:.2g}, n0={fit['n0']:.3g}±{fit['sigma_n0']:.2g}")
    D = e.get("compaction")
    if D:
        exp_n = experimental_law(nn[1:], D)
        ref = experimental_law([n.max()], D)[0]
        scale = m[-1] / ref if ref > 0 and m[-1] > 0 else 0.0
        if scale > 0:
            ax.plot(nn[1:], scale * np.array(exp_n), ":", color="C3",
                    label=f"experiment, D={D:g}, × {scale:.3g}")
            ax2.plot(nn[1:], np.array(exp_n) / ref, ":", color="C3", label=f"experiment (n0 = {10 * D:.2g})")
    if m[-1] > 0:
        ax2.plot(n, m / m[-1], "o-", color="C0", label="simulation mean")
        if fit and "C" in fit:
            ax2.plot(nn, fit["C"] * np.log1p(nn / fit["n0"]) / m[-1], "--", color="C1", label="fit")
    ax.set_xlabel("cycle n")
    ax.set_ylabel("crease length ℓ / L0")
    ax.set_title(f"crease length, {e['n_runs']} runs")
    ax.legend(fontsize=8)
    ax2.set_xlabel("cycle n")
    ax2.set_ylabel("ℓ(n) / ℓ(last cycle)")
    ax2.set_title("shape of ℓ(n)")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"plot_crease_length.py: wrote {args.output}")


if __name__ == "__main__":
    main()
