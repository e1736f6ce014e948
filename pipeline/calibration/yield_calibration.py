#!/usr/bin/env python3
"""The calibration of the yield fold angle (issue 36, item 4; docs/SCIENCE.md): from the
yield_calibration sweep (pipeline/sweeps/yield_calibration.yaml: one cycle at compaction D for
a bracket of material.yield_angle values, several seeds each), the angle at which the ensemble
mean of the perimeter measure P after cycle 1 equals the experiments' law
c1 (1 - D) ln(1 + c2/D) (data/crease_length_law_constants.csv; docs/STATISTICS.md §2.1).

P falls steeply as the yield angle rises (fewer hinges pass a higher yield), about
exponentially over the bracket, so the angle is found by linear interpolation of ln P between
the two neighbouring angles whose P bracket the target. Its uncertainty comes from the seeds:
each end's s.e.m. of ln P, carried through the interpolation in quadrature. As a cross-check a
weighted straight line through all (angle, ln P) is solved for the target too; the two should
agree within the uncertainty when ln P is near linear across the bracket.

Writes OUT/calibration.json, OUT/calibration.csv (P per angle), OUT/CALIBRATION.md and
OUT/calibration.png. Exit 0 done; 2 bad input; 3 the target is not bracketed (the message says
which way to extend the grid) or P does not fall with the angle across the bracket.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import (add_figure_args, die, experiment, figure_output, load_ensemble,  # noqa: E402
                    load_json, save_figure, sweep_groups)

KEY = "material.yield_angle"


def angle_rows(points, groups_dir):
    """Per angle of the sweep: P after cycle 1 (mean, s.e.m., seeds), the compaction, c0."""
    rows = []
    for group in sweep_groups(points):
        p = next(q for q in points["points"] if q["group"] == group)
        if KEY not in p["values"]:
            die(f"group {group} of the points file does not vary {KEY}: not a yield calibration")
        e = load_ensemble(os.path.join(groups_dir, group, "ensemble.json"))
        c1 = next((c for c in e["cycles"] if c["cycle"] == 1), None)
        if c1 is None:
            die(f"group {group}: no cycle 1 in its ensemble")
        rows.append({"group": group, "angle_deg": float(p["values"][KEY]),
                     "c0": 2 * math.sin(math.radians(float(p["values"][KEY])) / 2),
                     "compaction": e["compaction"], "n_runs": e["n_runs"],
                     "P_mean": c1["perimeter_P_mean"], "P_sem": c1["perimeter_P_sem"],
                     "l_mean": c1["crease_length_L0_mean"], "l_sem": c1["crease_length_L0_sem"]})
    rows.sort(key=lambda r: r["angle_deg"])
    return rows


def interpolate(rows, target):
    """The angle where ln P crosses ln target, between the neighbouring angles that bracket it,
    with its standard error from the two ends' s.e.m.; None and a reason when not bracketed."""
    lt = math.log(target)
    for a, b in zip(rows, rows[1:]):
        if not (b["P_mean"] <= target <= a["P_mean"]):
            continue
        la, lb = math.log(a["P_mean"]), math.log(b["P_mean"])
        if la == lb:
            return None, f"P is flat between {a['angle_deg']} and {b['angle_deg']} degrees"
        t = (lt - la) / (lb - la)
        angle = a["angle_deg"] + t * (b["angle_deg"] - a["angle_deg"])
        slope = (lb - la) / (b["angle_deg"] - a["angle_deg"])  # d ln P / d angle
        # angle* moves by -(1 - t) dlnPa / slope and -t dlnPb / slope.
        sa, sb = a["P_sem"] / a["P_mean"], b["P_sem"] / b["P_mean"]
        sigma = math.hypot((1 - t) * sa, t * sb) / abs(slope)
        return {"angle_deg": angle, "sigma_deg": sigma, "between_deg": [a["angle_deg"], b["angle_deg"]],
                "dlnP_dangle": slope}, None
    if all(r["P_mean"] > target for r in rows):
        return None, (f"P after cycle 1 is above the target {target:.2f} L0 at every angle up to "
                      f"{rows[-1]['angle_deg']} degrees: add larger angles to the grid")
    if all(r["P_mean"] < target for r in rows):
        return None, (f"P after cycle 1 is below the target {target:.2f} L0 at every angle down to "
                      f"{rows[0]['angle_deg']} degrees: add smaller angles to the grid")
    return None, "P does not fall monotonically with the angle where it crosses the target"


