#!/usr/bin/env bash
# The report chain of `make reproduce` after the simulator, on synthetic run files
# (tests/analysis/make_synthetic_run.py, five cycles, three seeds): crumple-analyze per run,
# crumple-analyze ensemble, pipeline/plots/ensemble.py, the four plot scripts, make_report.py
# and check_report.py. Checks that the report is complete; that its fit table and ensemble.csv
# show the numbers of the ensemble file (the scripts fit and average nothing themselves); and
# that run files from before the compaction was recorded per cycle are reported without c1, c2,
# saying why.
#   test_report_pipeline.sh CRUMPLE_ANALYZE   (run from the repository root)
set -euo pipefail
analyze="$1"
py=/usr/bin/python3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# report FOLDER RUN_FLAGS: synthetic runs, their analyses and the whole report chain in FOLDER.
report() {
  local d="$1"
  shift
  mkdir -p "$d/runs"
  for s in 1 2 3; do
    $py tests/analysis/make_synthetic_run.py "$d/runs/seed$s.h5" --seed $s --cycles 5 --k 32 \
      --c0 0.3 --stage-ends --compaction 0.36 "$@" > /dev/null
    "$analyze" "$d/runs/seed$s.h5" --bootstrap 20 > /dev/null 2>&1
  done
  local out="$d/results"
  "$analyze" ensemble -o "$out/ensemble.json" "$d"/runs/seed{1,2,3}.analysis > /dev/null
  $py pipeline/plots/ensemble.py "$out/ensemble.json" > /dev/null
  for p in crease_length stages facets; do
    $py pipeline/plots/plot_$p.py "$out/ensemble.json" -o "$out/$p.png" > /dev/null
  done
  $py pipeline/plots/plot_maps.py "$d/runs/seed1.analysis" -o "$out/maps.png" > /dev/null
  $py pipeline/report/make_report.py --ensemble "$out/ensemble.json" --runs "$d/runs/seed1.analysis" \
    --preset synthetic --protocol protocols/axial_crumpling.yaml -o "$out/REPORT.md" > /dev/null
  $py pipeline/report/check_report.py "$out/REPORT.md"
}

report "$dir/now"
$py - "$dir/now/results" <<'PY'
import csv, json, math, os, sys
sys.path.insert(0, "pipeline/report")
sys.path.insert(0, "pipeline/plots")
from make_report import pm  # the report's own number format
from common import law_constants
out = sys.argv[1]
e = json.load(open(os.path.join(out, "ensemble.json")))
text = open(os.path.join(out, "REPORT.md")).read()
assert e["compaction"] == 0.36, e["compaction"]
for q, name in (("perimeter_P", "P"), ("crease_length_L0", "ℓ/L0")):
    for kind in ("increments", "cumulative"):
        f = e["fits"][q][kind]
        assert "C" in f, (q, kind, f)
        assert f["weighted"], (q, kind)
        cells = f"| {pm(f['C'], f['sigma_C'])} | {pm(f['n0'], f['sigma_n0'])} |"
        assert cells in text, f"report lacks the {q} {kind} fit {cells}"
        assert pm(f["c1"], f["sigma_c1"]) in text, (q, kind, "c1")
rows = list(csv.DictReader(open(os.path.join(out, "ensemble.csv"))))
assert [int(r["cycle"]) for r in rows] == [c["cycle"] for c in e["cycles"]]
c1, c2 = law_constants()
D = e["compaction"]
for r, c in zip(rows, e["cycles"]):
    for k in ("perimeter_P_mean", "perimeter_P_sem", "crease_length_L0_increment_std"):
        assert math.isclose(float(r[k]), c[k], rel_tol=1e-12), (k, r[k], c[k])
    n = c["cycle"]
    assert math.isclose(float(r["law"]), c1 * (1 - D) * math.log(1 + c2 * n / D), rel_tol=1e-12)
print("report, ensemble.csv and ensemble.json agree")
PY

# Run files from before /cycles/NNNN@compaction: analysed and reported, without c1, c2.
report "$dir/old" --no-compaction-record
$py - "$dir/old/results" <<'PY'
import json, os, sys
out = sys.argv[1]
e = json.load(open(os.path.join(out, "ensemble.json")))
assert e["compaction"] is None, e["compaction"]
assert "records no compaction ratio" in e["compaction_note"], e["compaction_note"]
assert "c1" not in e["fits"]["perimeter_P"]["increments"]
text = open(os.path.join(out, "REPORT.md")).read()
assert "records no compaction ratio" in text, "the report does not say why c1, c2 are missing"
print("older run files: no compaction, and the report says why")
PY

# Bad input: ensemble.py on a file that is not an ensemble file exits 2 and names it.
echo '{"cycles": []}' > "$dir/not_ensemble.json"
set +e
msg=$($py pipeline/plots/ensemble.py "$dir/not_ensemble.json" 2>&1)
rc=$?
set -e
[ $rc -eq 2 ] || { echo "not an ensemble file: exit $rc, expected 2"; exit 1; }
echo "$msg" | grep -q "not_ensemble.json" || { echo "message does not name the file: $msg"; exit 1; }
echo "3 passed, 0 failed"
