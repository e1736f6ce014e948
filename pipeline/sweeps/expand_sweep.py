#!/usr/bin/env python3
"""Expands a sweep file (pipeline/sweeps/NAME.yaml; pipeline/sweeps/README.md) into its points.

A sweep names a protocol, the preset it starts from, fixed settings on top of the preset, a
grid of config or stage keys and the seeds. Every combination of grid values and seed is one
point: one run of crumple-sim with the preset's --set arguments, then the sweep's fixed ones,
then the point's own (the last --set of a key wins). Points with the same grid values and
different seeds form a group, whose runs make one ensemble.

Writes into OUT_DIR (runs/sweeps/NAME):
  points.json   the points: name, group, seed, run file, analysis folder, crumple-sim arguments
  points.mk     the same as make rules (included by pipeline/sweep.mk): one file target per run,
                per analysis, per group ensemble
  PATH.args     per run, its arguments; rewritten only when they change, so a point whose
                arguments changed is run again and the others are not
  PATH.config   (with --sim) per run, its configuration as `crumple-sim --print-config` resolves
                it; rewritten only when it changes, and the run depends on it rather than on the
                protocol file, so a protocol edit that the sweep overrides redoes nothing
With --sim, each point's configuration is first resolved with `crumple-sim --print-config`, so
a mistyped key fails here, naming the sweep file's line, rather than in every run.

With --kept DIR (make sweep passes docs/studies/NAME/runs), a point that has neither a run file
nor a checkpoint in the run folder and whose run is kept in DIR as a summary (kept_runs.py: a sweep
made in parts on machines that do not share a run folder) is analysed from that summary instead of
being run, when the summary was made with the point's own arguments, resolved configuration and
analysis options; otherwise it is run, and the reason is printed.

A sweep with `runs_of: OTHER` makes no runs of its own: its points are the runs of the sweep
OTHER.yaml beside it (in OTHER's run folder, made by the same rules), analysed again with its own
`analyze` options into its own folder, so an analysis choice is studied on runs already made.

Exit codes: 0 done, 2 bad sweep file (nothing written).
"""
import argparse
import itertools
import json
import os
import re
import shlex
import subprocess
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_config import update as update_run_config, write_if_changed  # noqa: E402
import kept_runs  # noqa: E402

KEYS = {"description", "preset", "protocol", "set", "grid", "seeds", "threads", "collapse",
        "convergence", "history", "analyze", "runs_of"}
# What a sweep of another's runs may state itself; the rest is the other sweep's.
RUNS_OF_KEYS = {"description", "runs_of", "analyze"}
REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


class SweepError(Exception):
    pass


def fail(path, node, key, what):
    line = f":{node.start_mark.line + 1}" if node is not None else ""
    raise SweepError(f"{path}{line}: {key}: {what}")


def mapping(node):
    """A YAML mapping node as {key: (key node, value node)}."""
    return {k.value: (k, v) for k, v in node.value}


def scalar_text(path, node, key):
    if not isinstance(node, yaml.ScalarNode) or node.value == "":
        fail(path, node, key, "expected a value")
    return node.value


def read_preset(path):
    """PRESET_SEEDS, PRESET_SETS and PRESET_THREADS of a preset file (pipeline/presets/NAME.mk), which holds only
    `NAME := value` lines and comments, so that a sweep and `make reproduce` start from the same
    settings."""
    values = {}
    with open(path) as f:
        for no, line in enumerate(f, 1):
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            m = re.fullmatch(r"([A-Z_]+)\s*:=\s*(.*)", s)
            if not m or "$" in m.group(2):
                raise SweepError(f"{path}:{no}: a preset holds only `NAME := value` lines")
            values[m.group(1)] = m.group(2)
    threads = values.get("PRESET_THREADS", "1")
    if not re.fullmatch(r"[1-9][0-9]*", threads):
        raise SweepError(f"{path}: PRESET_THREADS: {threads!r} is not a thread count")
    return (values.get("PRESET_SEEDS", "").split(), shlex.split(values.get("PRESET_SETS", "")),
            int(threads))


