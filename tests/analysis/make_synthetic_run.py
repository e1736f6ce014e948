#!/usr/bin/python3
"""Writes a synthetic run file (docs/FILE_FORMAT.md layout) to exercise crumple-analyze and the
pipeline scripts without the simulator: a regularly triangulated square sheet whose plastic field
gains, each cycle, a number of random crease segments along mesh-edge lines (x = const,
y = const, y - x = const) proportional to C/(n + n0), so the crease length grows roughly like
C ln(1 + n/n0).

With --stage-ends it also writes /stage_ends (the plastic field at the end of each of the
stages roll, compress, release, unfold of every cycle): each new crease segment of a cycle is
made in one of those stages (mostly in compress), so the last stage end of a cycle equals the
cycle's field. --c0 writes integrator.plastic_c0 into /config (absent otherwise, as in files
whose config does not give it). Every /cycles/NNNN records the compaction D as crumple-sim does
(@compaction), unless --no-compaction-record writes the layout of files from before it was
recorded. The cycle fields do not depend on these flags.

usage: make_synthetic_run.py OUT.h5 [--seed S] [--cycles N] [--k K] [--compaction D]
                             [--c0 C0] [--stage-ends] [--no-compaction-record]
"""
import argparse

import h5py
import numpy as np


def grid_mesh(k, side):
    d = side / k
    idx = lambda i, j: j * (k + 1) + i  # noqa: E731
    pos = np.array([[i * d, j * d, 0.0] for j in range(k + 1) for i in range(k + 1)])
    tris = []
    for j in range(k):
        for i in range(k):
            tris += [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)], [idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]]
    edges, index, opp = [], {}, {}
    for t in tris:
        for a in range(3):
            u, v, w = t[a], t[(a + 1) % 3], t[(a + 2) % 3]
            e = (min(u, v), max(u, v))
            if e not in index:
                index[e] = len(edges)
                edges.append(e)
            opp.setdefault(e, []).append(w)
    hinges, hedge = [], []
    for e, o in opp.items():
        if len(o) == 2:
            hinges.append([e[0], e[1], o[0], o[1]])
            hedge.append(index[e])
    edges = np.array(edges)
    rest = np.linalg.norm(pos[edges[:, 0]] - pos[edges[:, 1]], axis=1)
    boundary = np.array([(i in (0, k) or j in (0, k)) for j in range(k + 1) for i in range(k + 1)], np.uint8)
    return pos, np.array(tris), edges, rest, np.array(hinges), np.array(hedge), boundary


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cycles", type=int, default=5)
    ap.add_argument("--k", type=int, default=48)
    ap.add_argument("--compaction", type=float, default=0.27)
    ap.add_argument("--c0", type=float, default=None, help="integrator.plastic_c0 in /config")
    ap.add_argument("--stage-ends", action="store_true", help="write /stage_ends")
    ap.add_argument("--no-compaction-record", action="store_true",
                    help="no /cycles/NNNN@compaction (a file from before it was recorded)")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    stage_rng = np.random.default_rng(a.seed + 1000)  # keeps the cycle fields flag-independent
    stages = ["roll", "compress", "release", "unfold"]
    stage_share = [0.05, 0.8, 0.1, 0.05]
    side, k = 0.1, a.k
    pos, tris, edges, rest, hinges, hedge, boundary = grid_mesh(k, side)
    # integer grid coordinates of each hinge's edge ends
    ij = np.rint(pos[:, :2] / (side / k)).astype(int)
    e0, e1 = ij[edges[hedge, 0]], ij[edges[hedge, 1]]
    p = rng.normal(0, 0.01, len(hinges))
    with h5py.File(a.out, "w") as f:
        m = f.create_group("meta")
        m.attrs["length_unit_m"] = 1.0
        m.attrs["seed"] = np.uint64(a.seed)
        m.attrs["program_version"] = "synthetic"
        integrator = f"integrator:\n  plastic_c0: {a.c0}\n" if a.c0 is not None else ""
        f["config"] = (f"mesh:\n  shape: square\n  size: {side}\n{integrator}protocol:\n"
                       f"  cycles: {a.cycles}\n  stages:\n    - type: roll\n"
                       f"    - type: compress\n      compaction: {a.compaction}\n"
                       f"    - type: release\n    - type: unfold\n")
        g = f.create_group("mesh")
        g["ref_positions"], g["triangles"] = pos, tris.astype(np.int32)
        g["edges"], g["rest_lengths"] = edges.astype(np.int32), rest
        g["hinges"], g["hinge_edge"] = hinges.astype(np.int32), hedge.astype(np.int32)
        g["boundary"] = boundary
        cg = f.create_group("cycles")
        sg = f.create_group("stage_ends") if a.stage_ends else None
        t = 0.0
        for n in range(1, a.cycles + 1):
            at_stage = [p.copy() for _ in stages]  # p at each stage end of this cycle
            for _ in range(int(round(12 * 2.7 / (n + 2.7)))):
                kind, c = rng.integers(3), rng.integers(1, k)
                lo, hi = np.sort(rng.integers(0, k + 1, 2))
                if kind == 0:    # x = c
                    sel = (e0[:, 0] == c) & (e1[:, 0] == c) & (np.minimum(e0[:, 1], e1[:, 1]) >= lo) & (np.maximum(e0[:, 1], e1[:, 1]) <= hi)
                elif kind == 1:  # y = c
                    sel = (e0[:, 1] == c) & (e1[:, 1] == c) & (np.minimum(e0[:, 0], e1[:, 0]) >= lo) & (np.maximum(e0[:, 0], e1[:, 0]) <= hi)
                else:            # y - x = c - k/2
                    dd = c - k // 2
                    sel = (e0[:, 1] - e0[:, 0] == dd) & (e1[:, 1] - e1[:, 0] == dd) & (e0[:, 0] != e1[:, 0])
                p[sel] = rng.choice([-1, 1]) * rng.uniform(0.3, 1.5)
                made = stage_rng.choice(len(stages), p=stage_share)
                for j in range(made, len(stages)):
                    at_stage[j][sel] = p[sel]
            if sg is not None:
                for j, name in enumerate(stages):
                    t += 0.5
                    g1 = sg.create_group(f"{len(sg):06d}")
                    g1["p"] = at_stage[j]
                    g1.attrs["t"], g1.attrs["cycle"] = t, np.int32(n)
                    g1.attrs["stage"], g1.attrs["stage_index"] = name, np.int32(j)
                    if name == "compress" and not a.no_compaction_record:
                        g1.attrs["compaction"] = a.compaction
            cyc = cg.create_group(f"{n:04d}")
            cyc["p"], cyc["x"] = p, pos
            if not a.no_compaction_record:
                cyc.attrs["compaction"] = a.compaction
    print(f"make_synthetic_run.py: wrote {a.out}")


if __name__ == "__main__":
    main()
