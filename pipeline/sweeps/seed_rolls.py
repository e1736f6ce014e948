#!/usr/bin/python3
"""How each run's roll axes go with its crease growth, from a kept study's runs.csv (issue 36:
whether a set of seeds samples the protocol's random rolls fairly; docs/SCIENCE.md, "Which rolls
the seeds draw").

Two orientations matter in this model (docs/studies/roll_axis/, roll_side/): the first roll's
angle to the nearer side of the square sheet (rolled about a side it creases about twice the
perimeter of an oblique roll), and each later roll's novelty, its smallest angle to the axes
rolled before (a roll that repeats an earlier one adds little). Per run this lists the first
roll's angle to the nearer side with P after cycle 1, and per later cycle the novelty with the
increment of P; then, over all runs, Spearman's rank correlation of P(1) with the first roll's
angle to the side and of the increments with the novelty (each with its p-value and the number
of pairs), and
the mean increment of the rolls within 10 degrees of an earlier axis against those beyond 30.
A uniform draw puts the first roll 22.5 degrees from a side on average and the second 45
degrees from the first.

Writes OUT.json and OUT.md. Exit 2 on bad input (no runs.csv, no roll axes in it).

usage: seed_rolls.py --runs docs/studies/NAME/runs.csv [--group GROUP] -o OUT
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, read_csv  # noqa: E402


def angle_to_side(axis):
    """A roll axis's angle (degrees) to the nearer side of the square sheet (sides at 0 and 90)."""
    d = axis % 90.0
    return min(d, 90.0 - d)


def spearman(xs, ys):
    """Spearman's rank correlation and its two-sided p-value, or (None, None) with fewer than
    three pairs or no spread. Up to seven pairs the p-value is exact (every permutation; scipy's
    t approximation calls three pairs in perfect order certain, where one ordering in three is
    as extreme), beyond from scipy."""
    from itertools import permutations
    from scipy.stats import spearmanr
    if len(xs) < 3 or len(set(xs)) < 2 or len(set(ys)) < 2:
        return None, None
    r = spearmanr(xs, ys)
    rho = float(r.statistic)
    if len(xs) > 7:
        return rho, float(r.pvalue)
    rhos = [float(spearmanr(xs, list(p)).statistic) for p in permutations(ys)]
    return rho, sum(1 for r in rhos if abs(r) >= abs(rho) - 1e-12) / len(rhos)


def read_runs(path, group):
    rows = read_csv(path)
    need = {"group", "seed", "cycle", "perimeter_P", "roll_axis_deg", "novelty_deg"}
    if not rows or not need <= set(rows[0]):
        die(f"{path}: not a runs.csv (columns {sorted(need)} expected)")
    runs = {}
    for r in rows:
        if group and r["group"] != group:
            continue
        if r["roll_axis_deg"] in ("", None):
            die(f"{path}: group {r['group']} seed {r['seed']} cycle {r['cycle']}: no roll axis "
                "recorded (a run file older than the axes' record)")
        runs.setdefault((r["group"], int(r["seed"])), {})[int(r["cycle"])] = r
    if not runs:
        die(f"{path}: no runs" + (f" in group {group}" if group else ""))
    return runs


