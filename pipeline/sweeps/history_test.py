#!/usr/bin/python3
"""The history-independence test of a sweep (pipeline/sweeps/history.yaml; docs/STATISTICS.md
§2.3): the experiments found that the crease length a cycle adds depends only on the crease
length already there and on that cycle's compaction D, not on how the sheet got there. Sheets
are brought to some length by different histories of compaction and then crumpled at the test
compaction D; the reference is the group crumpled at D in every cycle.

For every group and every cycle n >= 2 crumpled at D after a different history, with mean
length l_pre before it (cycle n - 1) and mean increment dl (both over seeds, with their
s.e.m.), the reference predicts the increment a sheet of length l_pre gets at D: the reference
mean curve l_ref(k) (k = 0, 1, ..., l_ref(0) = 0) is inverted at l_pre by linear interpolation,
k*, and dl_pred = l_ref(k* + 1) - l_ref(k*); its error is the reference increments' s.e.m.
interpolated alike. The verdict is |dl - dl_pred| / sqrt(sem_dl^2 + sem_pred^2) against
AGREE_SEM (2, the reports' rule). A prediction that needs the reference beyond its last cycle
(l_pre above the reference's last length but one) is left out and said so. This computes
differences and interpolations of the ensemble means only; the statistics over seeds are the
ensembles' (crumple-analyze ensemble).

Writes RESULTS/history.json.
  history_test.py --points runs/sweeps/NAME/points.json --results results/NAME --compaction 0.27
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, load_ensemble, load_json, sweep_groups  # noqa: E402

AGREE_SEM = 2.0
MEASURES = ("perimeter_P", "crease_length_L0")


def series(e, key):
    """{cycle: (mean, sem, increment mean, increment sem, compaction)} of an ensemble."""
    out = {}
    for r in e["cycles"]:
        out[r["cycle"]] = (r.get(key + "_mean"), r.get(key + "_sem"),
                           r.get(key + "_increment_mean"), r.get(key + "_increment_sem"),
                           r.get("compaction"))
    return out


def interpolate(xs, ys, x):
    """Linear interpolation of ys(xs) at x within [xs[0], xs[-1]]; None outside."""
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            w = 0.0 if xs[i + 1] == xs[i] else (x - xs[i]) / (xs[i + 1] - xs[i])
            return ys[i] + w * (ys[i + 1] - ys[i])
    return None


def reference_curve(ref, key):
    """Cycle numbers 0..N and the reference means (0 at k = 0) and increment s.e.m.s."""
    s = series(ref, key)
    ks, ls, sems = [0], [0.0], [0.0]
    for k in sorted(s):
        m, _, _, isem, _ = s[k]
        if m is None or k != ks[-1] + 1:
            break
        ks.append(k), ls.append(m), sems.append(isem or 0.0)
    return ks, ls, sems


def predict(ks, ls, sems, l_pre):
    """The reference's increment for a sheet of length l_pre, and its error; None beyond it."""
    if any(b <= a for a, b in zip(ls, ls[1:])):  # the inversion needs a rising curve
        ls = [max(ls[:i + 1]) for i in range(len(ls))]
    k_star = None
    for i in range(len(ls) - 1):
        if ls[i] <= l_pre <= ls[i + 1] and ls[i + 1] > ls[i]:
            k_star = ks[i] + (l_pre - ls[i]) / (ls[i + 1] - ls[i])
            break
    if k_star is None or k_star + 1 > ks[-1]:
        return None
    pred = interpolate(ks, ls, k_star + 1) - l_pre
    # The increment of cycle k+1 has the s.e.m. sems[k+1]; interpolated between neighbours.
    sem = interpolate(ks[1:], sems[1:], min(max(k_star + 1, ks[1]), ks[-1]))
    return k_star, pred, sem


def history_json(points, results, D):
    groups = sweep_groups(points)
    ens = {g: load_ensemble(os.path.join(results, "groups", g, "ensemble.json")) for g in groups}
    schedule = {}
    for g, e in ens.items():
        cs = [r.get("compaction") for r in e["cycles"]]
        if any(c is None for c in cs):
            die(f"group {g}: the compaction of some cycle is unknown; the history test needs "
                "each cycle's (recorded by crumple-sim since issue 34)")
        schedule[g] = cs
    refs = [g for g in groups if all(abs(c - D) < 1e-12 for c in schedule[g])]
    if not refs:
        die(f"no group is crumpled at {D} in every cycle: the history test needs that reference")
    ref = refs[0]
    out = {"compaction": D, "reference": ref, "rule": f"agree within {AGREE_SEM:g} combined s.e.m.",
           "method": "prediction from the reference group's mean curve at the same crease "
                     "length (pipeline/sweeps/history_test.py)",
           "groups": [{"group": g, "schedule": schedule[g], "n_runs": ens[g]["n_runs"]}
                      for g in groups],
           "tests": {}, "notes": []}
    for key in MEASURES:
        ks, ls, sems = reference_curve(ens[ref], key)
        rows = []
        for g in groups:
            if g == ref:
                continue
            s = series(ens[g], key)
            for n in sorted(s):
                if n < 2 or abs(schedule[g][n - 1] - D) > 1e-12 or n - 1 not in s:
                    continue
                if all(abs(c - D) < 1e-12 for c in schedule[g][:n - 1]):
                    continue  # the same history as the reference so far: nothing to test
                l_pre, sem_pre = s[n - 1][0], s[n - 1][1]
                dl, sem_dl = s[n][2], s[n][3]
                if l_pre is None or dl is None:
                    continue
                row = {"group": g, "cycle": n, "history": schedule[g][:n - 1], "l_pre": l_pre,
                       "l_pre_sem": sem_pre, "dl": dl, "dl_sem": sem_dl}
                p = predict(ks, ls, sems, l_pre)
                if p is None:
                    row["note"] = ("l_pre beyond the reference's range (run the reference for "
                                   "more cycles)")
                else:
                    k_star, pred, psem = p
                    comb = math.hypot(sem_dl or 0.0, psem or 0.0)
                    z = abs(dl - pred) / comb if comb > 0 else None
                    row.update({"k_equivalent": k_star, "dl_pred": pred, "dl_pred_sem": psem,
                                "z": z, "ratio": dl / pred if pred else None,
                                "verdict": None if z is None else
                                ("agree" if z <= AGREE_SEM else "disagree")})
                rows.append(row)
        out["tests"][key] = rows
    if not any(out["tests"][k] for k in MEASURES):
        out["notes"].append("no cycle was crumpled at the test compaction after a different "
                            "history: nothing to test")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", required=True)
    ap.add_argument("--results", required=True)
    ap.add_argument("--compaction", type=float, required=True, help="the test compaction D")
    a = ap.parse_args()
    if not 0 < a.compaction < 1:
        die("--compaction must lie in (0, 1)")
    doc = history_json(load_json(a.points, "sweep points file"), a.results, a.compaction)
    path = os.path.join(a.results, "history.json")
    with open(path + ".new", "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    os.replace(path + ".new", path)
    n = sum(len(v) for v in doc["tests"].values())
    print(f"history_test.py: {n} comparisons -> {path}")


if __name__ == "__main__":
    main()
