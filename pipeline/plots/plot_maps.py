#!/usr/bin/python3
"""Crease maps and facets of one run, per cycle, each map with a scale bar in physical units and
the figure with a key to its colours.

Reads the images crumple-analyze wrote into the run's analysis folder (crease_NNNN.png,
facets_NNNN.png), its facets.csv (the area of every facet) and its stats.json (sheet.px_per_m
for the scale; per-cycle crease length, P and facet count for the titles; the crease threshold).
Both rows show the sheet in its flat reference configuration.

Top row, crease map: creased hinges (|p| above the crease threshold, p the plastic rest
curvature) drawn along their mesh edges, red for p > 0 and blue for p < 0 (opposite fold
senses), on the light-grey uncreased sheet with its outline in black; the legend says so.
Bottom row, facets: the segmentation of that crease map (labels grown over the crease pixels so
the facets tile the sheet), each facet filled by its area in mm² on a logarithmic colour scale
(the colour bar; the mark on it is the mean area of one mesh triangle, about the smallest facet
the mesh can make), facet boundaries in dark grey. The areas are facets.csv's: crumple-analyze
paints each facet one colour, and the pixel share of each colour (or, past the few thousand
facets after which its colours repeat, of each connected region of one colour) is matched to
facets.csv's area fractions x. Pixels that match no facet are grey; a panel that does not match
keeps crumple-analyze's arbitrary colours. The legend says so when either happens.

usage: plot_maps.py runs/.../seed1.analysis -o results/images/maps.png [--format png|svg]
                    [--max-cycles 6]
"""
import argparse
import glob
import os
import re
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import add_figure_args, die, figure_output, load_json, read_csv, save_figure  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter  # noqa: E402
import numpy as np  # noqa: E402
from scipy.sparse import coo_matrix  # noqa: E402
from scipy.sparse.csgraph import connected_components  # noqa: E402

# colours of analysis/raster/crease_map.cpp (OpenCV BGR there, RGB here)
RED, BLUE, SHEET = (220 / 255, 40 / 255, 40 / 255), (30 / 255, 90 / 255, 200 / 255), (225 / 255,) * 3
WHITE = 0xFFFFFF        # outside the sheet in facets_NNNN.png (packed RGB)
AREA_CMAP = "viridis"   # perceptually uniform and readable without colour vision
BOUNDARY = "0.15"
UNMATCHED = "0.7"       # pixels of no facet of facets.csv: stray bits of one, where colours repeat


def pick(cycles, k):
    """At most k cycles, evenly spread, always with the first and the last."""
    if len(cycles) <= k:
        return cycles
    idx = np.unique(np.round(np.linspace(0, len(cycles) - 1, k)).astype(int))
    return [cycles[i] for i in idx]


def nice_length(width_cm):
    """A round scale-bar length (cm) of at most a third of the map, and its label in cm or mm."""
    for v in (10, 5, 2, 1, 0.5, 0.2, 0.1, 0.05):
        if v <= width_cm / 3:
            return v, (f"{v:g} cm" if v >= 1 else f"{10 * v:g} mm")
    v = width_cm / 4
    return v, f"{10 * v:.2g} mm"


def scale_bar(ax, w_cm, h_cm, gid):
    """A black bar with its length, in a margin below the map (so it hides none of it); the
    map's x axis is in cm. Both artists take ids from `gid` (ids in SVG output)."""
    L, label = nice_length(w_cm)
    y = -0.08 * h_cm
    bar, = ax.plot([0, L], [y, y], "-", color="k", lw=3, solid_capstyle="butt", clip_on=False)
    bar.set_gid(gid)
    ax.text(L + 0.04 * w_cm, y, label, ha="left", va="center", fontsize=8, gid=gid + "-label")
    ax.set_ylim(-0.16 * h_cm, h_cm)


def clean_axes(ax):
    """No pixel ticks or frame: the scale bar gives the size."""
    ax.set_xticks([])
    ax.set_yticks([])
    for sp in ax.spines.values():
        sp.set_visible(False)


def map_cycles(analysis):
    """{cycle: 'NNNN'} for every cycle with both crease_NNNN.png and facets_NNNN.png."""
    tags = {}
    for p in glob.glob(os.path.join(analysis, "crease_*.png")):
        m = re.match(r"crease_(\d+)\.png$", os.path.basename(p))
        if m and os.path.isfile(os.path.join(analysis, f"facets_{m.group(1)}.png")):
            tags[int(m.group(1))] = m.group(1)
    if not tags:
        die(f"no crease_NNNN.png with a matching facets_NNNN.png in {analysis}")
    return tags


