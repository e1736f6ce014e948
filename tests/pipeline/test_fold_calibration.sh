#!/usr/bin/env bash
# make calibrate's script end to end on tiny sheets: four single-fold runs (two resolutions, two
# yield radii) through crumple-sim, then pipeline/calibration/fold_calibration.py; checks its
# outputs, that c_f falls with c0 (as the yield radius shrinks), that each run's c0 is the one its
# mesh derived from the yield radius, and that bad input exits 2 with a message.
#   test_fold_calibration.sh CRUMPLE_SIM   (run from the repository root)
set -euo pipefail
sim="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for n in 80 160; do
  for r in 40 10; do
    "$sim" protocols/single_fold.yaml -o "$dir/fold_n${n}_r${r}mm.h5" --quiet --threads 1 \
      --set mesh.nodes=$n --set material.yield_radius=${r}e-3
  done
done
/usr/bin/python3 pipeline/calibration/fold_calibration.py -o "$dir/out" "$dir"/fold_*.h5
for f in fold_calibration.csv fold_calibration.png FOLD_CALIBRATION.md; do
  [ -s "$dir/out/$f" ] || { echo "missing $f"; exit 1; }
done
[ "$(grep -c '^fold_n' "$dir/out/fold_calibration.csv")" -eq 4 ] || { echo "expected 4 rows"; exit 1; }
# c_f falls with c0 at each resolution (the CSV's '#' lines are comments, as in data/).
/usr/bin/python3 - "$dir/out/fold_calibration.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
for n in {r["nodes"] for r in rows}:
    rr = sorted((float(r["c0"]), float(r["c_f"])) for r in rows if r["nodes"] == n)
    assert rr[0][1] > rr[1][1] + 0.1, (n, rr)
# c0 ~ w / R_y: a quarter of the radius, about four times the hinge yield on each mesh.
for n in {r["nodes"] for r in rows}:
    c0 = {float(r["yield_radius_mm"]): float(r["c0"]) for r in rows if r["nodes"] == n}
    assert 3.5 < c0[10] / c0[40] < 4.5, (n, c0)
print("c_f falls with c0 at both resolutions; c0 scales as 1 / R_y")
PY
# Bad input: a missing run file exits 2 and names it.
set +e
msg=$(/usr/bin/python3 pipeline/calibration/fold_calibration.py -o "$dir/bad" "$dir/nope.h5" 2>&1)
rc=$?
set -e
[ $rc -eq 2 ] || { echo "missing input: exit $rc, expected 2"; exit 1; }
echo "$msg" | grep -q "nope.h5" || { echo "message does not name the file: $msg"; exit 1; }
echo "1 passed, 0 failed"
