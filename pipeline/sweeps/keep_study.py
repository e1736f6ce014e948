#!/usr/bin/python3
"""Keeps a sweep's result in the repository without its runs: from results/NAME (make sweep) to
docs/studies/NAME/, the report and its figures, the fits (collapse.json, history.json, convergence.json,
.csv and convergence_paired.csv, as the sweep made them; a yield calibration's calibration.json, .csv and CALIBRATION.md;
make predictions' PREDICTIONS.md and predictions.json; compare_groups.py's COMPARISON.md and
.json, and any COMPARISON_WHAT.md and .json beside them), and groups.csv, each group's per-cycle
ensemble table (mean, s.d. and s.e.m. over seeds of the crease lengths, P, facet counts,
single-triangle fraction, a_fit, a_univ and the fit above the resolution floor, and the KS
tests' counts), and runs.csv, the same statistics run by run and cycle with each cycle's roll
axis and its smallest angle to the axes rolled before (seed-paired comparisons need the seeds, not
only their mean; roll_axes.py) and the run's integration wall (so that the costs the docs quote
are in a kept file). The run files stay out (they are binary and large); `make sweep SWEEP=NAME` makes them again, and
`plot_sweep.py --results docs/studies/NAME --collapse-only` redraws the collapse from the JSON.

A fit over a subset of the groups (make predictions PREDICT_GROUPS=...) that the docs quote beside
the study's own is kept with --fit-as TAG: its collapse.json, predictions.json and PREDICTIONS.md
become collapse_TAG.json, predictions_TAG.json and PREDICTIONS_TAG.md, and nothing else in the kept
study is touched (so the whole-sweep fit kept before stays).

usage: keep_study.py --points runs/sweeps/NAME/points.json --results results/NAME --out docs/studies/NAME
       keep_study.py ... --fit-as 0.27-0.63
"""
import argparse
import csv
import glob
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, load_ensemble, load_json, sweep_groups, write_csv  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from kept_runs import rolls_and_wall  # noqa: E402
from roll_axes import angle_between  # noqa: E402

QUANTITIES = ("perimeter_P", "crease_length_L0", "new_crease_length_L0", "n_facets",
              "single_triangle_fraction", "a_fit", "dangling_fraction", "plastic_rotation_L0",
              "creased_rotation_share", "creased_hinge_share", "a_univ",
              "n_facets_above_floor", "a_fit_above_floor", "a_univ_above_floor")
# Counts per group and cycle: runs tested and rejected by the KS tests of the whole-sample law and
# of the law cut at the resolution floor, and runs whose fit above the floor measured a shape.
COUNTS = ("ks_n_tested", "ks_n_rejected", "ks_above_floor_n_tested", "ks_above_floor_n_rejected",
          "a_fit_above_floor_n")
# The fits above the floor that stopped on each edge of their search (FitEdge).
EDGES = ("a_min", "a_max", "theta")


# Run by run: the statistics a seed-paired comparison takes.
RUN_QUANTITIES = ("perimeter_P", "crease_length_L0", "new_crease_length_L0", "n_facets",
                  "single_triangle_fraction", "a_fit", "dangling_fraction", "creased_hinge_share")


def write_runs_table(pts, path):
    """runs.csv: one row per run and cycle of the points whose analysis is there; False if none."""
    rows = []
    for p in pts["points"]:
        stats = os.path.join(p["analysis"], "stats.json")
        if not os.path.isfile(stats):
            continue
        axes, wall = rolls_and_wall(p)  # from the run file, or the summary it was kept as
        earlier = []
        for c in load_json(stats, "run analysis")["cycles"]:
            axis = axes.get(c["cycle"])
            novelty = (min(angle_between(axis, e) for e in earlier)
                       if axis is not None and earlier else None)
            if axis is not None:
                earlier.append(axis)
            rows.append({"group": p["group"], "seed": p["seed"], "cycle": c["cycle"],
                         "compaction": c.get("compaction"),
                         **{q: c.get(q) for q in RUN_QUANTITIES},
                         "roll_axis_deg": None if axis is None else round(axis, 3),
                         "novelty_deg": None if novelty is None else round(novelty, 3),
                         "run_wall_s": None if wall is None else round(wall, 1)})
    if not rows:
        return False
    write_csv(path, rows, f"sweep {pts['name']} ({pts['file']}): per run and cycle; roll_axis_deg "
              "as recorded at the roll's end, novelty_deg its smallest angle to the cycle's "
              "earlier axes; run_wall_s the whole run's integration wall (its /log wall_total, "
              "the same on each of its rows) on the machine and load it ran with")
    return True


# The files a fit writes into the sweep's results (plot_sweep.py's collapse, predictions.py's
# table): kept as they are by a whole keep, renamed by --fit-as.
FIT_FILES = ("collapse.json", "predictions.json", "PREDICTIONS.md")


