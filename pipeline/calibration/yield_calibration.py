#!/usr/bin/env python3
"""The calibration of the yield (issue 36, item 4; docs/SCIENCE.md): from a calibration sweep
(one cycle at compaction D for a bracket of yield values, several seeds each), the yield at
which the ensemble mean of the perimeter measure P after cycle 1 equals the experiments' law
c1 (1 - D) ln(1 + c2/D) (data/crease_length_law_constants.csv; docs/STATISTICS.md §2.1).

The sweep varies one statement of the yield (docs/MODEL.md §7.5-7.6), named by its grid key:
material.yield_radius (pipeline/sweeps/yield_radius_calibration.yaml; P rises with the radius,
a gentler yield) or material.yield_angle (pipeline/sweeps/yield_calibration.yaml; P falls as the
angle rises). P changes steeply and about exponentially over the bracket, so the yield is found
by linear interpolation of ln P between the two neighbouring values whose P bracket the target.
Its uncertainty comes from the seeds: each end's s.e.m. of ln P, carried through the
interpolation in quadrature. As a cross-check a weighted straight line through all (value, ln P)
is solved for the target too; the two should agree within the uncertainty when ln P is near
linear across the bracket.

Writes OUT/calibration.json, OUT/calibration.csv (P per value), OUT/CALIBRATION.md and
OUT/calibration.png. Exit 0 done; 2 bad input; 3 the target is not bracketed (the message says
which way to extend the grid, or that P peaks or dips inside it) or P is not monotonic where it
crosses the target.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import (add_figure_args, die, experiment, figure_output, load_ensemble,  # noqa: E402
                    load_json, save_figure, sweep_groups)

# The statements of the yield a calibration may vary: the points file's key, the name and unit
# the report uses, and the factor from the key's value to that unit.
KINDS = {
    "material.yield_angle": {"name": "yield angle", "unit": "degrees", "short": "deg", "scale": 1.0,
                             "section": "§7.6"},
    "material.yield_radius": {"name": "yield radius", "unit": "mm", "short": "mm", "scale": 1e3,
                              "section": "§7.5"},
}


def yield_key(points):
    """The yield statement the sweep varies (one of KINDS), or die."""
    keys = {k for p in points["points"] for k in p["values"] if k in KINDS}
    if len(keys) != 1:
        die(f"the points file varies {sorted(keys) or 'no yield'}: a yield calibration varies "
            f"exactly one of {sorted(KINDS)}")
    return keys.pop()


def hinge_c0(key, value):
    """The hinge yield c0 the value gives, where it does not depend on the mesh (the angle)."""
    return 2 * math.sin(math.radians(value) / 2) if key == "material.yield_angle" else None


def yield_rows(points, groups_dir, key):
    """Per yield value of the sweep (in KINDS[key]'s unit): P and l after cycle 1 (mean, s.e.m.),
    the compaction, the runs."""
    rows = []
    for group in sweep_groups(points):
        p = next(q for q in points["points"] if q["group"] == group)
        if key not in p["values"]:
            die(f"group {group} of the points file does not vary {key}: not a yield calibration")
        e = load_ensemble(os.path.join(groups_dir, group, "ensemble.json"))
        c1 = next((c for c in e["cycles"] if c["cycle"] == 1), None)
        if c1 is None:
            die(f"group {group}: no cycle 1 in its ensemble")
        value = float(p["values"][key]) * KINDS[key]["scale"]
        rows.append({"group": group, "value": value, "c0": hinge_c0(key, value),
                     "compaction": e["compaction"], "n_runs": e["n_runs"],
                     "P_mean": c1["perimeter_P_mean"], "P_sem": c1["perimeter_P_sem"],
                     "l_mean": c1["crease_length_L0_mean"], "l_sem": c1["crease_length_L0_sem"],
                     "threshold": e.get("parameters", {}).get("threshold")})
    rows.sort(key=lambda r: r["value"])
    return rows


def interpolate(rows, target, kind):
    """The value where ln P crosses ln target, between the neighbouring values that bracket it,
    with its standard error from the two ends' s.e.m.; None and a reason when not bracketed."""
    lt = math.log(target)
    u = kind["unit"]
    brackets = [(a, b) for a, b in zip(rows, rows[1:])
                if min(a["P_mean"], b["P_mean"]) <= target <= max(a["P_mean"], b["P_mean"])]
    if len(brackets) > 1:
        where = ", ".join(f"{a['value']:g}-{b['value']:g} {u}" for a, b in brackets)
        return None, (f"P crosses the target more than once ({where}): it is not monotonic in the "
                      f"{kind['name']}, so no single value is calibrated; refine or extend the grid")
    for a, b in brackets:
        la, lb = math.log(a["P_mean"]), math.log(b["P_mean"])
        if la == lb:
            return None, f"P is flat between {a['value']:g} and {b['value']:g} {u}"
        t = (lt - la) / (lb - la)
        value = a["value"] + t * (b["value"] - a["value"])
        slope = (lb - la) / (b["value"] - a["value"])  # d ln P / d value
        # value* moves by -(1 - t) dlnPa / slope and -t dlnPb / slope.
        sa, sb = a["P_sem"] / a["P_mean"], b["P_sem"] / b["P_mean"]
        sigma = math.hypot((1 - t) * sa, t * sb) / abs(slope)
        return {"value": value, "sigma": sigma, "between": [a["value"], b["value"]],
                "dlnP_dvalue": slope}, None
    # Not bracketed. Where P comes closest to the target at an end of the grid, extending the
    # grid beyond that end may reach it. Where it comes closest inside the grid (a peak below the
    # target, a dip above it) and some inner value is closer than both ends by more than twice
    # their combined s.e.m., P is not monotonic in the yield and extending is no answer. An inner best within the noise of an
    # end shows no turn: extend the end where P moves toward the target, if either does.
    above = all(r["P_mean"] > target for r in rows)
    side = "above" if above else "below"
    dist = [abs(r["P_mean"] - target) for r in rows]
    k = min(range(len(rows)), key=lambda i: dist[i])
    best = rows[k]
    ends = (0, len(rows) - 1)

    def beats(i, j):
        """Row i closer to the target than row j by more than 2 combined s.e.m."""
        return dist[j] - dist[i] > 2 * math.hypot(rows[i]["P_sem"], rows[j]["P_sem"])

    if 0 < k < len(rows) - 1:
        # The turn is shown when some inner value beats both ends (not necessarily the closest,
        # whose own s.e.m. may be the largest); the closest is the one reported.
        if any(all(beats(i, e) for e in ends) for i in range(1, len(rows) - 1)):
            turn = "a dip" if above else "a peak"
            return None, (f"P after cycle 1 is {side} the target {target:.2f} L0 at every "
                          f"{kind['name']} from {rows[0]['value']:g} to {rows[-1]['value']:g} {u}, "
                          f"with {turn} of {best['P_mean']:.2f} ± {best['P_sem']:.2f} L0 "
                          f"({best['P_mean'] / target:.2f} of the target) at {best['value']:g} {u} "
                          f"inside the grid and {rows[0]['P_mean']:.2f} and {rows[-1]['P_mean']:.2f} "
                          f"L0 at its ends: P is not monotonic in the {kind['name']}, and no value "
                          f"of the grid reaches the target")
        toward = [e for e, nb in ((0, 1), (len(rows) - 1, len(rows) - 2)) if dist[e] < dist[nb]]
        if not toward:
            return None, (f"P after cycle 1 is {side} the target {target:.2f} L0 at every "
                          f"{kind['name']} from {rows[0]['value']:g} to {rows[-1]['value']:g} {u}; "
                          f"it comes closest at {best['value']:g} {u} ({best['P_mean']:.2f} ± "
                          f"{best['P_sem']:.2f} L0) inside the grid, but not by more than twice the "
                          f"seeds' errors against both ends, and P moves away from the target at "
                          f"both ends: the grid does not show which way the target lies; add seeds, "
                          f"or values beyond both ends")
        k = min(toward, key=lambda e: dist[e])
        best = rows[k]
    way = "smaller" if k == 0 else "larger"
    return None, (f"P after cycle 1 is {side} the target {target:.2f} L0 at every {kind['name']} "
                  f"to {best['value']:g} {u}: add {way} values to the grid")


def line_fit(rows, target):
    """Weighted least squares ln P = A + B value over every value (weights 1/s.e.m.(ln P)^2),
    solved for the target: a cross-check of the local interpolation."""
    w = [(r["P_mean"] / max(r["P_sem"], 1e-12 * r["P_mean"])) ** 2 for r in rows]
    x = [r["value"] for r in rows]
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
            "value": (math.log(target) - a) / b if b != 0 else None}