def grid_value(path, node, key):
    """A grid value as --set takes it: a scalar, or a flat list written as YAML's [a,b,c] (a
    stage parameter that takes one value per cycle, such as compress.compaction)."""
    if isinstance(node, yaml.SequenceNode):
        if not node.value or not all(isinstance(x, yaml.ScalarNode) and x.value for x in node.value):
            fail(path, node, key, "a list value must be a non-empty list of plain values")
        return "[" + ",".join(x.value for x in node.value) + "]"
    return scalar_text(path, node, key)


def value_name(v):
    """A grid value as it appears in a folder name ([0.6,0.27] as 0.6-0.27)."""
    if v.startswith("[") and v.endswith("]"):
        v = "-".join(x.strip() for x in v[1:-1].split(","))
    return re.sub(r"[^A-Za-z0-9.+-]", "_", v)


def load(path):
    try:
        with open(path) as f:
            root = yaml.compose(f)
    except FileNotFoundError:
        raise SweepError(f"{path}: no such sweep file")
    except yaml.YAMLError as e:
        raise SweepError(f"{path}: not valid YAML: {e}")
    if not isinstance(root, yaml.MappingNode):
        raise SweepError(f"{path}: a sweep file is a mapping (protocol, preset, grid, seeds, ...)")
    top = mapping(root)
    for k, (kn, _) in top.items():
        if k not in KEYS:
            fail(path, kn, k, f"unknown key (known: {', '.join(sorted(KEYS))})")
    if "runs_of" in top:
        return load_runs_of(path, top)
    for k in ("protocol", "preset", "grid"):
        if k not in top:
            raise SweepError(f"{path}: {k}: missing")
    sweep = {"file": path, "name": os.path.splitext(os.path.basename(path))[0]}
    sweep["description"] = top["description"][1].value if "description" in top else ""
    pn = top["protocol"][1]
    sweep["protocol"] = scalar_text(path, pn, "protocol")
    if not os.path.isfile(os.path.join(REPO, sweep["protocol"])):
        fail(path, pn, "protocol", f"no such file {sweep['protocol']}")
    prn = top["preset"][1]
    sweep["preset"] = scalar_text(path, prn, "preset")
    preset_file = os.path.join("pipeline", "presets", sweep["preset"] + ".mk")
    if not os.path.isfile(os.path.join(REPO, preset_file)):
        known = sorted(f[:-3] for f in os.listdir(os.path.join(REPO, "pipeline", "presets")))
        fail(path, prn, "preset", f"no preset {sweep['preset']!r} (known: {', '.join(known)})")
    sweep["preset_file"] = preset_file
    preset_seeds, sweep["preset_sets"], preset_threads = read_preset(os.path.join(REPO, preset_file))

    fixed = []
    if "set" in top:
        sn = top["set"][1]
        if not isinstance(sn, yaml.MappingNode):
            fail(path, sn, "set", "expected a mapping of key: value")
        for k, (kn, vn) in mapping(sn).items():
            fixed.append((k, scalar_text(path, vn, f"set.{k}")))
    sweep["set"] = fixed

    gn = top["grid"][1]
    if not isinstance(gn, yaml.MappingNode) or not gn.value:
        fail(path, gn, "grid", "expected a mapping of key: [values]")
    grid = []
    for k, (kn, vn) in mapping(gn).items():
        if not isinstance(vn, yaml.SequenceNode) or not vn.value:
            fail(path, vn, f"grid.{k}", "expected a non-empty list of values")
        values = [grid_value(path, x, f"grid.{k}") for x in vn.value]
        if len(set(values)) != len(values):
            fail(path, vn, f"grid.{k}", "a value appears twice")
        grid.append({"key": k, "values": values, "line": kn.start_mark.line + 1})
    sweep["grid"] = grid

    if "seeds" in top:
        sdn = top["seeds"][1]
        if not isinstance(sdn, yaml.SequenceNode) or not sdn.value:
            fail(path, sdn, "seeds", "expected a non-empty list of seeds")
        seeds = [scalar_text(path, x, "seeds") for x in sdn.value]
    else:
        seeds = preset_seeds
    for s in seeds:
        if not re.fullmatch(r"[0-9]+", s):
            fail(path, top.get("seeds", (None, None))[1], "seeds", f"{s!r} is not a seed (0, 1, 2, ...)")
    if len(set(seeds)) != len(seeds):
        fail(path, top["seeds"][1], "seeds", "a seed appears twice")
    sweep["seeds"] = seeds
    sweep["threads"] = preset_threads
    if "threads" in top:
        tn = top["threads"][1]
        t = scalar_text(path, tn, "threads")
        if not re.fullmatch(r"[1-9][0-9]*", t):
            fail(path, tn, "threads", f"{t!r} is not a thread count")
        sweep["threads"] = int(t)
    # The collapse needs one compaction per group: a grid of constant compaction ratios.
    sweep["collapse"] = "history" not in top and any(
        g["key"].endswith(".compaction") and not any(v.startswith("[") for v in g["values"])
        for g in grid)
    if "collapse" in top:
        cn = top["collapse"][1]
        c = scalar_text(path, cn, "collapse")
        if c not in ("true", "false"):
            fail(path, cn, "collapse", "expected true or false")
        sweep["collapse"] = c == "true"
    # A ladder in resolution alone gets the convergence table (convergence.py).
    sweep["convergence"] = [g["key"] for g in grid] == ["mesh.nodes"]
    if "convergence" in top:
        vn = top["convergence"][1]
        v = scalar_text(path, vn, "convergence")
        if v not in ("true", "false"):
            fail(path, vn, "convergence", "expected true or false")
        if v == "true" and [g["key"] for g in grid] != ["mesh.nodes"]:
            fail(path, vn, "convergence", "a convergence ladder varies mesh.nodes alone in its grid")
        sweep["convergence"] = v == "true"
    sweep["runs_of"] = None
    sweep["history"] = None
    if "history" in top:
        hn = top["history"][1]
        h = scalar_text(path, hn, "history")
        try:
            sweep["history"] = float(h)
        except ValueError:
            sweep["history"] = None
        if sweep["history"] is None or not 0 < sweep["history"] < 1:
            fail(path, hn, "history", f"{h!r}: the test compaction, a number in (0, 1)")
    # Extra crumple-analyze arguments for every run (e.g. the ladder's --px-per-edge).
    sweep["analyze"] = analyze_options(path, top) if "analyze" in top else []
    return sweep


