#!/usr/bin/env bash
# The Slurm path against a real Slurm (`make test-slurm`, run by .ci/run): installs Debian's
# slurmctld, slurmd, slurm-client and munge if missing, starts a one-node cluster on this machine
# (local_cluster.sh), and
#   1. runs the tiny sweep locally and through Slurm (`make sweep SWEEP=tiny SCHEDULER=slurm`)
#      and checks that every run file's end-of-cycle states and the collapse fit are identical;
#   2. stops one run of a Slurm submission with SIGTERM (what Slurm sends at a time limit):
#      the submission must fail (its report job cancelled, not left pending), the run must keep
#      its checkpoint, and submitting again must run only what is unfinished, resume the
#      stopped run from its checkpoint and end with the local path's results;
# then stops the daemons it started, by their pid files. Prints the walls of both paths.
#   tests/slurm/test_slurm.sh [SCRATCH]   (from the repository root, after make build)
set -euo pipefail
[ -n "${TEST_SLURM_TRACE:-}" ] && set -x
cd "$(dirname "$0")/../.."
T=$(realpath -m "${1:-build/test-slurm}")
rm -rf "$T"; mkdir -p "$T"
CLUSTER="$T/cluster"
tests/slurm/local_cluster.sh install
trap 'tests/slurm/local_cluster.sh stop "$CLUSTER"' EXIT
tests/slurm/local_cluster.sh start "$CLUSTER"
export SLURM_CONF="$CLUSTER/slurm.conf"
PY=/usr/bin/python3
sweep() {  # NAME [make args...]: the tiny sweep kept in $T/NAME
  local name=$1; shift
  make --no-print-directory sweep SWEEP=tiny SWEEP_DIR="$T/$name/runs" \
    SWEEP_RESULTS="$T/$name/results" "$@"
}
now() { date +%s.%N; }

t0=$(now); sweep local > "$T/local.log" 2>&1 || { tail -20 "$T/local.log"; exit 1; }
t1=$(now); sweep slurm SCHEDULER=slurm SLURM_WAIT=1 > "$T/slurm.log" 2>&1 \
  || { tail -20 "$T/slurm.log"; exit 1; }
t2=$(now)
grep -q "array job" "$T/slurm.log" || { echo "FAIL: no array job submitted"; exit 1; }
compare() {  # A B: the run files and the collapse of two sweeps agree exactly
  $PY - "$1" "$2" <<'PYEOF'
import glob, json, os, sys
import h5py, numpy as np
a, b = sys.argv[1:]
runs = sorted(os.path.relpath(p, a) for p in glob.glob(f"{a}/runs/*/seed*.h5"))
assert len(runs) == 4, runs
for r in runs:
    with h5py.File(f"{a}/{r}") as fa, h5py.File(f"{b}/{r}") as fb:
        assert list(fa["cycles"]) == list(fb["cycles"]), r
        for c in fa["cycles"]:
            for k in ("x", "p"):
                assert np.array_equal(fa[f"cycles/{c}/{k}"][()], fb[f"cycles/{c}/{k}"][()]), (r, c, k)
ca, cb = (json.load(open(f"{d}/results/collapse.json"))["fits"] for d in (a, b))
assert ca == cb, "collapse fits differ"
print(f"same results: {len(runs)} runs and the collapse fit of {a} and {b}")
PYEOF
}
compare "$T/local" "$T/slurm"

# A run stopped by SIGTERM: the submission fails and nothing is left pending.
sweep fail SCHEDULER=slurm SLURM_WAIT=1 > "$T/fail.log" 2>&1 &
submit=$!
for _ in $(seq 600); do
  ls "$T"/fail/runs/*/seed*.h5.tmp > /dev/null 2>&1 && break
  sleep 0.1
done
array=$(sed -n 's/.*array job \([0-9]*\).*/\1/p' "$T/fail.log")
[ -n "$array" ] || { echo "FAIL: no array job"; cat "$T/fail.log"; exit 1; }
tmp=$(ls "$T"/fail/runs/*/seed*.h5.tmp | head -1)
# The array element that runs this file: its log names the target.
task=$(grep -l "$(basename "$(dirname "$tmp")")/$(basename "$tmp" .h5.tmp).analysis" \
  "$T"/fail/runs/slurm/"${array}"_*.out | head -1 | sed 's/.*_\([0-9]*\)\.out/\1/')
# (scancel may report an error when the element ends at once on the signal; what follows checks the effect.)
scancel --batch --signal=TERM "${array}_${task}" || true
if wait "$submit"; then echo "FAIL: a submission with a stopped run succeeded"; exit 1; fi
grep -q "final job .*CANCELLED" "$T/fail.log" || { echo "FAIL: the report job was not cancelled"; cat "$T/fail.log"; exit 1; }
[ -f "$tmp" ] || { echo "FAIL: the stopped run lost its checkpoint $tmp"; exit 1; }
[ -z "$(squeue -h)" ] || { echo "FAIL: jobs left in the queue:"; squeue; exit 1; }
echo "a run stopped by SIGTERM (task $task) failed the submission; checkpoint kept: $tmp"

# Submitting again runs only what is unfinished and resumes the stopped run.
sweep fail SCHEDULER=slurm SLURM_WAIT=1 > "$T/resubmit.log" 2>&1 || { tail -20 "$T/resubmit.log"; exit 1; }
grep -q "runs to do" "$T/resubmit.log"
todo=$(sed -n 's/.*submit: \([0-9]*\) of 4 runs to do.*/\1/p' "$T/resubmit.log")
[ "$todo" -ge 1 ] && [ "$todo" -lt 4 ] || { echo "FAIL: resubmitted $todo of 4 runs"; exit 1; }
# (The rule's text names --resume whichever way it goes: the run file says whether it resumed.)
$PY -c 'import h5py, sys; sys.exit(0 if len(h5py.File(sys.argv[1], "r")["resumes"]) else 1)' \
  "${tmp%.tmp}" || { echo "FAIL: the stopped run did not resume (${tmp%.tmp}: /resumes empty)"; exit 1; }
compare "$T/local" "$T/fail"
printf 'tiny sweep wall: local %.1f s, through Slurm %.1f s (one node, %d CPUs)\n' \
  "$(echo "$t1 - $t0" | bc)" "$(echo "$t2 - $t1" | bc)" "$(nproc)"
echo "test_slurm: OK"
