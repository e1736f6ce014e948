#!/usr/bin/env python3
"""pipeline/sweeps/run_costs.py on a short real run: the /log counters it reads are those the run
printed, the crossing counts those the diagnostic printed (a stand-in diagnostic reporting a
crossing, so the parse is checked on a nonzero count), and a missing run is an error naming it
with nothing written.

Usage: test_run_costs.py CRUMPLE_SIM DIAG_INTERSECTIONS (run from the repository root)."""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

SCRIPT = "pipeline/sweeps/run_costs.py"


def main():
    sim, real_diag = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "g", "seed1.h5")
        os.makedirs(os.path.dirname(run))
        r = subprocess.run([sim, "protocols/axial_crumpling.yaml", "--threads", "1", "--set",
                            "mesh.nodes=200", "--set", "protocol.cycles=1", "--set",
                            "protocol.t_max=0.6", "-o", run, "--force"],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        m = re.search(r"steps (\d+) implicit \+ (\d+) explicit", r.stderr)
        assert m, r.stderr[-500:]
        implicit, explicit = int(m.group(1)), int(m.group(2))
        # A stand-in for diag_intersections: compress has 2 of 5 frames crossing, at most 7.
        diag = os.path.join(tmp, "diag")
        with open(diag, "w") as f:
            f.write("#!/bin/sh\n"
                    "echo \"$1  compress   frames    5  with intersections    2  largest count 7\"\n"
                    "echo \"$1  roll       frames    3  with intersections    0  largest count 0\"\n"
                    "exit 1\n")
        os.chmod(diag, 0o755)
        points = os.path.join(tmp, "points.json")
        with open(points, "w") as f:
            json.dump({"points": [{"group": "g", "seed": 1, "run": run}]}, f)
        out = os.path.join(tmp, "costs.csv")
        r = subprocess.run([sys.executable, SCRIPT, "--points", points, "--diag", diag, "-o", out],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        with open(out) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        assert len(rows) == 1, rows
        row = rows[0]
        assert int(row["steps_implicit"]) == implicit and int(row["steps_explicit"]) == explicit, row
        assert float(row["wall_total"]) >= float(row["contact_search_s"]) >= 0, row
        assert (row["compress_frames"], row["compress_frames_crossing"],
                row["compress_most_crossings"]) == ("5", "2", "7"), row
        assert (row["roll_frames"], row["roll_frames_crossing"]) == ("3", "0"), row
        assert row["unfold_frames"] == "0", row

        # The real diagnostic on the real run: every stored frame checked, none crossing (a flat
        # sheet rolled for 0.6 s), and the frame counts add up to the run's stored frames.
        r = subprocess.run([sys.executable, SCRIPT, "--points", points, "--diag", real_diag,
                            "-o", out], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        with open(out) as f:
            row = list(csv.DictReader(line for line in f if not line.startswith("#")))[0]
        stages = ("roll", "compress", "release", "unfold")
        assert sum(int(row[f"{s}_frames"]) for s in stages) > 0, row
        assert all(row[f"{s}_frames_crossing"] == "0" for s in stages), row

        # A diagnostic whose output is not understood is an error, not "no crossings".
        with open(diag, "w") as f:
            f.write("#!/bin/sh\necho something else\nexit 0\n")
        r = subprocess.run([sys.executable, SCRIPT, "--points", points, "--diag", diag, "-o",
                            out + ".3"], capture_output=True, text=True)
        assert r.returncode == 2 and "no per-stage line" in r.stderr, (r.returncode, r.stderr)
        assert not os.path.exists(out + ".3")

        # A run that is not there: exit 2, named, no CSV.
        with open(points, "w") as f:
            json.dump({"points": [{"group": "g", "seed": 2, "run": run + ".missing"}]}, f)
        out2 = os.path.join(tmp, "costs2.csv")
        r = subprocess.run([sys.executable, SCRIPT, "--points", points, "--diag", diag, "-o", out2],
                           capture_output=True, text=True)
        assert r.returncode == 2 and "seed1.h5.missing" in r.stderr, (r.returncode, r.stderr)
        assert not os.path.exists(out2) and not os.path.exists(out2 + ".new")
    print("test_run_costs: ok")


if __name__ == "__main__":
    main()
