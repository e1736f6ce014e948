#!/usr/bin/env python3
"""The cost and the integrity of every run of a sweep, as one CSV (docs/MODEL.md §6.6).

Per run: the integration wall and the contact search's share of it, read from the run file's
/log counters (the project's reader, pipeline/python/crumple), and the stored frames in which layers of the sheet cross
each other, per stage, from tests/bench/diag_intersections (exact CGAL predicates). Wall times are
those of the machine the runs ran on; the counts of searches and steps are exact.

    python3 pipeline/sweeps/run_costs.py --points runs/sweeps/NAME/points.json \
        --diag build/tests/bench/diag_intersections -o docs/studies/NAME/run_costs.csv

Exit 0 with the CSV written, 2 on bad input (a missing run or tool), naming it.
"""
import argparse
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import crumple  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import write_csv  # noqa: E402

LOG_KEYS = ["wall_total", "contact_searches", "contact_search_s", "contact_eval_s",
            "steps_implicit", "steps_explicit"]
STAGES = ["roll", "compress", "release", "unfold"]


def fail(msg):
    print(f"run_costs: {msg}", file=sys.stderr)
    sys.exit(2)


def log_counters(run):
    """The run's /log counters (wall times, searches, steps), named as in LOG_KEYS."""
    try:
        counters = crumple.load_run(run).log_counters
        return {k: float(counters[k]) for k in LOG_KEYS}
    except (OSError, ValueError, KeyError) as e:
        fail(f"{run}: no /log counter {e}" if isinstance(e, KeyError) else f"{run}: {e}")


def crossings(diag, run):
    """{stage: (frames, frames with crossings, largest count)} from diag_intersections."""
    r = subprocess.run([diag, run], capture_output=True, text=True)
    if r.returncode not in (0, 1):
        fail(f"{diag} {run}: exit {r.returncode}: {r.stderr.strip()[:200]}")
    out = {}
    for line in r.stdout.splitlines():
        m = re.search(r"\s(\w+)\s+frames\s+(\d+)\s+with intersections\s+(\d+)\s+largest count (\d+)",
                      line)
        if m:
            out[m.group(1)] = tuple(int(m.group(i)) for i in (2, 3, 4))
    # A run has at least its initial frame: nothing parsed means the tool's output changed, and
    # reading that as "no crossings" would be wrong.
    if not out:
        fail(f"{diag} {run}: no per-stage line understood in its output:\n{r.stdout[:300]}")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", required=True, help="runs/sweeps/NAME/points.json")
    ap.add_argument("--diag", required=True, help="the diag_intersections binary")
    ap.add_argument("-o", "--output", required=True, help="CSV to write")
    a = ap.parse_args()
    try:
        with open(a.points) as f:
            pts = json.load(f)["points"]
    except (OSError, ValueError, KeyError) as e:
        fail(f"{a.points}: {e}")
    if not os.access(a.diag, os.X_OK):
        fail(f"{a.diag}: not an executable (cmake --build build --target diag_intersections)")
    rows = []
    for p in pts:
        run = p["run"]
        if not os.path.isfile(run):
            fail(f"{run}: no such run (make sweep first)")
        row = {"group": p["group"], "seed": p["seed"]}
        for k, v in log_counters(run).items():
            # Seconds to six significant figures: the wall of a shared machine is no finer.
            row[k] = int(v) if k.startswith(("steps", "contact_searches")) else float(f"{v:.6g}")
        row["search_share"] = round(row["contact_search_s"] / row["wall_total"], 3)
        cr = crossings(a.diag, run)
        for s in STAGES:
            frames, bad, worst = cr.get(s, (0, 0, 0))
            row[f"{s}_frames"], row[f"{s}_frames_crossing"], row[f"{s}_most_crossings"] = \
                frames, bad, worst
        rows.append(row)
    write_csv(a.output, rows,
              f"run costs and crossing layers of {a.points} (pipeline/sweeps/run_costs.py)")
    print(f"run_costs: {a.output}: {len(rows)} runs")


if __name__ == "__main__":
    main()