def line_fit(rows, target):
    """Weighted least squares ln P = A + B angle over every angle (weights 1/s.e.m.(ln P)^2),
    solved for the target: a cross-check of the local interpolation."""
    w = [(r["P_mean"] / max(r["P_sem"], 1e-12 * r["P_mean"])) ** 2 for r in rows]
    x = [r["angle_deg"] for r in rows]
    y = [math.log(r["P_mean"]) for r in rows]
    sw = sum(w)
    mx = sum(wi * xi for wi, xi in zip(w, x)) / sw
    my = sum(wi * yi for wi, yi in zip(w, y)) / sw
    sxx = sum(wi * (xi - mx) ** 2 for wi, xi in zip(w, x))
    if sxx == 0:
        return None
    b = sum(wi * (xi - mx) * (yi - my) for wi, xi, yi in zip(w, x, y)) / sxx
    a = my - b * mx
    chi2 = sum(wi * (yi - a - b * xi) ** 2 for wi, xi, yi in zip(w, x, y))
    return {"A": a, "B": b, "chi2": chi2, "dof": len(rows) - 2,
            "angle_deg": (math.log(target) - a) / b if b != 0 else None}


def write_outputs(out, rows, target, law, result, fit, fig_path, fig_fmt):
    os.makedirs(out, exist_ok=True)
    doc = {"what": "yield fold angle at which P after cycle 1 equals the experiments' law",
           "key": KEY, "compaction": law["D"], "target_P_L0": target, "law": law["note"],
           "c1": law["c1"], "c2": law["c2"], "rows": rows, "interpolation": result,
           "line_fit": fit,
           "method": "linear interpolation of ln P between the bracketing angles; s.e.m. of "
                     "ln P at both ends carried through in quadrature"}
    if result:
        doc["calibrated"] = {"angle_deg": round(result["angle_deg"], 1),
                             "sigma_deg": round(result["sigma_deg"], 1),
                             "c0": 2 * math.sin(math.radians(round(result["angle_deg"], 1)) / 2)}
    with open(os.path.join(out, "calibration.json"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    with open(os.path.join(out, "calibration.csv"), "w") as f:
        f.write("yield_angle_deg,c0,n_runs,P_cycle1_mean_L0,P_cycle1_sem_L0,"
                "l_cycle1_mean_L0,l_cycle1_sem_L0\n")
        for r in rows:
            f.write(f"{r['angle_deg']:g},{r['c0']:.6g},{r['n_runs']},{r['P_mean']:.6g},"
                    f"{r['P_sem']:.6g},{r['l_mean']:.6g},{r['l_sem']:.6g}\n")
    plot(rows, target, result, fit, fig_path, fig_fmt)
    lines = ["# Calibration of the yield fold angle", "",
             f"The one fitted constant: `{KEY}` (docs/MODEL.md §7.6), chosen so that the mean perimeter "
             f"measure P after the first cycle at compaction {law['D']} equals the experiments' law, "
             f"{law['c1']:g} (1 - {law['D']}) ln(1 + {law['c2']:g}/{law['D']}) = {target:.2f} L0 "
             "(data/crease_length_law_constants.csv). Everything else the simulation predicts.", "",
             "| yield angle (deg) | c0 | runs | P after cycle 1 (L0) | ℓ after cycle 1 (L0) |",
             "| --- | --- | --- | --- | --- |"]
    for r in rows:
        lines.append(f"| {r['angle_deg']:g} | {r['c0']:.3f} | {r['n_runs']} | {r['P_mean']:.2f} ± "
                     f"{r['P_sem']:.2f} | {r['l_mean']:.2f} ± {r['l_sem']:.2f} |")
    lines.append("")
    if result:
        lines.append(f"**Calibrated yield angle: {result['angle_deg']:.1f} ± {result['sigma_deg']:.1f} "
                     f"degrees** (c0 = {doc['calibrated']['c0']:.3f}), interpolating ln P between "
                     f"{result['between_deg'][0]:g} and {result['between_deg'][1]:g} degrees; the "
                     "uncertainty is the seeds' s.e.m. carried through. ")
        if fit and fit["angle_deg"] is not None:
            lines.append(f"A weighted straight line through all angles, ln P = {fit['A']:.3f} "
                         f"{fit['B']:+.4f} angle (χ² = {fit['chi2']:.1f} for {fit['dof']} degrees "
                         f"of freedom), gives {fit['angle_deg']:.1f} degrees.")
    lines += ["", f"![P after cycle 1 against the yield angle](calibration.{fig_fmt})", ""]
    with open(os.path.join(out, "CALIBRATION.md"), "w") as f:
        f.write("\n".join(lines))


def plot(rows, target, result, fit, path, fmt):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.2, 3.8))
    x = [r["angle_deg"] for r in rows]
    ax.errorbar(x, [r["P_mean"] for r in rows], yerr=[r["P_sem"] for r in rows], fmt="o",
                color="C0", capsize=3, label="simulation, mean ± s.e.m. over seeds")
    if fit and fit["angle_deg"] is not None:
        xs = [x[0] + (x[-1] - x[0]) * k / 50 for k in range(51)]
        ax.plot(xs, [math.exp(fit["A"] + fit["B"] * v) for v in xs], color="C0", lw=0.8, ls=":",
                label="weighted line in ln P")
    ax.axhline(target, color="k", lw=1, ls="--", label=f"experiments' law, {target:.2f} L0")
    if result:
        ax.axvspan(result["angle_deg"] - result["sigma_deg"], result["angle_deg"] + result["sigma_deg"],
                   color="C1", alpha=0.3,
                   label=f"calibrated {result['angle_deg']:.1f} ± {result['sigma_deg']:.1f}°")
    ax.set_yscale("log")
    ax.set_xlabel("yield fold angle (degrees)")
    ax.set_ylabel("P after cycle 1 (L0)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path, fmt, 150)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--points", help="runs/sweeps/yield_calibration/points.json")
    ap.add_argument("--groups", help="results/yield_calibration/groups")
    ap.add_argument("--out", help="folder for the calibration's files")
    ap.add_argument("--replot", metavar="CALIBRATION_JSON",
                    help="only redraw the figure from a kept calibration.json (make study-figures)")
    add_figure_args(ap)
    a = ap.parse_args()
    a.output, a.format = figure_output(a)
    if a.replot:
        doc = load_json(a.replot, "calibration file")
        plot(doc["rows"], doc["target_P_L0"], doc["interpolation"], doc["line_fit"], a.output, a.format)
        return
    if not (a.points and a.groups and a.out):
        die("give --points, --groups and --out (or --replot CALIBRATION_JSON)")
    points = load_json(a.points, "points file")
    rows = angle_rows(points, a.groups)
    if len(rows) < 2:
        die(f"{a.points}: the calibration needs at least two yield angles, got {len(rows)}")
    ds = {r["compaction"] for r in rows}
    if len(ds) != 1 or None in ds:
        die(f"the groups were crumpled to different or unknown compactions {sorted(map(str, ds))}")
    law = experiment(ds.pop(), [1])
    target = law["cycles"][0]["law"]
    result, why = interpolate(rows, target)
    fit = line_fit(rows, target)
    write_outputs(a.out, rows, target, law, result, fit, a.output, a.format)
    if result is None:
        print(f"yield_calibration: {why}", file=sys.stderr)
        sys.exit(3)
    print(f"yield_calibration: {result['angle_deg']:.2f} ± {result['sigma_deg']:.2f} degrees "
          f"(P(1) = {target:.2f} L0 at compaction {law['D']}) -> {a.out}/CALIBRATION.md")


if __name__ == "__main__":
    main()
