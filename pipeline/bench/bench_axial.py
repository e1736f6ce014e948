#!/usr/bin/python3
"""bench_axial.py: the speed of the axial-crumpling protocol (issue 32; `make bench-axial`).

Runs crumple-sim on protocols/axial_crumpling.yaml for one cycle,
    crumple-sim PROTOCOL -o OUT.h5 --set protocol.cycles=1 --set mesh.nodes=N --set mesh.seed=S
                --threads T --quiet [--set KEY=VALUE]...
and prints what the run file says about where the time went (docs/FILE_FORMAT.md): the total
wall and peak memory of the process, the wall of every stage (/stage_ends@wall), the steps per
mode, switches and rejections (/log attributes), the split of the total wall into assembly,
contact search, contact response, linear solve, output and the rest, the implicit and explicit
steps of every stage, and the ratio of kinetic to deformation energy e_kinetic / (e_stretch +
e_bend) during each compress stage (median, 90th percentile, maximum over its steps).

With --baseline B the binary B and the main one run alternately on the same configuration
(B, A, B, A, ... --repeats times each), so that a speed-up is timed side by side on a machine
whose speed drifts; each pair gives a ratio of total walls A/B, and their median is the result.
Step counts are exact and repeatable, so a change of them is reported. A baseline built before
the run file carried the stage walls and /log costs shows "-" there.

usage (from the repository root):
    make bench-axial [BENCH_NODES=3000] [BENCH_THREADS=2] [BENCH_SEED=1] [BENCH_BASELINE=OLD]
    /usr/bin/python3 pipeline/bench/bench_axial.py --nodes 3000 --threads 2 [--seed 1]
        [--baseline OLD_CRUMPLE_SIM] [--repeats R] [--set KEY=VALUE]... [--binary CRUMPLE_SIM]
        [--protocol YAML] [--out-dir build/bench-axial] [--json SUMMARY.json]
A baseline binary comes, for example, from a second build of an older revision in a git
worktree. The run files stay in --out-dir (one per run, overwritten by the next bench).
"""
import argparse
import json
import math
import os
import statistics
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_run import check_binary, die, from_root, run_child, tail  # noqa: E402

# The split of the total wall: (key, label). "assembly" is the integrator's wall_assembly less
# the contact response evaluated inside it; "other" is what the others leave (mesh generation,
# step control, plastic update, the step log's energies, stage checks).
SPLIT = [("assembly", "force/Jacobian assembly (w/o contact)"), ("contact_search", "contact search"),
         ("contact_response", "contact response"), ("linear", "linear solve"), ("output", "output"),
         ("other", "other")]


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nodes", type=int, default=3000, help="mesh.nodes (default 3000)")
    ap.add_argument("--threads", type=int, default=2, help="crumple-sim --threads (default 2)")
    ap.add_argument("--seed", type=int, default=1, help="mesh.seed (default 1)")
    ap.add_argument("--binary", default=from_root("build/sim/apps/crumple-sim"), help="crumple-sim to time (A)")
    ap.add_argument("--baseline", help="a second crumple-sim (B), timed alternately with A")
    ap.add_argument("--repeats", type=int, default=1, help="runs of each binary (default 1)")
    ap.add_argument("--protocol", default=from_root("protocols/axial_crumpling.yaml"))
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="passed on to crumple-sim (repeatable), after the bench's own")
    ap.add_argument("--out-dir", default=from_root("build/bench-axial"))
    ap.add_argument("--json", help="write the printed figures to this JSON file")
    a = ap.parse_args()
    if a.repeats < 1:
        die("--repeats must be at least 1")
    return a


# ---- one run ---------------------------------------------------------------------------------