def analyze_options(path, top):
    an = top["analyze"][1]
    text = scalar_text(path, an, "analyze")
    try:
        options = shlex.split(text)
    except ValueError as e:
        fail(path, an, "analyze", f"{text!r}: not a list of arguments ({e})")
    if any(a in ("-o", "--output") or not a.startswith("-") and not re.fullmatch(r"[-+.0-9eE]+", a)
           for a in options):
        fail(path, an, "analyze", f"{text!r}: crumple-analyze options only (no output or "
             "input paths)")
    return options


def load_runs_of(path, top):
    """A sweep of another sweep's runs: that sweep's points, this sweep's name and analysis."""
    for k, (kn, _) in top.items():
        if k not in RUNS_OF_KEYS:
            fail(path, kn, k, "comes from the sweep named by runs_of (a sweep of another's runs "
                 f"states only {', '.join(sorted(RUNS_OF_KEYS))})")
    rn = top["runs_of"][1]
    other = scalar_text(path, rn, "runs_of")
    other_path = os.path.join(os.path.dirname(path), other + ".yaml")
    if not re.fullmatch(r"[A-Za-z0-9_.-]+", other) or not os.path.isfile(other_path):
        fail(path, rn, "runs_of", f"no sweep {other!r} beside this file ({other_path})")
    if other == os.path.splitext(os.path.basename(path))[0]:
        fail(path, rn, "runs_of", "names this sweep itself")
    sweep = load(other_path)
    if sweep["runs_of"]:
        fail(path, rn, "runs_of", f"{other} is itself a sweep of {sweep['runs_of']}'s runs: name "
             "that one")
    sweep["runs_of"] = other
    sweep["file"] = path
    sweep["name"] = os.path.splitext(os.path.basename(path))[0]
    if "description" in top:
        sweep["description"] = top["description"][1].value
    if "analyze" in top:
        sweep["analyze"] = analyze_options(path, top)
    return sweep