def pixels_per_m(s, analysis):
    px = s.get("sheet", {}).get("px_per_m")
    if not px and s.get("parameters", {}).get("px_per_cm"):
        px = 100.0 * s["parameters"]["px_per_cm"]
    if not px:
        die(f"{analysis}/stats.json gives neither sheet.px_per_m nor parameters.px_per_cm")
    return px


def rgb_uint8(img):
    """An image read by matplotlib (PNG: floats in [0, 1]) as 8-bit RGB."""
    img = np.asarray(img)[..., :3]
    return np.round(img * 255).astype(np.uint8) if img.dtype.kind == "f" else img.astype(np.uint8)


def area_of_share(share, x, area):
    """The area of a facet whose sheet fraction x equals each pixel share (relative 1e-6: the
    CSV keeps ten digits), NaN where none does. Facets of equal x have equal areas."""
    order = np.argsort(x)
    xs, ar = x[order], area[order]
    hi = np.clip(np.searchsorted(xs, share), 0, len(xs) - 1)
    lo = np.clip(hi - 1, 0, len(xs) - 1)
    near = np.where(np.abs(xs[lo] - share) < np.abs(xs[hi] - share), lo, hi)
    return np.where(np.abs(xs[near] - share) <= 1e-6 * share, ar[near], np.nan)


def colour_regions(packed, sheet):
    """Labels 0.. of the 4-connected regions of one colour on the sheet (-1 off it)."""
    h, w = packed.shape
    idx = np.arange(h * w).reshape(h, w)
    right = (packed[:, 1:] == packed[:, :-1]) & sheet[:, 1:]
    down = (packed[1:, :] == packed[:-1, :]) & sheet[1:, :]
    a = np.concatenate([idx[:, 1:][right], idx[1:, :][down]])
    b = np.concatenate([idx[:, :-1][right], idx[:-1, :][down]])
    graph = coo_matrix((np.ones(a.size, bool), (a, b)), shape=(h * w, h * w))
    region = connected_components(graph, directed=False)[1].reshape(h, w)
    labels = np.full((h, w), -1)
    labels[sheet] = np.unique(region[sheet], return_inverse=True)[1]
    return labels


def facet_area_map(img, rows):
    """The facets of facets_NNNN.png with facets.csv's areas (the rows of that cycle): a dict of
    `area` (mm² of the facet under each pixel; NaN outside the sheet and where unmatched),
    `edge` (facet boundaries) and `unmatched` (sheet pixels of no matched facet), or None when
    the image is not of these facets.

    crumple-analyze paints each facet one colour and x = facet pixels / sheet pixels, so with
    one colour per facet the colours' pixel shares, sorted, are facets.csv's x, sorted, and
    pairing them gives each colour its area. Past some thousands of facets its colours repeat
    (fewer colours than facets); then each 4-connected region of one colour is a facet (facets
    of one colour do not touch, or they would be one region) whose area is that of the facets
    with its pixel share (pixels of a region whose share is no facet's are left unmatched)."""
    if not rows:
        return None
    rgb = rgb_uint8(img).astype(np.uint32)
    packed = (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]
    sheet = packed != WHITE
    total = sheet.sum()
    x = np.array([float(r["x"]) for r in rows])
    area = np.array([float(r["area_m2"]) for r in rows]) * 1e6
    labels = np.full(packed.shape, -1)
    _, labels[sheet], count = np.unique(packed[sheet], return_inverse=True, return_counts=True)
    if len(count) == len(rows):
        by_share, by_x = np.argsort(count, kind="stable"), np.argsort(x, kind="stable")
        if not np.allclose(count[by_share] / total, x[by_x], rtol=1e-6, atol=0):
            return None
        label_area = np.empty(len(count))
        label_area[by_share] = area[by_x]
    elif len(count) < len(rows):
        labels = colour_regions(packed, sheet)
        label_area = area_of_share(np.bincount(labels[sheet]) / total, x, area)
    else:
        return None
    out = np.full(packed.shape, np.nan)
    out[sheet] = label_area[labels[sheet]]
    unmatched = sheet & np.isnan(out)
    if unmatched.sum() > total / 2:
        return None
    edge = np.zeros(packed.shape, bool)
    edge[:, 1:] |= labels[:, 1:] != labels[:, :-1]
    edge[1:, :] |= labels[1:, :] != labels[:-1, :]
    return {"area": out, "edge": edge & sheet, "unmatched": unmatched}


