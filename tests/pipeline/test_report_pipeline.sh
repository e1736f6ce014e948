#!/usr/bin/env bash
# The report chain of `make reproduce` after the simulator, on synthetic run files
# (tests/analysis/make_synthetic_run.py, five cycles, three seeds): crumple-analyze per run, then
# the report rule of pipeline/reproduce.mk itself (`make report` with RUNDIR pointed at the
# synthetic runs: crumple-analyze ensemble, pipeline/plots/ensemble.py, the four plot scripts,
# make_report.py) and check_report.py. Checks that the report is complete; that its fit table and
# ensemble.csv show the numbers of the ensemble file (the scripts fit and average nothing
# themselves); that run files from before the compaction was recorded per cycle are reported
# without c1, c2, saying why; that the maps carry scale bars and colour keys that say what they
# show (the figure's objects, and the SVG's text); that FIG_FORMAT=svg gives .svg figures that the
# report links and leaves no .png figure behind, and a bad FIG_FORMAT or --format is refused
# (exit 2); and that the images index lists every image file in images/, check_report failing
# when it does not.
#   test_report_pipeline.sh CRUMPLE_ANALYZE   (run from the repository root)
set -euo pipefail
analyze="$1"
py=/usr/bin/python3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# make_report FOLDER [VAR=VALUE ...]: the report rule of pipeline/reproduce.mk on FOLDER/runs,
# writing FOLDER/results (a make of ours, not of whatever runs this test). The synthetic runs
# stand as they are (make -o): the preset's runs depend on their resolved configuration, which
# these files, not made by crumple-sim, do not store.
make_report() {
  local d="$1"
  shift
  local stand=()
  for s in 1 2 3; do stand+=(-o "$d/runs/seed$s.h5"); done
  env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make report PRESET=tiny SEEDS="1 2 3" \
    RUNDIR="$d/runs" RESULTS="$d/results" ANALYZE="$analyze" "${stand[@]}" "$@"
}

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
  make_report "$d" > "$d/make.log" 2>&1 || { cat "$d/make.log"; exit 1; }
  $py pipeline/report/check_report.py "$d/results/REPORT.md"
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
# A run whose protocol states its crease angle is reported with that rule (not "--threshold").
from make_report import rule_text
said = rule_text({"threshold": 0.318, "threshold_rule": {"kind": "crease_angle", "angle_deg": 18.3,
                                                         "angle_source": "config"}})
assert "a permanent fold of more than 18.3 degrees" in said and "output.crease_angle" in said, said
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

# The maps explain themselves: every map has a scale bar in cm and no pixel ticks, the crease
# colours and the facet areas have keys, and the facet colours are facets.csv's areas.
$py - "$dir/now/runs/seed1.analysis" <<'PY'
import csv, os, sys
import numpy as np
sys.path.insert(0, "pipeline/plots")
import plot_maps
from matplotlib.colors import LogNorm
from matplotlib.lines import Line2D
an = sys.argv[1]
fig, _ = plot_maps.draw(an, max_cycles=3)
maps = [ax for ax in fig.axes if ax.images]
assert len(maps) == 6, f"{len(maps)} map panels, expected 2 rows of 3"
for ax in maps:
    bars = [a for a in ax.get_children()
            if isinstance(a, Line2D) and (a.get_gid() or "").startswith("scale-bar")]
    labels = [t.get_text() for t in ax.texts if (t.get_gid() or "").startswith("scale-bar")]
    assert len(bars) == 1 and len(labels) == 1, (ax.get_title(), bars, labels)
    length = np.ptp(bars[0].get_xdata())  # the map's x axis is in cm
    value, unit = labels[0].split()
    assert unit in ("cm", "mm") and abs(float(value) / (10 if unit == "mm" else 1) - length) < 1e-9, \
        (labels[0], length)
    assert not ax.get_xticks().size and not ax.get_yticks().size, "pixel ticks on a map"
legend = [l for l in fig.legends if l.get_gid() == "crease-key"]
assert legend, "no key to the crease map's colours"
texts = [t.get_text() for t in legend[0].get_texts()]
for want in ("crease: p > 0.15", "crease: p < −0.15", "not creased", "outside the sheet", "facet boundary"):
    assert any(want in t for t in texts), (want, texts)