def sim_command(binary, a, out):
    sets = ["protocol.cycles=1", f"mesh.nodes={a.nodes}", f"mesh.seed={a.seed}"] + a.set
    cmd = [binary, a.protocol, "-o", out, "--threads", str(a.threads), "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    return cmd


def run_once(binary, label, k, a):
    """Runs binary once; returns its figures (read from the run file)."""
    stem = os.path.join(a.out_dir, f"{label}{k}_n{a.nodes}_t{a.threads}_s{a.seed}")
    out = stem + ".h5"
    for stale in (out, out + ".tmp", stem + ".xdmf"):
        if os.path.exists(stale):
            os.remove(stale)
    rc, wall, rss = run_child(sim_command(binary, a, out), stem + ".log")
    if rc != 0:
        die(f"{binary} exited with {rc}; its output ({stem}.log) ends:\n{tail(stem + '.log')}", 1)
    f = read_figures(out)
    f.update(binary=binary, label=label, repeat=k, run_file=out, wall_total_s=wall, peak_rss_mib=rss)
    f["split"] = wall_split(f)
    return f


# ---- figures from the run file ---------------------------------------------------------------

def attr(obj, name):
    """An attribute as a Python number, None when absent (older files) or NaN."""
    if name not in obj.attrs:
        return None
    v = obj.attrs[name]
    v = v.item() if hasattr(v, "item") else v
    return None if isinstance(v, float) and math.isnan(v) else v


def read_stages(f, t, mode):
    """Each stage end with its wall and the steps (rows of /log) that ended in the stage."""
    stages, t_prev = [], -math.inf
    for name in sorted(f.get("stage_ends", {})):
        g = f["stage_ends"][name]
        t_end = float(g.attrs["t"])
        rows = (t > t_prev) & (t <= t_end)
        stages.append({"cycle": int(g.attrs["cycle"]), "stage": g.attrs["stage"], "t_end": t_end,
                       "wall_s": attr(g, "wall"), "steps_implicit": int(np.sum(rows & (mode == 0))),
                       "steps_explicit": int(np.sum(rows & (mode == 1))), "rows": rows})
        t_prev = t_end
    return stages


def energy_ratio(log, rows):
    """Median, 90th percentile and maximum of e_kinetic / (e_stretch + e_bend) over the rows."""
    e_def = log["e_stretch"][:] + log["e_bend"][:]
    keep = rows & (e_def > 0)
    r = log["e_kinetic"][:][keep] / e_def[keep]
    if r.size == 0:
        return None
    return {"median": float(np.median(r)), "p90": float(np.percentile(r, 90)), "max": float(r.max()),
            "steps": int(r.size)}


def read_figures(path):
    with h5py.File(path, "r") as f:
        log = f["log"]
        t, mode = log["t"][:], log["mode"][:]
        keys = ["steps_implicit", "steps_explicit", "switches", "wall_total", "wall_assembly", "wall_linear",
                "wall_before_step", "contact_search_s", "contact_eval_s", "contact_searches", "output_s"]
        fig = {k: attr(log, k) for k in keys}
        fig["threads"] = attr(f["meta"], "threads")
        rej = [attr(log, k) for k in ("rejected_error", "rejected_newton", "rejected_not_spd", "rejected_other")]
        fig["rejections"] = None if None in rej else sum(rej)
        stages = read_stages(f, t, mode)
        fig["compress_energy_ratio"] = [dict(cycle=s["cycle"], **(energy_ratio(log, s["rows"]) or {}))
                                        for s in stages if s["stage"] == "compress"]
    for s in stages:
        del s["rows"]
    fig["stages"] = stages
    return fig


def wall_split(f):
    """The total wall in parts (None where the run file lacks the figure); other = the rest.
    A file without the contact costs (an older binary) gives the whole wall_assembly and, for the
    search, the integrator's before-step wall (the contact update); f["split_approx"] says so."""
    ev = f["contact_eval_s"]
    f["split_approx"] = ev is None
    if ev is None:
        assembly, search = f["wall_assembly"], f["wall_before_step"]
    else:
        assembly, search = f["wall_assembly"] - ev, f["contact_search_s"]
    parts = {"assembly": assembly, "contact_search": search, "contact_response": ev,
             "linear": f["wall_linear"], "output": f["output_s"]}
    known = sum(v for v in parts.values() if v is not None)
    parts["other"] = f["wall_total_s"] - known
    return parts


# ---- printing --------------------------------------------------------------------------------

W_LABEL, W_COL = 38, 18


def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def row(label, cells):
    return f"  {label:<{W_LABEL}}" + "".join(f"{c:>{W_COL}}" for c in cells)


def stage_sum(r):
    walls = [s["wall_s"] for s in r["stages"]]
    return None if not walls or None in walls else sum(walls)


def detail_table(runs):
    """The figures of one run per binary, side by side."""
    L = [row("", [r["label"] for r in runs])]
    L.append(row("total wall [s]", [fmt(r["wall_total_s"], ".2f") for r in runs]))
    L.append(row("  in the integrator (wall_total)", [fmt(r["wall_total"], ".2f") for r in runs]))
    L.append(row("  in the stages (sum of their walls)", [fmt(stage_sum(r), ".2f") for r in runs]))
    L.append(row("peak memory [MiB]", [fmt(r["peak_rss_mib"], ".0f") for r in runs]))
    L.append(row("steps implicit / explicit",
                 [f"{fmt(r['steps_implicit'], 'd')} / {fmt(r['steps_explicit'], 'd')}" for r in runs]))
    L.append(row("switches / rejections", [f"{fmt(r['switches'], 'd')} / {fmt(r['rejections'], 'd')}" for r in runs]))
    L.append(row("contact searches", [fmt(r["contact_searches"], "d") for r in runs]))
    L.append("  split of the total wall [s (share)]:")
    for key, name in SPLIT:
        cells = []
        for r in runs:
            v = r["split"][key]
            star = "*" if r["split_approx"] and key in ("assembly", "contact_search") else ""
            cells.append("-" if v is None else f"{v:.2f} ({100 * v / r['wall_total_s']:.1f}%){star}")
        L.append(row("  " + name, cells))
    if any(r["split_approx"] for r in runs):
        L.append("    (*: a run file without /log@contact_eval_s: assembly includes the contact response,")
        L.append("     contact search is the integrator's before-step wall; -: not in that run file)")
    L.append("  by stage: wall [s], steps implicit / explicit:")
    for i in range(max(len(r["stages"]) for r in runs)):
        st = [r["stages"][i] if i < len(r["stages"]) else None for r in runs]
        first = next(s for s in st if s)
        L.append(row(f"  c{first['cycle']} {first['stage']}",
                     ["-" if s is None else f"{fmt(s['wall_s'], '.2f')}  {s['steps_implicit']}/{s['steps_explicit']}"
                      for s in st]))
    L.append("  e_kinetic/(e_stretch+e_bend) in compress:")
    for i in range(max(len(r["compress_energy_ratio"]) for r in runs)):
        er = [r["compress_energy_ratio"][i] if i < len(r["compress_energy_ratio"]) else {} for r in runs]
        cyc = next(e for e in er if e).get("cycle")
        for q in ("median", "p90", "max"):
            L.append(row(f"  c{cyc} {q}", [fmt(e.get(q), ".3g") for e in er]))
    return L


def median_run(runs):
    """The run of median total wall (the lower middle one of an even number)."""
    s = sorted(runs, key=lambda r: r["wall_total_s"])
    return s[(len(s) - 1) // 2]


def steps_line(a_runs, b_runs):
    def steps(r):
        return (r["steps_implicit"], r["steps_explicit"])
    sa, sb = {steps(r) for r in a_runs}, {steps(r) for r in b_runs}
    if len(sa | sb) == 1:
        i, e = sa.pop()
        return f"steps per mode: A and B agree ({i} implicit, {e} explicit)"
    show = lambda s: ", ".join(f"{i}/{e}" for i, e in sorted(s))  # noqa: E731
    return f"steps per mode DIFFER (implicit/explicit): A {show(sa)}; B {show(sb)}"


def main():
    a = parse_args()
    check_binary(a.binary, "--binary")
    if a.baseline:
        check_binary(a.baseline, "--baseline")
    os.makedirs(a.out_dir, exist_ok=True)
    print(f"bench-axial: {a.protocol}, 1 cycle, {a.nodes} nodes, mesh.seed {a.seed}, {a.threads} threads"
          + (f", --set {' '.join(a.set)}" if a.set else ""))
    print(f"  A = {a.binary}" + (f"   B = {a.baseline} (baseline)" if a.baseline else ""))
    order = [("B", a.baseline), ("A", a.binary)] if a.baseline else [("A", a.binary)]
    runs = {"A": [], "B": []}
    for k in range(1, a.repeats + 1):
        for label, binary in order:
            r = run_once(binary, label, k, a)
            runs[label].append(r)
            print(f"  run {label}{k}: {r['wall_total_s']:.2f} s wall", flush=True)
    summary = {"protocol": a.protocol, "nodes": a.nodes, "threads": a.threads, "seed": a.seed, "sets": a.set,
               "binary": a.binary, "baseline": a.baseline, "repeats": a.repeats,
               "runs": runs["A"] + runs["B"]}
    shown = [median_run(runs["A"])] + ([median_run(runs["B"])] if a.baseline else [])
    print("figures" + (" (of the run of median wall of each binary):" if a.repeats > 1 else ":"))
    print("\n".join(detail_table(shown)))
    if a.baseline:
        ratios = [ra["wall_total_s"] / rb["wall_total_s"] for ra, rb in zip(runs["A"], runs["B"])]
        med = statistics.median(ratios)
        print("total wall A/B per pair: " + " ".join(f"{x:.3f}" for x in ratios)
              + f"; median {med:.3f} (A {'faster' if med < 1 else 'slower'}: speed-up B/A {1 / med:.2f}x)")
        print(steps_line(runs["A"], runs["B"]))
        summary.update(ratios_a_over_b=ratios, median_ratio_a_over_b=med)
    if a.json:
        os.makedirs(os.path.dirname(os.path.abspath(a.json)), exist_ok=True)
        with open(a.json, "w") as f:
            json.dump(summary, f, indent=1)
        print(f"summary: {a.json}")


if __name__ == "__main__":
    main()