def mean(xs):
    return sum(xs) / len(xs) if xs else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", required=True, help="a kept study's runs.csv")
    ap.add_argument("--group", help="only this group of the study")
    ap.add_argument("-o", "--output", required=True, help="OUT (writes OUT.json and OUT.md)")
    a = ap.parse_args()
    runs = read_runs(a.runs, a.group)
    table, firsts, later = [], [], []
    for (group, seed), cycles in sorted(runs.items()):
        c1 = cycles.get(1)
        if c1 is None:
            die(f"{a.runs}: group {group} seed {seed}: no cycle 1")
        side = angle_to_side(float(c1["roll_axis_deg"]))
        P = {n: float(r["perimeter_P"]) for n, r in cycles.items()}
        row = {"group": group, "seed": seed, "first_roll_to_side_deg": round(side, 1),
               "P1": P[1], "cycles": []}
        firsts.append((side, P[1]))
        for n in sorted(cycles):
            if n == 1 or n - 1 not in P:
                continue
            nov, inc = float(cycles[n]["novelty_deg"]), P[n] - P[n - 1]
            row["cycles"].append({"cycle": n, "novelty_deg": round(nov, 1), "P_increment": inc})
            later.append((n, nov, inc))
        table.append(row)
    near = [inc for _, nov, inc in later if nov < 10]
    far = [inc for _, nov, inc in later if nov > 30]
    rho1, p1 = spearman([s for s, _ in firsts], [p for _, p in firsts])
    rho2, p2 = spearman([n for _, n, _ in later], [i for _, _, i in later])
    summary = {
        "runs": len(table),
        "spearman_P1_vs_first_roll_to_side": rho1, "p_P1": p1, "pairs_P1": len(firsts),
        "spearman_increment_vs_novelty": rho2, "p_increment": p2,
        "pairs_increment": len(later),
        "mean_increment_novelty_below_10": mean(near), "n_below_10": len(near),
        "mean_increment_novelty_above_30": mean(far), "n_above_30": len(far),
        "mean_first_roll_to_side_deg": mean([s for s, _ in firsts]),
        "mean_second_roll_novelty_deg": mean([nov for n, nov, _ in later if n == 2]),
    }
    doc = {"source": os.path.relpath(a.runs), "group": a.group, "runs": table, "summary": summary}
    with open(a.output + ".json.new", "w") as f:
        json.dump(doc, f, indent=1)
    os.replace(a.output + ".json.new", a.output + ".json")

    def fmt(x, nd=2):
        return "–" if x is None else f"{x:.{nd}f}"

    def pval(p):
        return "p < 0.001" if p is not None and p < 0.001 else f"p = {fmt(p, 3)}"

    cycles = sorted({c["cycle"] for r in table for c in r["cycles"]})
    md = [f"# Roll axes and crease growth run by run (`{os.path.relpath(a.runs)}`"
          + (f", group {a.group})" if a.group else ")"), "",
          "Made by `pipeline/sweeps/seed_rolls.py`. P in L0; the first roll's angle to the nearer "
          "side of the sheet (uniform draw: 22.5° on average); for each later cycle the roll's "
          "novelty (its smallest angle to the axes rolled before; the second roll's averages 45° "
          "in a uniform draw) and the increment of P.", "",
          "| " + " | ".join(["group", "seed", "first roll to side", "P(1)"]
                           + [f"cycle {n}: novelty, ΔP" for n in cycles]) + " |",
          "|" + " --- |" * (4 + len(cycles))]
    for r in table:
        by = {c["cycle"]: c for c in r["cycles"]}
        md.append("| " + " | ".join(
            [r["group"], str(r["seed"]), f"{r['first_roll_to_side_deg']:.1f}°", f"{r['P1']:.1f}"]
            + [f"{by[n]['novelty_deg']:.1f}°, {by[n]['P_increment']:+.1f}" if n in by else "–"
               for n in cycles]) + " |")
    s = summary
    md += ["", f"- Spearman ρ of P(1) with the first roll's angle to the side: "
               f"{fmt(s['spearman_P1_vs_first_roll_to_side'])} ({pval(s['p_P1'])}) over "
               f"{s['pairs_P1']} runs "
               f"(mean angle {fmt(s['mean_first_roll_to_side_deg'], 1)}°)"]
    if later:  # a one-cycle study has no later rolls to tell about
        md += [f"- Spearman ρ of the increment of P with the roll's novelty: "
               f"{fmt(s['spearman_increment_vs_novelty'])} ({pval(s['p_increment'])}) over "
               f"{s['pairs_increment']} run-cycles (the cycles of a run are not independent draws "
               "of the rest of its history, so p is indicative)",
               f"- mean increment of rolls within 10° of an earlier axis: "
               f"{fmt(s['mean_increment_novelty_below_10'], 1)} L0 ({s['n_below_10']}); beyond 30°: "
               f"{fmt(s['mean_increment_novelty_above_30'], 1)} L0 ({s['n_above_30']})",
               f"- mean novelty of the second roll: {fmt(s['mean_second_roll_novelty_deg'], 1)}°"]
    md.append("")
    with open(a.output + ".md.new", "w") as f:
        f.write("\n".join(md))
    os.replace(a.output + ".md.new", a.output + ".md")
    print("\n".join(line for line in md if line.startswith("- ")))


if __name__ == "__main__":
    main()
