#!/usr/bin/python3
"""Rate independence of the plastic flow (make rate-check): from crumple-analyze's stats.json of
runs named rate<R>_seed<S>.analysis/stats.json, the per-cycle crease length l/L0, the new length
of each cycle and P at every rate (ensemble mean and seed-to-seed standard deviation), and the
change of the mean from the middle rate to each other rate against the seed-to-seed spread.

A rate-independent flow changes the crease length by less than the seed-to-seed standard
deviation when the rate is halved or doubled (issue 31; docs/MODEL.md section 7.2).

usage: rate_check.py -o results/rate_check runs/rate_check/rate*_seed*.analysis/stats.json
"""
import argparse
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, load_json  # noqa: E402

QUANTITIES = [("crease_length_L0", "ℓ/L0 (cumulative)"), ("new_crease_length_L0", "new ℓ/L0 of the cycle"),
              ("perimeter_P", "P")]


def mean_sd(v):
    n = len(v)
    m = sum(v) / n
    sd = math.sqrt(sum((x - m) ** 2 for x in v) / (n - 1)) if n > 1 else None
    return m, sd


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("stats", nargs="+")
    ap.add_argument("-o", "--output", required=True, help="directory for RATE_CHECK.md and rate_check.json")
    args = ap.parse_args()
    runs = {}  # rate -> list of cycle lists
    threshold = None
    for path in args.stats:
        m = re.search(r"rate([0-9.eE+-]+)_seed(\d+)\.analysis", path)
        if not m:
            die(f"{path}: expected a path .../rate<R>_seed<S>.analysis/stats.json")
        s = load_json(path, "stats.json")
        threshold = s.get("parameters", {}).get("threshold", threshold)
        runs.setdefault(float(m.group(1)), []).append({c["cycle"]: c for c in s["cycles"]})
    rates = sorted(runs)
    if len(rates) < 2:
        die("need runs at two rates at least")
    ref = rates[len(rates) // 2]
    cycles = sorted(set.intersection(*[set(r) for rr in runs.values() for r in rr]))
    table = []
    for n in cycles:
        for key, name in QUANTITIES:
            row = {"cycle": n, "quantity": key, "rates": {}}
            for r in rates:
                v = [run[n][key] for run in runs[r] if run[n].get(key) is not None]
                mu, sd = mean_sd(v)
                row["rates"][r] = {"mean": mu, "sd": sd, "n": len(v)}
            sd_ref = row["rates"][ref]["sd"]
            for r in rates:
                d = row["rates"][r]["mean"] - row["rates"][ref]["mean"]
                row["rates"][r]["change_from_ref"] = d
                row["rates"][r]["change_over_sd"] = abs(d) / sd_ref if sd_ref else None
            table.append(row)
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "rate_check.json"), "w") as f:
        json.dump({"reference_rate": ref, "rates": rates, "threshold": threshold, "rows": table}, f, indent=2)

    L = ["# Rate independence of the plastic flow\n",
         f"Runs at integrator.plastic_rate = {', '.join(f'{r:g}' for r in rates)} /s, "
         f"{len(runs[ref])} seeds each; crease threshold |p| > {threshold}. Each cell: ensemble mean ± "
         f"seed-to-seed s.d.; in brackets the change of the mean from the rate {ref:g} /s in units of "
         "that rate's s.d. A rate-independent flow changes the mean by less than one s.d. when the "
         "rate is halved or doubled. Written by `pipeline/checks/rate_check.py` (`make rate-check`).\n",
         "| cycle | quantity | " + " | ".join(f"rate {r:g} /s" for r in rates) + " |",
         "|---|---|" + "---|" * len(rates)]
    worst = 0.0
    for row in table:
        cells = []
        for r in rates:
            c = row["rates"][r]
            cell = f"{c['mean']:.3g} ± {c['sd']:.2g}" if c["sd"] is not None else f"{c['mean']:.3g}"
            if r != ref and c["change_over_sd"] is not None:
                cell += f" ({c['change_from_ref']:+.3g}, {c['change_over_sd']:.2f} s.d.)"
                worst = max(worst, c["change_over_sd"])
            cells.append(cell)
        name = dict(QUANTITIES)[row["quantity"]]
        L.append(f"| {row['cycle']} | {name} | " + " | ".join(cells) + " |")
    L.append("")
    L.append(f"Largest change from the rate {ref:g} /s: {worst:.2f} seed-to-seed s.d. "
             + ("(below one s.d. everywhere: rate-independent at this resolution within the seed spread)."
                if worst < 1 else "(at least one s.d. somewhere: not rate-independent within the seed spread)."))
    with open(os.path.join(args.output, "RATE_CHECK.md"), "w") as f:
        f.write("\n".join(L) + "\n")
    print(f"rate_check.py: wrote {os.path.join(args.output, 'RATE_CHECK.md')}")


if __name__ == "__main__":
    main()
