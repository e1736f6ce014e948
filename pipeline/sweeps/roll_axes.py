#!/usr/bin/python3
"""Each cycle's roll axis, read back from a run file, beside the growth of P in that cycle
(issue 36: the slow crease growth; docs/studies/roll_side/). Run files record each roll's axis
at the stage's end (/stage_ends/NNNNNN@roll_axis_deg, docs/FILE_FORMAT.md); in files written
before that, it is recovered from the geometry, and for the others the recovered axis is given
beside the recorded one as a check. Rolling about
an in-plane axis a keeps every node's coordinate along a (up to a shift) and bends the other, so
in the frame nearest the end of each roll stage the coordinate x . a is an exact linear function
of the reference r . a along the axis and a curved one across it. The axis is the direction,
searched in 1-degree steps over 0-179, whose coordinates correlate best (Pearson) between the
frame and the reference; it is reported modulo 180 degrees (a and -a are the same roll).

For each cycle n > 1 the table gives the new axis's smallest angle to any axis rolled before
(0: an orientation the sheet has been rolled in already) and the increment P(n) - P(n-1) of the
run's analysis (stats.json). Writes OUT.csv and prints a summary; exit 2 on bad input.

usage: roll_axes.py RUN.h5 [RUN.h5 ...] -o OUT.csv
       (each RUN.h5's analysis is read from RUN.analysis/stats.json, as make sweep writes it)
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, write_csv  # noqa: E402


def axis_of(x, ref):
    """The in-plane direction (degrees, 0-179) along which the frame x keeps the reference ref's
    coordinate: the best Pearson correlation of x . a with ref . a."""
    best, best_r = None, -2.0
    for d in range(180):
        a = np.array([math.cos(math.radians(d)), math.sin(math.radians(d))])
        u, v = x[:, :2] @ a, ref[:, :2] @ a
        if np.std(u) == 0 or np.std(v) == 0:
            continue
        r = float(np.corrcoef(u, v)[0, 1])
        if r > best_r:
            best, best_r = d, r
    return best, best_r


def roll_axes(path):
    """[(cycle, recorded axis_deg or None, inferred axis_deg or None, correlation or None)] of a
    run file, one per roll stage; the geometry is read only where it is there."""
    import h5py
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        die(f"{path}: not a readable run file ({e})")
    with f:
        if "stage_ends" not in f:
            die(f"{path}: no stage ends: not a crumple-sim run file (or one too old to tell)")
        geometry = "frames" in f and "mesh/ref_positions" in f
        ref = np.array(f["mesh/ref_positions"]) if geometry else None
        times = {k: float(f["frames"][k].attrs["t"]) for k in f["frames"]} if geometry else {}
        out = []
        for k in sorted(f["stage_ends"]):
            e = f["stage_ends"][k].attrs
            if e["stage"] != "roll":
                continue
            recorded = float(e["roll_axis_deg"]) if "roll_axis_deg" in e else None
            d = r = None
            if times:
                t = float(e["t"])
                nearest = min(times, key=lambda q: abs(times[q] - t))
                d, r = axis_of(np.array(f["frames"][nearest]["x"]), ref)
            elif recorded is None:
                die(f"{path}: roll stage end {k} records no axis and the file has no frames and "
                    "reference positions to recover it from")
            out.append((int(e["cycle"]), recorded, d, r))
        return out


def angle_between(a, b):
    """Smallest angle between two axes given modulo 180 degrees."""
    d = abs(a - b) % 180
    return min(d, 180 - d)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("runs", nargs="+", help="run files (RUN.h5, analysed into RUN.analysis/)")
    ap.add_argument("-o", "--output", required=True, help="OUT.csv")
    a = ap.parse_args()
    rows = []
    for path in a.runs:
        stats = os.path.splitext(path)[0] + ".analysis/stats.json"
        if not os.path.isfile(stats):
            die(f"{path}: no analysis {stats} (make sweep writes it)")
        with open(stats) as f:
            P = {c["cycle"]: c["perimeter_P"] for c in json.load(f)["cycles"]}
        axes = roll_axes(path)
        seen = []
        for cycle, recorded, inferred, r in axes:
            d = round(recorded, 3) if recorded is not None else inferred
            novelty = min((angle_between(d, s) for s in seen), default=None)
            inc = (P[cycle] - P[cycle - 1] if cycle > 1 and cycle in P and cycle - 1 in P
                   else P.get(cycle))
            rows.append({"run": path, "cycle": cycle, "axis_deg": d,
                         "axis_source": "recorded" if recorded is not None else "inferred",
                         "inferred_axis_deg": inferred,
                         "fit_correlation": None if r is None else round(r, 6),
                         "angle_to_earlier_axes_deg": novelty, "P": P.get(cycle),
                         "P_increment": inc})
            seen.append(d)
    write_csv(a.output, rows)
    later = [r for r in rows if r["angle_to_earlier_axes_deg"] is not None]
    for lo, hi in ((0, 5), (5, 30), (30, 91)):
        sel = [r["P_increment"] for r in later if lo <= r["angle_to_earlier_axes_deg"] < hi]
        if sel:
            print(f"roll_axes.py: new axis {lo}-{hi - 1} degrees from every earlier one: "
                  f"{len(sel)} cycles, mean P increment {sum(sel) / len(sel):.2f} L0 "
                  f"(range {min(sel):.2f} to {max(sel):.2f})")
    print(f"roll_axes.py: {len(rows)} rolls of {len(a.runs)} runs -> {a.output}")


if __name__ == "__main__":
    main()