keys = [ax for ax in fig.axes if ax.get_gid() == "facet-area-key"]
assert len(keys) == 1 and "facet area (mm²" in keys[0].get_ylabel(), [ax.get_ylabel() for ax in fig.axes]
rows = {}
for r in csv.DictReader(open(os.path.join(an, "facets.csv"))):
    rows.setdefault(int(r["cycle"]), []).append(float(r["area_m2"]) * 1e6)
for ax, n in zip(maps[3:], (1, 3, 5)):
    im = ax.images[0]
    # the colour bar spans the panels' colour scale
    assert isinstance(im.norm, LogNorm) and np.allclose(keys[0].get_ylim(), (im.norm.vmin, im.norm.vmax))
    shown = np.unique(np.ma.compressed(im.get_array()))
    assert np.allclose(np.sort(shown), np.sort(np.unique(rows[n]))), \
        f"cycle {n}: the colours are not facets.csv's areas"
# Past some thousands of facets crumple-analyze's colours repeat: two facets that do not touch,
# painted alike, still get their own areas and boundaries.
from scipy import ndimage
p = plot_maps.load_panels(an, 5)[1][-1]
ref = plot_maps.facet_area_map(p["facets"], p["rows"])
rgb = plot_maps.rgb_uint8(p["facets"])
packed = (rgb[..., 0].astype(int) << 16) | (rgb[..., 1].astype(int) << 8) | rgb[..., 2]
colours = [c for c in np.unique(packed) if c != 0xFFFFFF]
sheet = packed != 0xFFFFFF  # every change of facet is on a boundary
edge = ref["edge"]
assert edge[1:][(packed[1:] != packed[:-1]) & sheet[1:]].all(), "facet boundaries missing"
assert edge[:, 1:][(packed[:, 1:] != packed[:, :-1]) & sheet[:, 1:]].all(), "facet boundaries missing"
c1, c2 = next((a, b) for a in colours for b in colours
              if a != b and not (ndimage.binary_dilation(packed == a) & (packed == b)).any())
