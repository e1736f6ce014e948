#!/usr/bin/python3
"""Crease maps and facets of one run, per cycle, with a scale bar in cm and a key.

Reads the images crumple-analyze wrote into the run's analysis folder (crease_NNNN.png,
facets_NNNN.png) and its stats.json (sheet.px_per_m for the scale; per-cycle crease length,
P and facet count for the titles). Both images show the sheet in its flat reference
configuration. Crease map: creased hinges (|p| above the crease threshold) drawn along their
mesh edges, red for p > 0 and blue for p < 0 (plastic rest curvature of opposite sense), on the
light-grey sheet with its outline in black. Facets: the segmentation of that crease map, one
random colour per facet (labels grown over the crease pixels so the facets tile the sheet).

usage: plot_maps.py runs/.../seed1.analysis -o results/maps.png [--max-cycles 6]
"""
import argparse
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import die, load_json  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402
import numpy as np  # noqa: E402

# colours of analysis/raster/crease_map.cpp (OpenCV BGR there, RGB here)
RED, BLUE, SHEET = (220 / 255, 40 / 255, 40 / 255), (30 / 255, 90 / 255, 200 / 255), (225 / 255,) * 3


def pick(cycles, k):
    """At most k cycles, evenly spread, always with the first and the last."""
    if len(cycles) <= k:
        return cycles
    idx = np.unique(np.round(np.linspace(0, len(cycles) - 1, k)).astype(int))
    return [cycles[i] for i in idx]


def nice_length(width_cm):
    for v in (10, 5, 2, 1, 0.5, 0.2, 0.1, 0.05):
        if v <= width_cm / 3:
            return v
    return width_cm / 4


def scale_bar(ax, w_cm, h_cm):
    L = nice_length(w_cm)
    x0, y0 = 0.05 * w_cm, 0.06 * h_cm
    ax.add_patch(Rectangle((x0 - 0.02 * w_cm, y0 - 0.03 * h_cm), L + 0.04 * w_cm, 0.12 * h_cm,
                           facecolor="white", edgecolor="none", alpha=0.8, zorder=4))
    ax.plot([x0, x0 + L], [y0, y0], "-", color="k", lw=3, solid_capstyle="butt", zorder=5)
    ax.text(x0 + L / 2, y0 + 0.015 * h_cm, f"{L:g} cm", ha="center", va="bottom", fontsize=7, zorder=5)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("analysis", help="analysis folder of one run (stats.json and the PNGs)")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--max-cycles", type=int, default=6, help="at most this many cycles (default 6)")
    args = ap.parse_args()
    s = load_json(os.path.join(args.analysis, "stats.json"), "stats.json of the shown run")
    tags = {}
    for p in glob.glob(os.path.join(args.analysis, "crease_*.png")):
        m = re.match(r"crease_(\d+)\.png$", os.path.basename(p))
        if m and os.path.isfile(os.path.join(args.analysis, f"facets_{m.group(1)}.png")):
            tags[int(m.group(1))] = m.group(1)
    if not tags:
        die(f"no crease_NNNN.png with a matching facets_NNNN.png in {args.analysis}")
    sheet = s.get("sheet", {})
    px_per_m = sheet.get("px_per_m")
    if not px_per_m and s.get("parameters", {}).get("px_per_cm"):
        px_per_m = 100.0 * s["parameters"]["px_per_cm"]
    if not px_per_m:
        die(f"{args.analysis}/stats.json gives neither sheet.px_per_m nor parameters.px_per_cm")
    stats = {c["cycle"]: c for c in s.get("cycles", [])}
    cycles = pick(sorted(tags), args.max_cycles)
    k = len(cycles)
    fig, axes = plt.subplots(2, k, figsize=(2.6 * k + 0.4, 6.0), squeeze=False)
    width_px = 0
    for j, n in enumerate(cycles):
        c = stats.get(n, {})
        for i, kind in enumerate(("crease", "facets")):
            img = mpimg.imread(os.path.join(args.analysis, f"{kind}_{tags[n]}.png"))
            h, w = img.shape[:2]
            w_cm, h_cm = 100.0 * w / px_per_m, 100.0 * h / px_per_m
            ax = axes[i, j]
            ax.imshow(img, extent=(0, w_cm, 0, h_cm), interpolation="antialiased")
            ax.set_xticks([])
            ax.set_yticks([])
            scale_bar(ax, w_cm, h_cm)
            if i == 0:
                t = [f"cycle {n}"]
                if c.get("crease_length_L0") is not None:
                    t.append(f"ℓ = {c['crease_length_L0']:.3g} L0")
                if c.get("perimeter_P") is not None:
                    t.append(f"P = {c['perimeter_P']:.3g}")
                if c.get("n_facets") is not None:
                    t.append(f"{c['n_facets']} facets")
                ax.set_title(t[0] + "\n" + ", ".join(t[1:]), fontsize=8)
            width_px = max(width_px, w)
    axes[0, 0].set_ylabel("crease map", fontsize=9)
    axes[1, 0].set_ylabel("facets", fontsize=9)
    thr = s.get("parameters", {}).get("threshold")
    key = [Patch(facecolor=RED, label="crease, p > 0"),
           Patch(facecolor=BLUE, label="crease, p < 0 (opposite sense)"),
           Patch(facecolor=SHEET, edgecolor="0.5", label="sheet, not creased"),
           Line2D([], [], color="k", lw=1, label="sheet outline"),
           Patch(facecolor="white", edgecolor="0.5", label="outside the sheet"),
           Patch(facecolor="#d08a5a", edgecolor="none", label="facets: one random colour each")]
    fig.legend(handles=key, loc="lower center", ncol=3, fontsize=8, frameon=False)
    seed = s.get("input", {}).get("meta", {}).get("seed")
    fig.suptitle(f"Crease maps and facets in the flat reference configuration, seed {seed}, "
                 f"crease threshold |p| > {thr}", fontsize=10)
    fig.tight_layout(rect=(0, 0.09, 1, 0.96))
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    # enough pixels per panel that one-pixel crease lines survive
    fig.savefig(args.output, dpi=float(np.clip(width_px / 2.2, 110, 250)))
    print(f"plot_maps.py: wrote {args.output} (cycles {', '.join(map(str, cycles))})")


if __name__ == "__main__":
    main()