def area_text(mm2):
    """'164 mm²', '1110 mm²', '4.2 mm²': no powers of ten in a title."""
    return f"{mm2:.0f} mm²" if mm2 >= 100 else f"{mm2:.3g} mm²"


def crease_key(thr):
    p = f"{thr:.3g}" if thr is not None else "the threshold"
    return [Patch(facecolor=RED, label=f"crease: p > {p} (one fold sense)"),
            Patch(facecolor=BLUE, label=f"crease: p < −{p} (the other sense)"),
            Patch(facecolor=SHEET, edgecolor="0.5", label=f"sheet, not creased (|p| ≤ {p})"),
            Line2D([], [], color="k", lw=1, label="sheet outline"),
            Line2D([], [], color=BOUNDARY, lw=1, label="facet boundary"),
            Patch(facecolor="white", edgecolor="0.5", label="outside the sheet")]


def load_panels(analysis, max_cycles):
    """Everything the figure shows: stats.json, the cycles drawn, and per cycle its two images
    and the facet-area map (or None when it could not be matched)."""
    s = load_json(os.path.join(analysis, "stats.json"), "stats.json of the shown run")
    tags = map_cycles(analysis)
    rows = {}
    for r in read_csv(os.path.join(analysis, "facets.csv")):
        rows.setdefault(int(r["cycle"]), []).append(r)
    panels = []
    for n in pick(sorted(tags), max_cycles):
        crease = mpimg.imread(os.path.join(analysis, f"crease_{tags[n]}.png"))
        facets = mpimg.imread(os.path.join(analysis, f"facets_{tags[n]}.png"))
        panels.append({"cycle": n, "crease": crease, "facets": facets, "rows": rows.get(n, []),
                       "areas": facet_area_map(facets, rows.get(n, []))})
    return s, panels


def crease_title(n, c):
    t = [f"cycle {n}"]
    if c.get("crease_length_L0") is not None:
        t.append(f"ℓ = {c['crease_length_L0']:.3g} L0")
    if c.get("perimeter_P") is not None:
        t.append(f"P = {c['perimeter_P']:.3g}")
    return t[0] + "\n" + ", ".join(t[1:])


def area_colour_bar(fig, ax_right, norm, triangle_mm2):
    """The facets' colour key beside the bottom row: area in mm² on a log scale, with the mean
    area of one mesh triangle marked when it lies within the range."""
    box = ax_right.get_position()
    inch = 1.0 / fig.get_figwidth()  # in figure fractions: room for the mark's words
    cax = fig.add_axes([box.x1 + 0.55 * inch, box.y0 + 0.1 * box.height, 0.16 * inch,
                        0.8 * box.height])
    sm = plt.cm.ScalarMappable(norm=norm, cmap=AREA_CMAP)
    cb = fig.colorbar(sm, cax=cax)
    cb.set_label("facet area (mm², log scale)", fontsize=8)
    # over a decade or two one label per decade is too few to read a colour by
    decades = np.log10(norm.vmax / norm.vmin)
    cax.yaxis.set_major_locator(LogLocator(subs=(1, 2, 5) if decades <= 2.5 else (1,)))
    cax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    cax.yaxis.set_minor_formatter(NullFormatter())
    cax.tick_params(labelsize=7)
    if triangle_mm2 and norm.vmin <= triangle_mm2 <= norm.vmax:
        cax.axhline(triangle_mm2, color="w", lw=2)
        cax.axhline(triangle_mm2, color="k", lw=1)
        cax.text(-0.4, triangle_mm2, "1 mesh\ntriangle", transform=cax.get_yaxis_transform(),
                 ha="right", va="center", fontsize=6)
    cax.set_gid("facet-area-key")
    return cb


def area_norm(panels):
    """One logarithmic colour scale for the facet areas of all panels, None when none matched."""
    areas = [p["areas"]["area"] for p in panels if p["areas"] is not None]
    if not areas:
        return None
    lo = min(np.nanmin(a) for a in areas)
    hi = max(np.nanmax(a) for a in areas)
    return LogNorm(vmin=lo, vmax=hi if hi > lo else lo * 10)


def overlay(mask, colour):
    """An RGBA image: `colour` on `mask`, transparent elsewhere."""
    rgba = np.zeros(mask.shape + (4,))
    rgba[mask] = matplotlib.colors.to_rgba(colour)
    return rgba


