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
again, and says why (the configurations compared as parsed YAML: a key the simulator gained
since makes the point run again). A run file in the run folder comes first: a point with a run
(or a checkpoint) there is run or resumed as usual, its summary ignored. Only a finished run whose
analysis is current is kept (not_current). What needs the run file itself is not served by a
summary: more cycles run a kept point afresh (nothing to extend), and a sweep with `runs_of`
analyses run files again.

usage: kept_runs.py --points runs/sweeps/NAME/points.json --out docs/studies/NAME/runs
       kept_runs.py --unpack docs/studies/NAME/runs/GROUP/seedS.json -o ANALYSIS/stats.json

Exit codes: 0 done, 2 an unreadable file, or nothing to keep.
"""
import argparse
import json
import os
import sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, load_json  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_config import stored_config_is, write_if_changed  # noqa: E402

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
        try:
            s = read_summary(point["kept"])
        except SummaryError as e:
            die(str(e))
        return {int(k): v for k, v in s.get("roll_axis_deg", {}).items()}, s.get("run_wall_s")
    return recorded_roll_axes_and_wall(point["run"])


def not_current(point):
    """Why a point's run and analysis are not a finished pair made as the point now says (None
    when they are). The argument and configuration files are rewritten by every expansion, before
    anything runs: a run older than them, or an analysis older than its run or its options, is
    from before a change (as make would judge it), and is not kept under the new settings."""
    run, stats = point["run"], os.path.join(point["analysis"], "stats.json")
    config = read_text(run + ".config")
    mtime = os.path.getmtime
    if os.path.exists(run + ".tmp"):
        return "a checkpoint is there: the run (or its extension) is not finished"
    if not os.path.isfile(run) or not os.path.isfile(stats):
        return "not run or not analysed yet"
    if config is None:
        return f"no resolved configuration ({run}.config; make sweep writes it)"
    if any(os.path.isfile(f) and mtime(f) > mtime(run) for f in (run + ".args", run + ".config")):
        return "its arguments or configuration changed after it ran (make sweep runs it again)"
    if not stored_config_is(run, config):
        return "the run file does not hold the configuration the point resolves to"
    if any(os.path.isfile(f) and mtime(f) > mtime(stats) for f in (run, point["analysis"] + ".args")):
        return "its analysis is older than the run or its options (make sweep analyses it again)"
    meta = load_json(stats, "run analysis").get("input", {}).get("meta", {})
    if meta.get("seed") not in (None, point["seed"]) or meta.get("status") not in (None, "complete"):
        return f"its analysis is of seed {meta.get('seed')}, status {meta.get('status')}"
    return None


def summary(point):
    """The summary of a point whose run and analysis are current (not_current)."""
    axes, wall = recorded_roll_axes_and_wall(point["run"])
    return {"format": FORMAT,
            "group": point["group"], "seed": point["seed"],
            "args": point["args"], "config": read_text(point["run"] + ".config"),
            "analyze_args": point["analyze_args"],
            "roll_axis_deg": {str(k): v for k, v in sorted(axes.items())},
            "run_wall_s": wall,
            "stats": load_json(os.path.join(point["analysis"], "stats.json"), "run analysis")}


class SummaryError(Exception):
    """A kept summary that is not one (unreadable, or a key missing): the file and key named."""


def read_summary(path):
    """A kept summary file, checked for the keys a sweep reads of it; SummaryError otherwise."""
    try:
        with open(path) as f:
            kept = json.load(f)
    except (OSError, ValueError) as e:
        raise SummaryError(f"{path}: not a readable kept run summary ({e})")
    if not isinstance(kept, dict) or kept.get("format") != FORMAT:
        raise SummaryError(f"{path}: format: not a kept run summary ({FORMAT!r})")
    for key, kind in (("args", list), ("analyze_args", list), ("config", str), ("stats", dict)):
        if not isinstance(kept.get(key), kind):
            raise SummaryError(f"{path}: {key}: missing or not a {kind.__name__}")
    if not isinstance(kept["stats"].get("cycles"), list):
        raise SummaryError(f"{path}: stats.cycles: missing (no run analysis)")
    return kept


def mismatch(kept, point, config):
    """Why a kept summary does not stand for a point (None when it does). `config` is the point's
    resolved configuration, or None where the sweep was expanded without the simulator. The
    configurations are compared as parsed YAML, so a key the simulator gained since the run was
    kept makes the point run again: it may change what the run computes."""
    if kept["args"] != point["args"]:
        return "made with other crumple-sim arguments"
    if config is not None and yaml.safe_load(kept["config"]) != yaml.safe_load(config):
        return "its configuration resolves otherwise (the protocol or a default changed)"
    if kept["analyze_args"] != point["analyze_args"]:
        return "analysed with other crumple-analyze options"
    return None


def find(kept_dir, point, config):
    """(summary, None) where a kept summary stands for the point, (summary, why) where one is
    there but does not, (None, None) where there is none; SummaryError for a file that is not a
    summary (not silently run again: a run may take hours)."""
    path = summary_path(kept_dir, point)
    if not os.path.isfile(path):
        return None, None
    kept = read_summary(path)
    return kept, mismatch(kept, point, config)


def write_out(path, text):
    """write_if_changed (whole or not at all), into a folder made if need be."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    write_if_changed(path, text)


def keep(points_file, out):
    pts = load_json(points_file, "sweep points file")
    if pts.get("runs_of"):
        die(f"{points_file}: a sweep of {pts['runs_of']}'s runs has none of its own to keep")
    if pts.get("seeds") != pts.get("sweep_seeds") or \
            {p["group"] for p in pts["points"]} != set(pts.get("sweep_groups", [])):
        print(f"kept_runs: the last make sweep SWEEP={pts['name']} expanded only some of its seeds "
              "or groups: the runs of that expansion are kept (make sweep without SWEEP_SEEDS and "
              "SWEEP_GROUPS first to keep every finished one)")
    kept, before, left = [], [], {}
    for p in pts["points"]:
        if p.get("kept"):
            before.append(p["name"])  # taken from a summary here: kept already, left as it is
            continue
        why = not_current(p)
        if why:
            left.setdefault(why, []).append(p["name"])
            continue
        path = summary_path(out, p)
        write_out(path, json.dumps(summary(p), indent=1) + "\n")
        kept.append(p["name"])
    if kept:
        print(f"kept_runs: {out}: {len(kept)} runs kept ({', '.join(kept)})")
    if before:
        print(f"kept_runs: {len(before)} runs were taken from their summaries, which stand: "
              f"{', '.join(before)}")
    for why, names in left.items():
        print(f"kept_runs: not kept, {why}: {', '.join(names)}")
    if not kept and not before:
        die(f"{points_file}: no finished, analysed run to keep (make sweep SWEEP={pts['name']} "
            "first)")


def stats_text(kept):
    """The stats.json a kept summary unpacks to."""
    return json.dumps(kept["stats"], indent=2) + "\n"


def unpack(path, out):
    try:
        kept = read_summary(path)
    except SummaryError as e:
        die(str(e))
    write_out(out, stats_text(kept))


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