def points(sweep, out_dir):
    """Every point of the grid and seeds, in order: grid values vary slowest, seeds fastest.
    The runs of a sweep of another's runs are in the other's folder beside OUT_DIR."""
    keys = [g["key"] for g in sweep["grid"]]
    runs_dir = os.path.join(os.path.dirname(os.path.normpath(out_dir)), sweep["runs_of"]) \
        if sweep["runs_of"] else out_dir
    base = [a for k, v in sweep["set"] for a in ("--set", f"{k}={v}")]
    out = []
    for combo in itertools.product(*(g["values"] for g in sweep["grid"])):
        group = "_".join(f"{k.split('.')[-1]}-{value_name(v)}" for k, v in zip(keys, combo))
        own = [a for k, v in zip(keys, combo) for a in ("--set", f"{k}={v}")]
        for seed in sweep["seeds"]:
            run = os.path.join(runs_dir, group, f"seed{seed}.h5")
            out.append({"name": f"{group}/seed{seed}", "group": group, "seed": int(seed),
                        "values": dict(zip(keys, combo)), "run": run,
                        "analysis": os.path.join(out_dir, group, f"seed{seed}.analysis"),
                        "analyze_args": list(sweep["analyze"]),
                        "args": [sweep["protocol"], "--seed", seed, "--threads",
                                 str(sweep["threads"])] + sweep["preset_sets"] + base + own})
    return out


def resolve_with_sim(sweep, pts, sim):
    """Each point's configuration through `crumple-sim --print-config` (keys, ranges, stages):
    {run: the resolved configuration}, or SweepError naming the group that is not valid."""
    resolved = {}
    for p in pts:
        r = subprocess.run([sim, "--print-config"] + p["args"], cwd=REPO, capture_output=True,
                           text=True)
        if r.returncode != 0:
            lines = ", ".join(f"line {g['line']}" for g in sweep["grid"])
            raise SweepError(f"{sweep['file']}: point {p['group']} ({lines} of the grid; the "
                             f"preset's and the sweep's set:) is not a valid configuration:\n"
                             f"{r.stderr.strip()}")
        resolved[p["run"]] = r.stdout
    return resolved


def take_kept_runs(pts, kept_dir, resolved):
    """Marks each point that has no run or checkpoint here and whose run is kept in kept_dir, made
    as the point says (kept_runs.py), with p["kept"] = its summary; says which and why not.
    Returns {stats.json path: its text} for the analyses to write once the whole sweep is read
    (so that a bad summary further on leaves nothing written)."""
    taken, analyses = [], {}
    for p in pts:
        if os.path.exists(p["run"]) or os.path.exists(p["run"] + ".tmp"):
            continue
        try:
            kept, why = kept_runs.find(kept_dir, p, resolved.get(p["run"]))
        except kept_runs.SummaryError as e:
            raise SweepError(str(e))
        if kept is None:
            continue
        path = kept_runs.summary_path(kept_dir, p)
        if why:
            print(f"expand_sweep: {path}: not taken for {p['name']}, which runs: {why}")
            continue
        p["kept"] = path
        taken.append(p["name"])
        # Written at expansion, over whatever an earlier analysis left here (which make would
        # take as newer than the summary); the make rule only restores it.
        analyses[os.path.join(p["analysis"], "stats.json")] = kept_runs.stats_text(kept)
    if taken:
        print(f"expand_sweep: {len(taken)} runs analysed from their summaries in {kept_dir} "
              f"(not run here): {', '.join(taken)}")
    return analyses


def members_file(ensemble):
    """The file beside a group's ENSEMBLE.json that lists the analyses it is made of."""
    return ensemble[: -len(".json")] + ".members"


