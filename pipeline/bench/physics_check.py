#!/usr/bin/python3
"""physics_check.py: is the physics unchanged? (`make physics-check`; issue 32)

A change made for speed must leave the crumpling statistics as they were. This runs the
axial-crumpling protocol with two crumple-sim binaries, --old and --new, on the same sheets
(default 1500 nodes, 3 cycles, seeds 1 2 3 4, one thread per run, two runs at a time), analyses
every run with one crumple-analyze (the same analysis for both, so that only the simulator
differs), and compares, cycle by cycle, the crease length ℓ/L0 and the facet-perimeter crease
length P (crumple-analyze's cycles.csv: crease_length_L0, perimeter_P).

For each cycle and quantity it prints the mean and the seed-to-seed standard deviation (s.d.)
over the seeds for old and new, the difference of the means new - old, and that difference in
units of the pooled s.d. sqrt((sd_old^2 + sd_new^2) / 2). The verdict is "within the
seed-to-seed spread" when |mean_new - mean_old| <= 1 pooled s.d. for both quantities at every
cycle, and "outside" otherwise (naming the worst). It is a screen, not a significance test: with
n seeds the standard error of the difference is about sqrt(2/n) s.d. (0.71 s.d. at four seeds),
so a real change of less than about one s.d. passes. When every figure is equal the results are
reported as identical (a bit-exact change).

Runs are kept and reused (resumable): each binary's runs go into a folder named after the
configuration and the binary's SHA-1, OUT/n<N>_c<C>[_<sets>]/<old|new>_<sha>/seed<S>.h5 with the
analysis in seed<S>.analysis/, so a rerun skips what exists, a killed run resumes from its
checkpoint, and a rebuilt binary gets fresh runs.

usage (from the repository root):
    make physics-check PHYSICS_OLD=OLD_CRUMPLE_SIM [PHYSICS_SEEDS="1 2 3 4"] [PHYSICS_NODES=1500]
        [PHYSICS_CYCLES=3]
    /usr/bin/python3 pipeline/bench/physics_check.py --old OLD_CRUMPLE_SIM
        [--new build/sim/apps/crumple-sim] [--nodes 1500] [--cycles 3] [--seeds 1 2 3 4]
        [--jobs 2] [--threads 1] [--set KEY=VALUE]... [--protocol YAML]
        [--analyze build/analysis/apps/crumple-analyze] [--out-dir build/physics-check]
        [--json SUMMARY.json]
Exit code 0 when within the spread (or identical), 1 when outside or a run failed, 2 on bad
arguments.
"""
import argparse
import concurrent.futures
import csv
import hashlib
import json
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_run import check_binary, die, from_root, run_child, tail  # noqa: E402

QUANTITIES = [("crease_length_L0", "ℓ/L0"), ("perimeter_P", "P")]


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--new", default=from_root("build/sim/apps/crumple-sim"), help="crumple-sim with the change")
    ap.add_argument("--old", required=True, help="crumple-sim without it")
    ap.add_argument("--nodes", type=int, default=1500)
    ap.add_argument("--cycles", type=int, default=3)
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4])
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time")
    ap.add_argument("--threads", type=int, default=1, help="OpenMP threads per run")
    ap.add_argument("--protocol", default=from_root("protocols/axial_crumpling.yaml"))
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="passed on to crumple-sim (repeatable)")
    ap.add_argument("--analyze", default=from_root("build/analysis/apps/crumple-analyze"))
    ap.add_argument("--bootstrap", type=int, default=20,
                    help="crumple-analyze --bootstrap (l and P do not depend on it)")
    ap.add_argument("--out-dir", default=from_root("build/physics-check"))
    ap.add_argument("--json", help="write the comparison to this JSON file")
    a = ap.parse_args()
    if a.jobs < 1 or a.threads < 1:
        die("--jobs and --threads must be at least 1")
    return a