rgb[packed == c2] = rgb[packed == c1][0]
got = plot_maps.facet_area_map(rgb, p["rows"])
assert np.allclose(got["area"], ref["area"], rtol=1e-9, equal_nan=True), "repeated colour: wrong areas"
assert np.array_equal(got["edge"], ref["edge"]) and not got["unmatched"].any()
# an image that is not of these facets keeps the analysis's colours, and the key says so
assert plot_maps.facet_area_map(p["facets"], p["rows"][:len(colours) // 3]) is None
needs = plot_maps.draw_facets(fig.add_axes([0, 0, 0.1, 0.1]), dict(p, areas=None), (0, 10, 0, 10), None)
assert any("arbitrary colours" in h.get_label() for h in plot_maps.figure_key(0.15, needs)), needs
print("maps: scale bars in cm, crease key, facet-area key with facets.csv's areas")
PY

# FIG_FORMAT=svg over the PNG report: SVG figures, linked, no PNG figure left; keys in the SVG.
make_report "$dir/now" FIG_FORMAT=svg > "$dir/make_svg.log" 2>&1 || { cat "$dir/make_svg.log"; exit 1; }
grep -q -- "plot_maps.py .*--format svg" "$dir/make_svg.log" ||
  { echo "changing FIG_FORMAT did not remake the report"; exit 1; }
$py pipeline/report/check_report.py "$dir/now/results/REPORT.md"
$py - "$dir/now/results" <<'PY'
import os, re, sys
out = sys.argv[1]
text = open(os.path.join(out, "REPORT.md")).read()
shown = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
figures = ("crease_length", "stages", "facets", "maps")
assert sorted(shown) == sorted(f"images/{f}.svg" for f in figures), shown
files = sorted(os.listdir(os.path.join(out, "images")))
assert not [f for f in files if f.endswith(".png") and not re.match(r"(crease|facets)_\d+\.png$", f)], files
svg = open(os.path.join(out, "images", "maps.svg")).read()
for want in ('id="scale-bar-0-0"', 'id="scale-bar-1-0"', 'id="crease-key"', 'id="facet-area-key"',
             "facet area (mm², log scale)", ">2 cm<", "crease: p &gt; 0.15"):
    assert want in svg, f"maps.svg lacks {want}"
for f in ("crease_length", "stages", "facets"):
    assert open(os.path.join(out, "images", f + ".svg")).read().lstrip().startswith("<?xml"), f
print("FIG_FORMAT=svg: SVG figures linked, no PNG figure left, keys in the SVG text")
PY

# Bad formats are refused before anything is written.
before=$(stat -c %Y "$dir/now/results/REPORT.md")
for bad in jpg "png svg" ""; do
  set +e
  msg=$(make_report "$dir/now" FIG_FORMAT="$bad" 2>&1)
  rc=$?
  set -e
  [ $rc -eq 2 ] || { echo "FIG_FORMAT='$bad': exit $rc, expected 2"; exit 1; }
  echo "$msg" | grep -q "FIG_FORMAT='$bad': choose png" || { echo "FIG_FORMAT='$bad': $msg"; exit 1; }
done
[ "$(stat -c %Y "$dir/now/results/REPORT.md")" = "$before" ] || { echo "a refused FIG_FORMAT wrote"; exit 1; }
for args in "-o $dir/x.png --format jpg" "-o $dir/x.png --format svg" "-o $dir/x.jpg"; do
  set +e
  msg=$($py pipeline/plots/plot_stages.py "$dir/now/results/ensemble.json" $args 2>&1)
  rc=$?
  set -e
  [ $rc -eq 2 ] || { echo "plot_stages.py $args: exit $rc, expected 2"; exit 1; }
  echo "$msg" | grep -q "format\|\.jpg" || { echo "plot_stages.py $args: $msg"; exit 1; }
done
[ ! -e "$dir/x.png" ] && [ ! -e "$dir/x.svg" ] || { echo "a refused --format wrote a figure"; exit 1; }
echo "bad FIG_FORMAT and --format refused with exit 2"

# The images index lists every image file in images/, also in a copy of the folder; a file it
# does not list, an index that is not the last section, or an absolute link fail check_report.
cp -r "$dir/now/results" "$dir/copy"
$py pipeline/report/check_report.py "$dir/copy/REPORT.md" > /dev/null
$py - "$dir/copy" <<'PY'
import os, re, sys
out = sys.argv[1]
text = open(os.path.join(out, "REPORT.md")).read()
index = text[text.index("\n## Images\n"):]
listed = re.findall(r"^\| \[([^\]]+)\]\(images/([^)]+)\) \| (.+) \|$", index, re.M)
assert all(a == b and len(c) > 20 for a, b, c in listed), listed
assert sorted(b for _, b, _ in listed) == sorted(os.listdir(os.path.join(out, "images"))), listed
assert len(listed) == 4 + 2 * 5, len(listed)
print(f"images index: all {len(listed)} files in images/, each with a caption")
PY
expect_incomplete() {  # expect_incomplete WHAT PATTERN: check_report exits 2 naming PATTERN
  set +e
  msg=$($py pipeline/report/check_report.py "$dir/copy/REPORT.md" 2>&1)
  rc=$?
  set -e
  [ $rc -eq 2 ] || { echo "$1: check_report exit $rc, expected 2"; exit 1; }
  echo "$msg" | grep -q "$2" || { echo "$1: $msg"; exit 1; }
}
cp "$dir/copy/images/maps.svg" "$dir/copy/images/extra.svg"
expect_incomplete "unlisted image" "index lacks files .*extra.svg"
rm "$dir/copy/images/extra.svg"
cp "$dir/copy/REPORT.md" "$dir/REPORT.md.good"
printf '\n## Afterword\n\nText.\n' >> "$dir/copy/REPORT.md"
expect_incomplete "index not last" "is not the last section"
sed "s#](images/stages.svg)#]($dir/copy/images/stages.svg)#" "$dir/REPORT.md.good" > "$dir/copy/REPORT.md"
expect_incomplete "absolute link" "not relative"
sed '/^## Images$/,$d' "$dir/REPORT.md.good" > "$dir/copy/REPORT.md"
expect_incomplete "no index" "no images index"
echo "check_report refuses an incomplete index and absolute links"

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
echo "7 passed, 0 failed"