def rounded(key, value):
    """The calibrated value as a protocol states it: 0.1 degree, or 0.01 mm."""
    return round(value, 1 if key == "material.yield_angle" else 2)


def write_outputs(out, key, rows, target, law, result, fit, fig_path, fig_fmt, why=None):
    kind = KINDS[key]
    u, name = kind["unit"], kind["name"]
    os.makedirs(out, exist_ok=True)
    doc = {"what": f"{name} at which P after cycle 1 equals the experiments' law",
           "key": key, "unit": u, "scale_from_key": kind["scale"], "compaction": law["D"],
           "target_P_L0": target, "law": law["note"], "c1": law["c1"], "c2": law["c2"],
           "rows": rows, "interpolation": result, "line_fit": fit,
           "method": "linear interpolation of ln P between the bracketing values; s.e.m. of "
                     "ln P at both ends carried through in quadrature"}
    if not result:
        doc["not_calibrated"] = why
    else:
        v = rounded(key, result["value"])
        doc["calibrated"] = {"key": key, "value": v, "unit": u,
                             "sigma": round(result["sigma"], 1 if key == "material.yield_angle" else 2),
                             "key_value": v / kind["scale"], "c0": hinge_c0(key, v)}
    with open(os.path.join(out, "calibration.json"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    with open(os.path.join(out, "calibration.csv"), "w") as f:
        f.write(f"{key.split('.')[-1]}_{kind['short']},c0,n_runs,P_cycle1_mean_L0,P_cycle1_sem_L0,"
                "l_cycle1_mean_L0,l_cycle1_sem_L0\n")
        for r in rows:
            c0 = f"{r['c0']:.6g}" if r["c0"] is not None else ""
            f.write(f"{r['value']:g},{c0},{r['n_runs']},{r['P_mean']:.6g},"
                    f"{r['P_sem']:.6g},{r['l_mean']:.6g},{r['l_sem']:.6g}\n")
    plot(doc, fig_path, fig_fmt)
    lines = [f"# Calibration of the {name}", "",
             f"The one fitted constant: `{key}` (docs/MODEL.md {kind['section']}), chosen so that the "
             f"mean perimeter measure P after the first cycle at compaction {law['D']} equals the "
             f"experiments' law, {law['c1']:g} (1 - {law['D']}) ln(1 + {law['c2']:g}/{law['D']}) = "
             f"{target:.2f} L0 (data/crease_length_law_constants.csv). Everything else the "
             "simulation predicts."]
    thresholds = {round(r["threshold"], 9) if r.get("threshold") is not None else None for r in rows}
    if len(thresholds) == 1 and None not in thresholds:
        t = thresholds.pop()
        lines[-1] += (f" Creases are hinges with |p| > {t:.4g}, a permanent fold of more than "
                      f"{math.degrees(2 * math.asin(min(1.0, t / 2))):.1f} degrees, at every value.")
    lines += ["", f"| {name} ({u}) | runs | P after cycle 1 (L0) | ℓ after cycle 1 (L0) |",
             "| --- | --- | --- | --- |"]
    for r in rows:
        lines.append(f"| {r['value']:g} | {r['n_runs']} | {r['P_mean']:.2f} ± "
                     f"{r['P_sem']:.2f} | {r['l_mean']:.2f} ± {r['l_sem']:.2f} |")
    lines.append("")
    if result:
        c0 = doc["calibrated"]["c0"]
        lines.append(f"**Calibrated {name}: {result['value']:.2f} ± {result['sigma']:.2f} {u}**"
                     + (f" (c0 = {c0:.3f})" if c0 is not None else "")
                     + f", interpolating ln P between {result['between'][0]:g} and "
                     f"{result['between'][1]:g} {u}; the uncertainty is the seeds' s.e.m. carried "
                     "through. ")
        if fit and fit["value"] is not None:
            lines.append(f"A weighted straight line through all values, ln P = {fit['A']:.3f} "
                         f"{fit['B']:+.4f} x (χ² = {fit['chi2']:.1f} for {fit['dof']} degrees "
                         f"of freedom), gives {fit['value']:.2f} {u}.")
    else:
        lines.append(f"**Not calibrated:** {why}.")
    lines += ["", f"![P after cycle 1 against the {name}](calibration.{fig_fmt})", ""]
    with open(os.path.join(out, "CALIBRATION.md"), "w") as f:
        f.write("\n".join(lines))


def plot(doc, path, fmt):
    """The figure, from a calibration document alone (so make study-figures can redraw it)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    kind = KINDS[doc["key"]]
    rows, target, result, fit = doc["rows"], doc["target_P_L0"], doc["interpolation"], doc["line_fit"]
    fig, ax = plt.subplots(figsize=(5.2, 3.8))
    x = [r["value"] for r in rows]
    ax.errorbar(x, [r["P_mean"] for r in rows], yerr=[r["P_sem"] for r in rows], fmt="o",
                color="C0", capsize=3, label="simulation, mean ± s.e.m. over seeds")
    if fit and fit["value"] is not None:
        xs = [x[0] + (x[-1] - x[0]) * k / 50 for k in range(51)]
        ax.plot(xs, [math.exp(fit["A"] + fit["B"] * v) for v in xs], color="C0", lw=0.8, ls=":",
                label="weighted line in ln P")
    ax.axhline(target, color="k", lw=1, ls="--", label=f"experiments' law, {target:.2f} L0")
    if result:
        ax.axvspan(result["value"] - result["sigma"], result["value"] + result["sigma"],
                   color="C1", alpha=0.3,
                   label=f"calibrated {result['value']:.2f} ± {result['sigma']:.2f} {kind['short']}")
    ax.set_yscale("log")
    ax.set_xlabel(f"{kind['name']} ({kind['unit']})")
    ax.set_ylabel("P after cycle 1 (L0)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path, fmt, 150)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--points", help="runs/sweeps/<calibration sweep>/points.json")
    ap.add_argument("--groups", help="results/<calibration sweep>/groups")
    ap.add_argument("--out", help="folder for the calibration's files")
    ap.add_argument("--replot", metavar="CALIBRATION_JSON",
                    help="only redraw the figure from a kept calibration.json (make study-figures)")
    add_figure_args(ap)
    a = ap.parse_args()
    a.output, a.format = figure_output(a)
    if a.replot:
        doc = load_json(a.replot, "calibration file")
        if doc.get("key") not in KINDS or "rows" not in doc:
            die(f"{a.replot}: not a calibration document of this script (no known yield key)")
        plot(doc, a.output, a.format)
        return
    if not (a.points and a.groups and a.out):
        die("give --points, --groups and --out (or --replot CALIBRATION_JSON)")
    points = load_json(a.points, "points file")
    key = yield_key(points)
    rows = yield_rows(points, a.groups, key)
    if len(rows) < 2:
        die(f"{a.points}: the calibration needs at least two values of {key}, got {len(rows)}")
    lone = [r["group"] for r in rows if r["P_sem"] is None]
    if lone:
        # The calibrated value's error, and whether P turns inside the grid, need each value's
        # s.e.m.; a single seed has none.
        die(f"{a.points}: groups {', '.join(lone)} have no s.e.m. of P (a single seed): the "
            f"calibration needs at least two seeds per value of {key}")
    ds = {r["compaction"] for r in rows}
    if len(ds) != 1 or None in ds:
        die(f"the groups were crumpled to different or unknown compactions {sorted(map(str, ds))}")
    law = experiment(ds.pop(), [1])
    target = law["cycles"][0]["law"]
    result, why = interpolate(rows, target, KINDS[key])
    fit = line_fit(rows, target)
    write_outputs(a.out, key, rows, target, law, result, fit, a.output, a.format, why)
    if result is None:
        print(f"yield_calibration: {why}", file=sys.stderr)
        sys.exit(3)
    print(f"yield_calibration: {key} = {result['value']:.3f} ± {result['sigma']:.3f} "
          f"{KINDS[key]['unit']} (P(1) = {target:.2f} L0 at compaction {law['D']}) -> {a.out}/CALIBRATION.md")


if __name__ == "__main__":
    main()