def make_rules(sweep, pts, out_dir, results, resolved):
    q = shlex.quote
    lines = [f"# Generated by pipeline/sweeps/expand_sweep.py from {sweep['file']}; do not edit.",
             f"SWEEP_PRESET := {sweep['preset']}",
             f"SWEEP_PROTOCOL := {sweep['protocol']}",
             f"SWEEP_COLLAPSE := {'yes' if sweep['collapse'] else ''}",
             f"SWEEP_HISTORY := {sweep['history'] if sweep['history'] is not None else ''}",
             f"SWEEP_CONVERGENCE := {'yes' if sweep['convergence'] else ''}",
             "PYTHON ?= /usr/bin/python3",
             f"SWEEP_RUNS := {' '.join(p['run'] for p in pts if not p.get('kept'))}",
             f"SWEEP_STATS := {' '.join(p['analysis'] + '/stats.json' for p in pts)}"]
    groups = []
    for p in pts:
        if p["group"] not in groups:
            groups.append(p["group"])
    ens = [f"{results}/groups/{g}/ensemble.json" for g in groups]
    lines.append(f"SWEEP_ENSEMBLES := {' '.join(ens)}")
    lines.append("")
    for p in pts:
        if p.get("kept"):
            # No run here: the analysis is the kept summary's (kept_runs.py).
            lines += [f"{p['analysis']}/stats.json: {p['kept']}",
                      f"\t$(PYTHON) pipeline/sweeps/kept_runs.py --unpack $< -o $@", ""]
            continue
        args = " ".join(q(a) for a in p["args"])
        # A run depends on what it resolves to (RUN.h5.config), not on the protocol file's date:
        # an edit of the protocol that a sweep's settings override leaves its runs standing.
        # Without the simulator to resolve it, on the protocol file.
        config = f"{p['run']}.config" if p["run"] in resolved else sweep["protocol"]
        # A resumed run appends to its log: the earlier pieces' lines (their walls, a stop or a
        # failure) stay with the run. A finished run made again (its arguments changed) is first
        # offered to --extend, which takes it only when the change is more cycles and nothing
        # else (exit 2 otherwise, the file untouched): then it is run afresh. Any other failure
        # of the extension (a numerical one, a stop) keeps its checkpoint for --resume.
        # (In the shell, not make's $(if): an argument may hold a comma.)
        sim = f"$(SIM) {args} -o $@"
        how = (f"if [ -e $@.tmp ]; then {sim} --resume >> $@.log 2>&1; "
               f"elif [ -e $@ ]; then {sim} --extend >> $@.log 2>&1 "
               f"|| {{ test $$? = 2 && {sim} --force > $@.log 2>&1; }}; "
               f"else {sim} --force > $@.log 2>&1; fi")
        lines += [f"{p['run']}: {p['run']}.args {config} | $(SIM)",
                  f"\t{how} "
                  f"|| {{ echo \"run failed: $@ (see $@.log):\"; tail -n 5 $@.log; exit 1; }}",
                  f"{p['analysis']}/stats.json: {p['run']} {p['analysis']}.args | $(ANALYZE)",
                  f"\t$(ANALYZE) $< -o {p['analysis']} "
                  + "".join(q(x) + " " for x in p["analyze_args"]) + f"> {p['analysis']}.log",
                  ""]
    for g, e in zip(groups, ens):
        members = [p["analysis"] for p in pts if p["group"] == g]
        # The member list (members_file) changes when the seeds do: an ensemble of some seeds,
        # newer than the analyses of the others, is made again when they join.
        lines += [f"{e}: {' '.join(m + '/stats.json' for m in members)} {members_file(e)} "
                  "| $(ANALYZE)",
                  f"\t@mkdir -p $(@D)",
                  f"\t$(ANALYZE) ensemble -o $@ {' '.join(members)} > $@.log",
                  ""]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("sweep", help="sweep file, e.g. pipeline/sweeps/compaction.yaml")
    ap.add_argument("--out-dir", required=True, help="folder of the runs, e.g. runs/sweeps/NAME")
    ap.add_argument("--results", required=True, help="folder of the report, e.g. results/NAME")
    ap.add_argument("--sim", help="crumple-sim, to check each group's configuration")
    ap.add_argument("--seeds", nargs="+", metavar="SEED",
                    help="only these of the sweep's seeds (part of a sweep first; the rest later "
                         "reuses the finished runs; the report names the seeds it used)")
    ap.add_argument("--groups", nargs="+", metavar="GROUP",
                    help="only these of the sweep's groups (grid points, named as in its run "
                         "folders, e.g. compaction-0.27); the report names the groups left out")
    ap.add_argument("--kept", metavar="DIR",
                    help="kept run summaries (docs/studies/NAME/runs): a point with no run here "
                         "whose run is kept there, made as the point says, is analysed from it")
    a = ap.parse_args()
    try:
        sweep = load(a.sweep)
        sweep["sweep_seeds"] = list(sweep["seeds"])
        if a.seeds:
            unknown = [s for s in a.seeds if s not in sweep["seeds"]]
            if unknown:
                raise SweepError(f"{a.sweep}: seeds: --seeds {' '.join(unknown)}: not among the "
                                 f"sweep's seeds ({', '.join(sweep['seeds'])})")
            sweep["seeds"] = [s for s in sweep["seeds"] if s in a.seeds]
        pts = points(sweep, a.out_dir)
        sweep["sweep_groups"] = list(dict.fromkeys(p["group"] for p in pts))
        if a.groups:
            unknown = [g for g in a.groups if g not in sweep["sweep_groups"]]
            if unknown:
                raise SweepError(f"{a.sweep}: grid: --groups {' '.join(unknown)}: not among the "
                                 f"sweep's groups ({', '.join(sweep['sweep_groups'])})")
            pts = [p for p in pts if p["group"] in a.groups]
        resolved = resolve_with_sim(sweep, pts, a.sim) if a.sim else {}
        kept_analyses = {}
        if a.kept and os.path.isdir(a.kept):
            if sweep["runs_of"]:
                print(f"expand_sweep: {a.kept}: not used by a sweep of {sweep['runs_of']}'s runs, "
                      "which analyses the run files again")
            else:
                kept_analyses = take_kept_runs(pts, a.kept, resolved)
    except SweepError as e:
        print(f"expand_sweep: {e}", file=sys.stderr)
        return 2
    os.makedirs(a.out_dir, exist_ok=True)
    for p in pts:
        os.makedirs(os.path.dirname(p["run"]), exist_ok=True)
        os.makedirs(os.path.dirname(p["analysis"]), exist_ok=True)
        # For a sweep of another's runs this is the other's argument file, written the same.
        write_if_changed(p["run"] + ".args", " ".join(shlex.quote(x) for x in p["args"]) + "\n")
        if p["run"] in resolved:
            update_run_config(p["run"], resolved[p["run"]])
        # A changed analysis argument redoes the analysis, not the run.
        write_if_changed(p["analysis"] + ".args",
                         " ".join(shlex.quote(x) for x in p["analyze_args"]) + "\n")
    for path, text in kept_analyses.items():
        kept_runs.write_out(path, text)
    doc = {k: sweep[k] for k in ("name", "file", "description", "preset", "protocol", "seeds",
                                 "sweep_seeds", "sweep_groups", "threads", "collapse", "convergence",
                                 "history", "analyze", "runs_of")}
    doc["set"] = [{"key": k, "value": v} for k, v in sweep["set"]]
    doc["grid"] = [{"key": g["key"], "values": g["values"]} for g in sweep["grid"]]
    doc["preset_sets"] = sweep["preset_sets"]
    doc["points"] = pts
    for g in doc["sweep_groups"]:
        members = [p["analysis"] for p in pts if p["group"] == g]
        if members:
            path = members_file(os.path.join(a.results, "groups", g, "ensemble.json"))
            os.makedirs(os.path.dirname(path), exist_ok=True)
            write_if_changed(path, "\n".join(members) + "\n")
    write_if_changed(os.path.join(a.out_dir, "points.json"), json.dumps(doc, indent=2) + "\n")
    write_if_changed(os.path.join(a.out_dir, "points.mk"), make_rules(sweep, pts, a.out_dir, a.results,
                                                                       resolved))
    print(f"expand_sweep: {sweep['name']}: {len(pts)} runs in "
          f"{len({p['group'] for p in pts})} groups -> {a.out_dir}/points.mk")
    return 0


if __name__ == "__main__":
    sys.exit(main())