def draw_facets(ax, p, ext, norm):
    """The facet panel of one cycle: areas on the colour scale, boundaries, unmatched pixels in
    grey; crumple-analyze's own colours when nothing matched. Returns what its key must say:
    {'arbitrary', 'unmatched'} or a part of it."""
    a = p["areas"]
    if a is None:
        ax.imshow(p["facets"], extent=ext, interpolation="nearest")
        ax.set_title(f"{len(p['rows'])} facets (arbitrary colours)", fontsize=8)
        return {"arbitrary"}
    ax.imshow(np.ma.masked_invalid(a["area"]), extent=ext, cmap=AREA_CMAP, norm=norm,
              interpolation="nearest")
    ax.imshow(overlay(a["unmatched"], UNMATCHED) + overlay(a["edge"], BOUNDARY), extent=ext,
              interpolation="nearest")
    mean = np.mean([float(r["area_m2"]) for r in p["rows"]]) * 1e6
    ax.set_title(f"{len(p['rows'])} facets, mean area {area_text(mean)}", fontsize=8)
    return {"unmatched"} if a["unmatched"].any() else set()


def figure_key(thr, needs):
    key = crease_key(thr)
    if "unmatched" in needs:
        key.append(Patch(facecolor=UNMATCHED, label="facet whose area is not in facets.csv"))
    if "arbitrary" in needs:
        key.append(Patch(facecolor="#d08a5a", label="facets in arbitrary colours: areas not "
                         "matched to facets.csv"))
    return key


def draw(analysis, max_cycles=6):
    """The figure (not saved) and the largest image width in pixels (for the output's dpi)."""
    s, panels = load_panels(analysis, max_cycles)
    px_per_m = pixels_per_m(s, analysis)
    stats = {c["cycle"]: c for c in s.get("cycles", [])}
    thr = s.get("parameters", {}).get("threshold")
    norm = area_norm(panels)
    k = len(panels)
    fig, axes = plt.subplots(2, k, figsize=(2.6 * k + 1.8, 6.4), squeeze=False)
    width_px = 0
    needs = set()
    for j, p in enumerate(panels):
        h, w = p["crease"].shape[:2]
        w_cm, h_cm = 100.0 * w / px_per_m, 100.0 * h / px_per_m
        ext = (0, w_cm, 0, h_cm)
        axes[0, j].imshow(p["crease"], extent=ext, interpolation="antialiased")
        axes[0, j].set_title(crease_title(p["cycle"], stats.get(p["cycle"], {})), fontsize=8)
        needs |= draw_facets(axes[1, j], p, ext, norm)
        for i in (0, 1):
            clean_axes(axes[i, j])
            scale_bar(axes[i, j], w_cm, h_cm, f"scale-bar-{i}-{j}")
        width_px = max(width_px, w)
    axes[0, 0].set_ylabel("crease map", fontsize=9)
    axes[1, 0].set_ylabel("facets", fontsize=9)
    key = figure_key(thr, needs)
    ncol = 2 if k <= 2 else 3
    rows_of_key = -(-len(key) // ncol)
    legend = fig.legend(handles=key, loc="lower center", ncol=ncol, fontsize=7.5, frameon=False)
    legend.set_gid("crease-key")
    seed = s.get("input", {}).get("meta", {}).get("seed")
    title = (f"Crease maps and facets of seed {seed} at the end of each cycle, in the flat "
             f"reference configuration; crease when |p| > {'?' if thr is None else f'{thr:.3g}'} "
             "(p: plastic rest curvature of a hinge)")
    fig.suptitle(textwrap.fill(title, width=int(13 * fig.get_figwidth())), fontsize=9)
    fig.tight_layout(rect=(0, 0.035 * rows_of_key + 0.01, 1 - 1.6 / fig.get_figwidth(), 0.91))
    if norm is not None:
        tri = s.get("resolution", {}).get("mean_triangle_area_m2")
        area_colour_bar(fig, axes[1, -1], norm, tri * 1e6 if tri else None)
    return fig, width_px


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("analysis", help="analysis folder of one run (stats.json, facets.csv and the PNGs)")
    add_figure_args(ap)
    ap.add_argument("--max-cycles", type=int, default=6, help="at most this many cycles (default 6)")
    args = ap.parse_args()
    out, fmt = figure_output(args)
    fig, width_px = draw(args.analysis, args.max_cycles)
    # enough pixels per panel that one-pixel crease lines survive (SVG embeds the maps likewise)
    save_figure(fig, out, fmt, dpi=float(np.clip(width_px / 2.2, 110, 250)))
    print(f"plot_maps.py: wrote {out}")


if __name__ == "__main__":
    main()