def sha1(path):
    h = hashlib.sha1()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def config_dir(a):
    """The folder of one configuration: extra --set values add a short hash of them."""
    name = f"n{a.nodes}_c{a.cycles}"
    if a.set:
        name += "_" + hashlib.sha1("\n".join(a.set).encode()).hexdigest()[:8]
    return os.path.join(a.out_dir, name)


# ---- runs ------------------------------------------------------------------------------------

def run_and_analyse(a, label, binary, folder, seed):
    """Runs one seed unless its run file exists (resuming a killed run), then analyses it unless
    its analysis exists. Returns a progress note; raises RuntimeError naming the log on failure."""
    run = os.path.join(folder, f"seed{seed}.h5")
    ana = os.path.join(folder, f"seed{seed}.analysis")
    notes = []
    if os.path.exists(run):
        notes.append("run kept")
    else:
        resume = os.path.exists(run + ".tmp")
        sidecar = os.path.splitext(run)[0] + ".xdmf"
        if os.path.exists(sidecar):  # left by a run file removed since; newer binaries refuse it
            os.remove(sidecar)
        cmd = [binary, a.protocol, "-o", run, "--seed", str(seed), "--threads", str(a.threads), "--quiet",
               "--set", f"mesh.nodes={a.nodes}", "--set", f"protocol.cycles={a.cycles}"]
        for s in a.set:
            cmd += ["--set", s]
        rc, wall, _ = run_child(cmd + (["--resume"] if resume else []), run + ".log")
        if rc != 0:
            raise RuntimeError(f"{label} seed {seed}: crumple-sim exited with {rc}; {run}.log ends:\n"
                               + tail(run + ".log"))
        notes.append(f"{'resumed and ran' if resume else 'ran'} in {wall:.1f} s")
    if os.path.exists(os.path.join(ana, "cycles.csv")):
        notes.append("analysis kept")
    else:
        part = ana + ".part"  # renamed when complete, so a killed analysis is redone
        shutil.rmtree(part, ignore_errors=True)
        rc, wall, _ = run_child([a.analyze, run, "-o", part, "--bootstrap", str(a.bootstrap)], ana + ".log")
        if rc != 0:
            raise RuntimeError(f"{label} seed {seed}: crumple-analyze exited with {rc}; {ana}.log ends:\n"
                               + tail(ana + ".log"))
        os.rename(part, ana)
        notes.append(f"analysed in {wall:.1f} s")
    return "; ".join(notes)


def run_all(a, binaries):
    """Every (binary, seed), old and new interleaved, a.jobs at a time."""
    tasks = [(label, binaries[label]["path"], binaries[label]["folder"], s)
             for s in a.seeds for label in ("old", "new")]
    failures = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_and_analyse, a, *t): t for t in tasks}
        for fut in concurrent.futures.as_completed(futures):
            label, _, _, seed = futures[fut]
            try:
                print(f"  {label} seed {seed}: {fut.result()}", flush=True)
            except RuntimeError as e:
                failures.append(str(e))
                print(f"  {label} seed {seed}: FAILED", flush=True)
    if failures:
        die("\n".join(failures), 1)


# ---- comparison ------------------------------------------------------------------------------

def read_cycles(folder, seed):
    with open(os.path.join(folder, f"seed{seed}.analysis", "cycles.csv")) as f:
        return {int(r["cycle"]): {k: float(r[k]) for k, _ in QUANTITIES} for r in csv.DictReader(f)}


def mean_sd(v):
    m = sum(v) / len(v)
    sd = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else None
    return m, sd