def keep_fit_as(results, out, tag):
    """Copies the fit files of results/ to out/ as NAME_TAG.ext; the list of names written."""
    if not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9._-]*", tag):
        die(f"--fit-as {tag!r}: a tag of letters, digits, '.', '_' and '-' (it goes into file names)")
    found = [f for f in FIT_FILES if os.path.isfile(os.path.join(results, f))]
    if not found:
        die(f"{results}: no fit to keep ({', '.join(FIT_FILES)}; run make predictions first)")
    os.makedirs(out, exist_ok=True)
    kept = []
    for f in found:
        stem, ext = os.path.splitext(f)
        name = f"{stem}_{tag}{ext}"
        shutil.copyfile(os.path.join(results, f), os.path.join(out, name))
        kept.append(name)
    # Say which groups the fit is of, so that a tag naming other ones is seen at once.
    if "collapse.json" in found:
        fitted = load_json(os.path.join(results, "collapse.json"), "collapse fit").get("compactions")
        if fitted:
            kept[0] += f" (compactions {' '.join(str(c) for c in fitted)})"
    return kept


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", required=True)
    ap.add_argument("--results", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--fit-as", metavar="TAG",
                    help="keep only the fit (a subset's), as collapse_TAG.json and so on")
    a = ap.parse_args()
    pts = load_json(a.points, "sweep points file")
    if a.fit_as is not None:
        print(f"keep_study: {a.out}: {', '.join(keep_fit_as(a.results, a.out, a.fit_as))}")
        return
    if not os.path.isfile(os.path.join(a.results, "REPORT.md")):
        die(f"{a.results}/REPORT.md: no report (run make sweep SWEEP={pts.get('name', 'NAME')} first)")
    os.makedirs(a.out, exist_ok=True)
    kept = []
    for f in (*FIT_FILES, "history.json", "convergence.json", "convergence.csv",
              "convergence_paired.csv", "calibration.json", "calibration.csv", "CALIBRATION.md",
              *sorted(os.path.basename(c) for c in glob.glob(os.path.join(a.results, "COMPARISON*"))
                      if c.endswith((".md", ".json"))),
              "crease_length.png", "collapse.png", "convergence.png", "calibration.png", "predictions.png"):
        if os.path.isfile(os.path.join(a.results, f)):
            shutil.copyfile(os.path.join(a.results, f), os.path.join(a.out, f))
            kept.append(f)
    with open(os.path.join(a.results, "REPORT.md")) as f:
        lines = f.read().split("\n")
    # The command that made it: make keep-study keeps a sweep under its own name; a part of a
    # sweep kept under another name says the script's own command line.
    if os.path.normpath(a.out) == os.path.join("docs", "studies", pts["name"]):
        how = f"make keep-study SWEEP={pts['name']}"
    else:
        how = (f"pipeline/sweeps/keep_study.py --points {os.path.relpath(a.points)} "
               f"--results {os.path.relpath(a.results)} --out {os.path.relpath(a.out)}")
    note = (f"> Kept in the repository by `{how}` from "
            f"`{os.path.relpath(a.results)}` (runs and ensembles not kept; `groups.csv` holds each "
            f"group's per-cycle table). Paths below are relative to that folder.\n")
    with open(os.path.join(a.out, "REPORT.md"), "w") as f:
        f.write("\n".join(lines[:1] + ["", note] + lines[1:]))
    kept.append("REPORT.md")
    cols = ["group", "compaction", "cycle", "n_runs", "seeds"] + [
        f"{q}_{s}" for q in QUANTITIES for s in ("mean", "std", "sem")] + list(COUNTS) + [
        f"fit_above_floor_at_{e}_n" for e in EDGES]
    with open(os.path.join(a.out, "groups.csv"), "w", newline="") as f:
        f.write(f"# sweep {pts['name']} ({pts['file']}), preset {pts['preset']}, seeds "
                f"{' '.join(str(s) for s in pts['seeds'])}: per group and cycle, over seeds\n")
        w = csv.writer(f)
        w.writerow(cols)
        for g in sweep_groups(pts):
            e = load_ensemble(os.path.join(a.results, "groups", g, "ensemble.json"))
            seeds = " ".join(str(s) for s in e.get("seeds", []))
            for row in e["cycles"]:
                edges = row.get("fit_above_floor_edges") or {}
                w.writerow([g, row.get("compaction"), row["cycle"], row.get("n_runs"), seeds] +
                           [row.get(c) for c in cols[5:len(cols) - len(EDGES)]] +
                           [edges.get(e) for e in EDGES])
    kept.append("groups.csv")
    if write_runs_table(pts, os.path.join(a.out, "runs.csv")):
        kept.append("runs.csv")
    print(f"keep_study: {a.out}: {', '.join(kept)}")


if __name__ == "__main__":
    main()
