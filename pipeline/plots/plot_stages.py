#!/usr/bin/python3
"""Where the creases were made: for every cycle, the new crease length (creased-edge length,
in L0, at the run's crease threshold) made in each stage of the cycle, as stacked bars of the
ensemble mean over seeds with the s.e.m. of each stage as an error bar at the top of its
segment (left; hatched bars below zero: crease length that fell back below the threshold in
that stage, when crumple-analyze reports it); and the share of each cycle's new crease length
made after its last compress stage ended, per seed and as mean +- s.e.m., against the 15 %
target of issue 31 (right).
A cycle's new creases (hinges creased at its end, not at the previous cycle's end) are
attributed to the stage from whose end on they stay creased to the cycle's end, so the stages'
new lengths add up to the cycle's (crumple-analyze, analysis/creases/stage_accounting.hpp).

Runs without per-stage data (run files without /stage_ends, or an older crumple-analyze) give
a figure that says so.

usage: plot_stages.py results/ensemble.json -o results/images/stages.png [--format png|svg]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import ensemble_cli, save_figure  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

TARGET = 0.15
STAGE_COLOURS = {"roll": "0.6", "compress": "C0", "release": "C1", "unfold": "C3"}


def main():
    args, e = ensemble_cli(__doc__)
    st = e["stages"]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw={"width_ratios": [1.4, 1]})
    if not st.get("available"):
        for a in (ax, ax2):
            a.axis("off")
        fig.text(0.5, 0.5, "No per-stage data in these runs:\n" + st.get("note", ""),
                 ha="center", va="center", wrap=True)
        save_figure(fig, args.output, args.format, dpi=110)
        print(f"plot_stages.py: wrote {args.output} (no per-stage data)")
        return

    # one series per (index, stage type); the colour follows the stage type
    keys = sorted({(s["index"], s["stage"]) for c in st["cycles"] for s in c["stages"]})
    names = {}
    for idx, name in keys:
        same = [k for k in keys if k[1] == name]
        names[(idx, name)] = name if len(same) == 1 else f"{name} ({same.index((idx, name)) + 1})"
    extra = iter(f"C{i}" for i in (2, 4, 5, 6, 8, 9) * 3)
    colours = {k: STAGE_COLOURS.get(k[1]) or next(extra) for k in keys}
    cycles = [c["cycle"] for c in st["cycles"]]
    x = np.arange(len(cycles), dtype=float)
    bottom = np.zeros(len(cycles))
    lost_bottom = np.zeros(len(cycles))
    any_lost = False
    for j, k in enumerate(keys):
        m = np.zeros(len(cycles))
        s = np.zeros(len(cycles))
        for i, c in enumerate(st["cycles"]):
            row = next((r for r in c["stages"] if (r["index"], r["stage"]) == k), None)
            if row and row["new_crease_length_L0_mean"] is not None:
                m[i] = row["new_crease_length_L0_mean"]
                s[i] = row["new_crease_length_L0_sem"] or 0.0
        lost = np.zeros(len(cycles))
        for i, c in enumerate(st["cycles"]):
            row = next((r for r in c["stages"] if (r["index"], r["stage"]) == k), None)
            if row and row.get("lost_crease_length_L0_mean"):
                lost[i] = row["lost_crease_length_L0_mean"]
        if np.any(lost > 0):
            any_lost = True
            ax.bar(x, -lost, 0.6, bottom=lost_bottom, color=colours[k], edgecolor="k", lw=0.5,
                   hatch="///", alpha=0.6)
            lost_bottom -= lost
        ax.bar(x, m, 0.6, bottom=bottom, color=colours[k], edgecolor="k", lw=0.5, label=names[k])
        off = (j - (len(keys) - 1) / 2) * 0.08
        ax.errorbar(x + off, bottom + m, yerr=s, fmt="none", ecolor="k", capsize=2, lw=0.8)
        bottom += m
    ax.set_xticks(x)
    ax.set_xticklabels([str(c) for c in cycles])
    ax.set_xlabel("cycle n")
    ax.set_ylabel("new crease length in the stage / L0")
    thr = e.get("parameters", {}).get("threshold")
    ax.set_title(f"(a) new crease length by stage, mean over {st['n_runs_with_stages']} seed(s), "
                 f"|p| > {thr}; error bars: s.e.m.", fontsize=9)
    if any_lost:
        ax.axhline(0, color="k", lw=0.8)
        ax.bar([np.nan], [np.nan], color="w", edgecolor="k", hatch="///",
               label="lost (fell below the threshold)")
    ax.legend(fontsize=8, title="stage", title_fontsize=8)

    any_share = False
    for i, c in enumerate(st["cycles"]):
        vals = [v for v in c.get("share_after_compress_values") or [] if v is not None]
        if vals:
            any_share = True
            ax2.plot(np.full(len(vals), x[i]) + np.linspace(-0.12, 0.12, len(vals)),
                     100 * np.array(vals), ".", color="0.6", label="seeds" if i == 0 else None)
    m = np.array([np.nan if c["share_after_compress_mean"] is None else c["share_after_compress_mean"]
                  for c in st["cycles"]], float)
    s = np.array([0 if c["share_after_compress_sem"] is None else c["share_after_compress_sem"]
                  for c in st["cycles"]], float)
    if any_share:
        ax2.errorbar(x, 100 * m, yerr=100 * s, fmt="o", color="C3", capsize=3, label="mean ± s.e.m.")
    else:
        ax2.text(0.5, 0.5, "no share available\n(no compress stage, or no new creases)",
                 ha="center", va="center", transform=ax2.transAxes)
    ax2.axhline(100 * TARGET, color="k", ls="--", lw=1, label="target: at most 15 %")
    ax2.set_xticks(x)
    ax2.set_xticklabels([str(c) for c in cycles])
    ax2.set_xlim(-0.6, len(cycles) - 0.4)
    top = np.nanmax(np.concatenate([100 * m + 100 * s, [100 * TARGET]])) if any_share else 100
    ax2.set_ylim(0, min(100, max(25, 1.15 * top)))
    ax2.set_xlabel("cycle n")
    ax2.set_ylabel("% of the cycle's new crease length")
    ax2.set_title("(b) share made after the last compress stage ended", fontsize=9)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, args.output, args.format, dpi=110)
    print(f"plot_stages.py: wrote {args.output}")


if __name__ == "__main__":
    main()