def compare(a, binaries):
    """One row per cycle and quantity: old and new mean and s.d., difference, in pooled s.d."""
    data = {label: [read_cycles(b["folder"], s) for s in a.seeds] for label, b in binaries.items()}
    cycles = sorted(set.intersection(*[set(c) for runs in data.values() for c in runs]))
    rows = []
    for n in cycles:
        for key, name in QUANTITIES:
            r = {"cycle": n, "quantity": key, "name": name}
            for label in ("old", "new"):
                r[label] = dict(zip(("mean", "sd"), mean_sd([run[n][key] for run in data[label]])))
            diff = r["new"]["mean"] - r["old"]["mean"]
            sds = (r["old"]["sd"], r["new"]["sd"])
            pooled = None if None in sds else math.sqrt((sds[0] ** 2 + sds[1] ** 2) / 2)
            if pooled:
                z = diff / pooled
            else:  # one seed (no spread), or no spread at all: only equality passes
                z = None if pooled is None else (0.0 if diff == 0 else math.copysign(math.inf, diff))
            r.update(diff=diff, pooled_sd=pooled, diff_over_sd=z)
            rows.append(r)
    identical = all(run_o == run_n for run_o, run_n in zip(data["old"], data["new"]))
    return rows, identical


def verdict(rows, identical):
    """(passed, line)."""
    if not rows:
        return False, "verdict: no cycle completed in every run: nothing to compare"
    if identical:
        return True, "verdict: identical: every seed gives the same ℓ/L0 and P at every cycle, old and new"
    if any(r["diff_over_sd"] is None for r in rows):
        return False, "verdict: undetermined: the seed-to-seed spread needs two seeds at least"
    worst = max(rows, key=lambda r: abs(r["diff_over_sd"]))
    where = f"largest {abs(worst['diff_over_sd']):.2f} s.d. at cycle {worst['cycle']} {worst['name']}"
    if abs(worst["diff_over_sd"]) <= 1:
        return True, ("verdict: within the seed-to-seed spread: |mean(new) - mean(old)| <= 1 pooled s.d. for "
                      f"ℓ/L0 and P at every cycle ({where})")
    return False, f"verdict: OUTSIDE the seed-to-seed spread: |mean(new) - mean(old)| > 1 pooled s.d. ({where})"


def print_table(rows):
    def ms(c):
        return f"{c['mean']:.4g} ± {c['sd']:.2g}" if c["sd"] is not None else f"{c['mean']:.4g}"
    print(f"{'cycle':>5}  {'':<5}  {'old mean ± s.d.':>18}  {'new mean ± s.d.':>18}  {'new - old':>10}  "
          f"{'in pooled s.d.':>14}")
    for r in rows:
        z = "-" if r["diff_over_sd"] is None else f"{r['diff_over_sd']:+.2f}"
        print(f"{r['cycle']:>5}  {r['name']:<5}  {ms(r['old']):>18}  {ms(r['new']):>18}  {r['diff']:>+10.3g}  {z:>14}")


def main():
    a = parse_args()
    for opt, path in (("--new", a.new), ("--old", a.old), ("--analyze", a.analyze)):
        check_binary(path, opt)
    binaries = {}
    for label, path in (("old", a.old), ("new", a.new)):
        digest = sha1(path)
        folder = os.path.join(config_dir(a), f"{label}_{digest[:12]}")
        os.makedirs(folder, exist_ok=True)
        binaries[label] = {"path": path, "sha1": digest, "folder": folder}
    print(f"physics check: {a.protocol}, {a.nodes} nodes, {a.cycles} cycle(s), seeds {' '.join(map(str, a.seeds))}, "
          f"{a.threads} thread(s) per run, {a.jobs} at a time" + (f", --set {' '.join(a.set)}" if a.set else ""))
    for label, b in binaries.items():
        print(f"  {label} = {b['path']} (sha1 {b['sha1'][:12]}): runs in {b['folder']}")
    run_all(a, binaries)
    rows, identical = compare(a, binaries)
    print_table(rows)
    passed, line = verdict(rows, identical)
    print(line)
    if a.json:
        os.makedirs(os.path.dirname(os.path.abspath(a.json)), exist_ok=True)
        with open(a.json, "w") as f:
            json.dump({"protocol": a.protocol, "nodes": a.nodes, "cycles": a.cycles, "seeds": a.seeds,
                       "sets": a.set, "binaries": binaries, "rows": rows, "identical": identical,
                       "passed": passed, "verdict": line}, f, indent=1)
        print(f"summary: {a.json}")
    sys.exit(0 if passed else 1)


if __name__ == "__main__":
    main()
