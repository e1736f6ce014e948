#!/usr/bin/python3
"""A sweep made in parts on machines that do not share a run folder: each finished run kept in
the repository as a small summary, which a later `make sweep` takes in place of the run.

A run file is binary and large and stays out of the repository, and a run folder does not always
outlive the machine it was made on (a session's scratch disk, a cluster's job directory). A sweep
whose runs take longer in all than one such machine affords is then made in parts: `make
keep-runs SWEEP=NAME` keeps each finished run as docs/studies/NAME/runs/GROUP/seedS.json, and
`make sweep SWEEP=NAME` elsewhere, later, analyses the kept runs from their summaries and runs only
the rest. A summary holds what the sweep's analysis reads of a run (its stats.json, as
crumple-analyze wrote it, with the configuration, seed and program version it records), what
keep_study.py's runs.csv reads of the run file (each roll's axis, the integration wall), and what
the run was made from: its crumple-sim arguments, its configuration as `crumple-sim
--print-config` resolved it (RUN.h5.config) and its crumple-analyze options.

A kept summary stands for a point only when all three are the point's own (expand_sweep.py
checks them): a sweep whose settings, protocol or analysis options changed since runs its points
again, and says why. A run file in the run folder comes first: a point with a run (or a
checkpoint) there is run or resumed as usual, its summary ignored.

usage: kept_runs.py --points runs/sweeps/NAME/points.json --out docs/studies/NAME/runs
       kept_runs.py --unpack docs/studies/NAME/runs/GROUP/seedS.json -o ANALYSIS/stats.json

Exit codes: 0 done, 2 an unreadable file, or nothing to keep.
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, load_json  # noqa: E402

FORMAT = "crumple kept run summary 1"


def summary_path(kept_dir, point):
    """Where a point's run is kept: KEPT_DIR/GROUP/seedS.json."""
    return os.path.join(kept_dir, point["group"], f"seed{point['seed']}.json")


def read_text(path):
    try:
        with open(path) as f:
            return f.read()
    except OSError:
        return None


def recorded_roll_axes_and_wall(run):
    """({cycle: roll axis in degrees} as the run file records it at each roll's end, the run's
    integration wall in s from its /log counters); ({}, None) for what a file lacks."""
    import h5py
    try:
        with h5py.File(run, "r") as f:
            ends = [f["stage_ends"][k].attrs for k in sorted(f.get("stage_ends", {}))]
            axes = {int(e["cycle"]): float(e["roll_axis_deg"]) for e in ends
                    if e["stage"] == "roll" and "roll_axis_deg" in e}
            wall = f["log"].attrs.get("wall_total") if "log" in f else None
            return axes, None if wall is None else float(wall)
    except OSError:
        return {}, None


def rolls_and_wall(point):
    """A point's roll axes and wall: from its kept summary when the sweep took it from one, else
    from its run file."""
    if point.get("kept"):
        s = load_json(point["kept"], "kept run summary")
        return {int(k): v for k, v in s.get("roll_axis_deg", {}).items()}, s.get("run_wall_s")
    return recorded_roll_axes_and_wall(point["run"])


def summary(point):
    """The summary of a finished, analysed point, or None where the run or its analysis is not
    there (or the point was itself taken from a summary: it is kept already)."""
    stats = os.path.join(point["analysis"], "stats.json")
    if point.get("kept") or not os.path.isfile(point["run"]) or not os.path.isfile(stats):
        return None
    axes, wall = recorded_roll_axes_and_wall(point["run"])
    return {"format": FORMAT,
            "group": point["group"], "seed": point["seed"],
            "args": point["args"], "config": read_text(point["run"] + ".config"),
            "analyze_args": point["analyze_args"],
            "roll_axis_deg": {str(k): v for k, v in sorted(axes.items())},
            "run_wall_s": wall,
            "stats": load_json(stats, "run analysis")}


def mismatch(kept, point, config):
    """Why a kept summary does not stand for a point (None when it does). `config` is the point's
    resolved configuration, or None where the sweep was expanded without the simulator."""
    if kept.get("format") != FORMAT:
        return f"not a kept run summary of this format ({FORMAT})"
    if kept.get("args") != point["args"]:
        return "made with other crumple-sim arguments"
    if config is not None and kept.get("config") not in (None, config):
        return "its configuration resolves otherwise (the protocol or a default changed)"
    if kept.get("analyze_args") != point["analyze_args"]:
        return "analysed with other crumple-analyze options"
    if not isinstance(kept.get("stats"), dict) or "cycles" not in kept["stats"]:
        return "holds no run analysis"
    return None


def find(kept_dir, point, config):
    """(path, None) where a kept summary stands for the point, (path, why) where one is there
    but does not, (None, None) where there is none."""
    path = summary_path(kept_dir, point)
    if not os.path.isfile(path):
        return None, None
    try:
        with open(path) as f:
            kept = json.load(f)
    except (OSError, ValueError) as e:
        return path, f"unreadable ({e})"
    return path, mismatch(kept, point, config)


def write_atomic(path, text):
    """Writes the whole file or, on failure, leaves what was there."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def keep(points_file, out):
    pts = load_json(points_file, "sweep points file")
    if pts.get("runs_of"):
        die(f"{points_file}: a sweep of {pts['runs_of']}'s runs has none of its own to keep")
    kept, missing = [], []
    for p in pts["points"]:
        s = summary(p)
        if s is None:
            if not p.get("kept"):
                missing.append(p["name"])
            continue
        path = summary_path(out, p)
        text = json.dumps(s, indent=1) + "\n"
        if read_text(path) != text:
            write_atomic(path, text)
        kept.append(p["name"])
    if not kept:
        die(f"{points_file}: no finished, analysed run to keep (make sweep SWEEP={pts['name']} "
            "first)")
    print(f"kept_runs: {out}: {len(kept)} runs kept ({', '.join(kept)})")
    if missing:
        print(f"kept_runs: not yet run or analysed: {', '.join(missing)}")


def unpack(path, out):
    s = load_json(path, "kept run summary")
    if s.get("format") != FORMAT or not isinstance(s.get("stats"), dict):
        die(f"{path}: not a kept run summary ({FORMAT})")
    write_atomic(out, json.dumps(s["stats"], indent=2) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", help="runs/sweeps/NAME/points.json: keep its finished runs")
    ap.add_argument("--out", help="docs/studies/NAME/runs")
    ap.add_argument("--unpack", metavar="SUMMARY", help="a kept summary: write its stats.json")
    ap.add_argument("-o", dest="stats", help="the stats.json --unpack writes")
    a = ap.parse_args()
    if a.unpack:
        if not a.stats:
            die("--unpack needs -o ANALYSIS/stats.json")
        unpack(a.unpack, a.stats)
    elif a.points and a.out:
        keep(a.points, a.out)
    else:
        die("give --points and --out, or --unpack and -o")


if __name__ == "__main__":
    main()
