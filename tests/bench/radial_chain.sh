#!/usr/bin/env bash
# A long bench_radial interval timed in pieces that survive interruptions.
#
# At 12000 nodes the hybrid alone needs hours of a quiet machine for one simulated second in
# dense self-contact, more than one sitting. This driver cuts [from, to] into pieces of `piece`
# seconds; each piece is one bench_radial run (--variants block-jacobi: explicit-only over the
# first --span of the piece, scaled, then the block-Jacobi-18 hybrid over the whole piece),
# started from the state the previous piece's hybrid ended in (--warm-state / --save-end; with
# --require-warm, so that a missing or mismatched state stops the chain instead of warming up). A
# piece that completes leaves piece_T.log and piece_T.done in the chain directory; rerunning the
# same command skips finished pieces and redoes an interrupted one from its start. The first
# piece warms up from --seed (a warm state file from before `from`, bench_radial --warm-state)
# or from rest, resumably too.
#
# The chain directory keeps a copy of the bench_radial it started with, and every piece runs
# that copy. Each piece restarts the hybrid with a fresh integrator (BDF order 1, the switching
# average empty), which a single run would not do: the summary counts the pieces so that this
# can be weighed.
#
#   tests/bench/radial_chain.sh [--nodes 12000] [--from 3] [--to 4] [--piece 0.05]
#                               [--span 0.002] [--threads 2] [--dir build/radial_chain_NODES]
#                               [--seed FILE] [--thickness MM]
#                               [--bench build/tests/bench/bench_radial] [--record DIR]
#                               [--summary]
# --thickness is passed to bench_radial (its default when absent, 0.125 mm) and names the default
# directory of any other sheet, build/radial_chain_NODES_hMM (also for --summary).
# --summary prints the totals over the finished pieces without running anything, and for an
# unfinished chain a projection of the whole interval at the rate of the finished pieces (with
# --record, the record's pieces count as finished).
# --record DIR keeps the chain in a directory meant for the sources (tests/bench/records), so
# that it survives the machine: it holds the finished pieces' logs, the start state of the next
# piece (before the first piece is done, the warm-up's progress: the first piece warms up in the
# record), the checksum of the chain's bench_radial and the chain's parameters. A chain directory
# that lacks what the record holds is filled from it before anything runs, and a record that
# lacks what the directory holds is brought up to it. A record is refused to another
# bench_radial (build the commit named in the record's README and pass that program with
# --bench) and to other parameters.
set -euo pipefail

nodes=12000 from=3 to=4 piece=0.05 span=0.002 threads=2 dir="" seed="" thickness="" summary_only=0 record=""
bench=build/tests/bench/bench_radial
while [ $# -gt 0 ]; do
  case "$1" in
    --nodes) nodes=$2; shift 2 ;;
    --from) from=$2; shift 2 ;;
    --to) to=$2; shift 2 ;;
    --piece) piece=$2; shift 2 ;;
    --span) span=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --dir) dir=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --thickness) thickness=$2; shift 2 ;;
    --bench) bench=$2; shift 2 ;;
    --record) record=$2; shift 2 ;;
    --summary) summary_only=1; shift ;;
    *) echo "radial_chain.sh: unknown argument '$1' (see the header of $0)" >&2; exit 2 ;;
  esac
done
# One spelling of a number (0.25 = 0.250, 3 = 3.0), so one per sheet; the default sheet keeps the
# plain name and flags.
num() { awk -v x="$1" 'BEGIN { printf "%g", x }'; }
[ -n "$thickness" ] && thickness=$(num "$thickness")
[ "$thickness" = 0.125 ] && thickness=""
dir=${dir:-build/radial_chain_$nodes${thickness:+_h$thickness}}
sheet=()
[ -n "$thickness" ] && sheet=(--thickness "$thickness")
# Piece times are named and passed with four decimals: from and piece must be whole multiples
# of 1e-4 s and [from, to] a whole number of pieces.
npieces=$(awk -v a="$from" -v b="$to" -v p="$piece" 'BEGIN {
  n = (b - a) / p
  if (p <= 0 || n < 0.5 || (n - int(n + 0.5))^2 > 1e-12 ||
      (a * 1e4 - int(a * 1e4 + 0.5))^2 > 1e-12 || (p * 1e4 - int(p * 1e4 + 0.5))^2 > 1e-12)
    print "bad"
  else
    printf "%d", n + 0.5 }')
if [ "$npieces" = bad ]; then
  echo "radial_chain.sh: [$from, $to] must be a whole number (>= 1) of pieces of $piece s, and" \
    "--from and --piece multiples of 0.0001 s" >&2
  exit 2
fi
# The start of piece k, as passed to bench_radial and used in file names.
piece_start() { awk -v a="$from" -v p="$piece" -v k="$1" 'BEGIN { printf "%.4f", a + k * p }'; }

summary() {
  local logs=()
  for ((k = 0; k < npieces; ++k)); do
    local t
    t=$(piece_start "$k")
    if [ -f "$dir/piece_$t.done" ]; then
      logs+=("$dir/piece_$t.log")
    elif [ -n "$record" ] && [ -f "$record/piece_$t.log" ]; then
      logs+=("$record/piece_$t.log")
    fi
  done
  if [ ${#logs[@]} -eq 0 ]; then
    echo "no finished piece in $dir${record:+ or $record}"
    return 0
  fi
  # The "totals:" line after each variant's line holds, in order: measured wall, time covered,
  # steps, explicit steps, switches, implicit attempts, Newton and CG iterations, rejections
  # (error, Newton, not SPD, other), wall implicit, linear, explicit.
  awk -v npieces="$npieces" -v from="$from" -v to="$to" '
    /^explicit only/ { v = "E" }
    /^hybrid, CG \+ block Jacobi 18 / { v = "H" }
    /^ +totals:/ {
      n = 0
      delete x
      for (i = 2; i <= NF; ++i) { f = $i; sub(/,$/, "", f); if (f ~ /^[0-9.eE+-]+$/) x[++n] = f }
      if (n != 15) { printf "unexpected totals line: %s\n", $0 > "/dev/stderr"; exit 1 }
      for (i = 1; i <= n; ++i) sum[v, i] += x[i]
      ms = x[3] > 0 ? 1e3 * x[1] / x[3] : 0
      if (v == "H") { ++pieces; row[pieces] = sprintf("%8.1f %9d %9d %8d %10.2f", x[1], x[3], x[4], x[5], ms) }
      else          { erow[pieces + 1] = sprintf("%10.2f", ms) }
      v = ""
    }
    /^interval \[/ { s = $0; sub(/.*\[/, "", s); sub(/\].*/, "", s); ivs[pieces + 1] = "[" s "]" }
    END {
      printf "%-18s %8s %9s %9s %8s %10s %12s\n", "piece", "wall [s]", "steps", "explicit", "switches", "ms/step", "expl. ms/step"
      for (i = 1; i <= pieces; ++i) printf "%-18s %s %12s\n", ivs[i], row[i], erow[i]
      printf "\n%d of %d pieces finished, %g s of simulated time\n", pieces, npieces, sum["H", 2]
      printf "hybrid, block Jacobi 18: %.1f s wall, %d steps (%d explicit), %d switches, %.2f Newton per implicit attempt, %.1f CG per Newton, rejected %d / %d / %d / %d (error / Newton / not SPD / other); wall implicit %.1f s (linear %.1f), explicit %.1f s\n", \
        sum["H", 1], sum["H", 3], sum["H", 4], sum["H", 5], \
        sum["H", 6] ? sum["H", 7] / sum["H", 6] : 0, sum["H", 7] ? sum["H", 8] / sum["H", 7] : 0, \
        sum["H", 9], sum["H", 10], sum["H", 11], sum["H", 12], sum["H", 13], sum["H", 14], sum["H", 15]
      if (sum["E", 2] > 0) {
        scaled = sum["E", 1] / sum["E", 2] * sum["H", 2]
        printf "explicit only: %.1f s wall over %d spans (%g s, %d steps), scaled to the finished pieces: %.1f s\n", \
          sum["E", 1], pieces, sum["E", 2], sum["E", 3], scaled
        printf "speed-up of the hybrid over the finished pieces: %.2fx\n", scaled / sum["H", 1]
      }
      # An unfinished chain: the whole interval at the rate of the finished pieces (an
      # estimate: how often the sheet snaps through changes along the interval).
      if (pieces < npieces && sum["H", 2] > 0) {
        whole = to - from
        printf "projected to the whole [%g, %g] at the rate of the finished pieces: hybrid %.0f s", from, to, sum["H", 1] / sum["H", 2] * whole
        if (sum["E", 2] > 0) printf ", explicit only %.0f s", sum["E", 1] / sum["E", 2] * whole
        printf "\n"
      }
    }' "${logs[@]}"
}

if [ "$summary_only" = 1 ]; then
  summary
  exit 0
fi
mkdir -p "$dir"
sum_of() { sha256sum "$1" | cut -d' ' -f1; }
# Copies a file so that the copy is never seen half written.
copy_whole() { cp "$1" "$2.part" && mv "$2.part" "$2"; }
to_record() { copy_whole "$1" "$record/$2"; }
# Brings the record up to the chain directory (a piece finished before --record was given, or a
# run stopped halfway through this): every finished piece's log, and of the states only the start
# of the first unfinished piece. That state goes in before the logs, so that a record caught in
# between still holds the start of every piece it does not count as finished.
sync_record() {
  local k t next=""
  for ((k = 0; k < npieces; ++k)); do
    t=$(piece_start "$k")
    if [ ! -f "$dir/piece_$t.done" ]; then next=$t; break; fi
  done
  [ -n "$next" ] || next=$(piece_start "$npieces")
  if [ ! -f "$record/state_$next.h5" ] && [ -f "$dir/state_$next.h5" ]; then
    to_record "$dir/state_$next.h5" "state_$next.h5"
  fi
  for ((k = 0; k < npieces; ++k)); do
    t=$(piece_start "$k")
    if [ -f "$dir/piece_$t.done" ] && [ ! -f "$record/piece_$t.log" ]; then
      to_record "$dir/piece_$t.log" "piece_$t.log"
    fi
  done
  [ -f "$record/state_$next.h5" ] || return 0
  local f
  for f in "$record"/state_*.h5; do
    if [ -e "$f" ] && [ "$f" != "$record/state_$next.h5" ]; then rm -f "$f"; fi
  done
}
# Every piece runs the same program: the chain keeps its own copy of bench_radial from its first
# run (a rebuild meanwhile does not mix two versions into one figure; a new chain directory
# takes the new one).
program=$bench
[ -x "$dir/bench_radial" ] && program=$dir/bench_radial
[ -x "$program" ] || { echo "radial_chain.sh: $program not found (make build)" >&2; exit 2; }
if [ -n "$record" ]; then
  # A record goes on only with its own program and parameters (all but --to: a chain may be
  # extended), checked before anything is copied or run.
  args="nodes $nodes, thickness ${thickness:-0.125} mm, pieces from $(num "$from") s of $(num "$piece") s, explicit-only span $(num "$span") s, $threads threads"
  if [ -f "$record/program.sha256" ] && [ "$(cat "$record/program.sha256")" != "$(sum_of "$program")" ]; then
    echo "radial_chain.sh: $record was measured with another bench_radial than $program (sha256" \
      "$(cat "$record/program.sha256")); build the commit its README names and pass that program" \
      "with --bench" >&2
    if [ "$program" != "$bench" ]; then
      echo "  ($dir keeps its own copy of another program: give a new --dir as well)" >&2
    fi
    exit 2
  fi
  if [ -f "$record/chain.args" ] && [ "$(cat "$record/chain.args")" != "$args" ]; then
    echo "radial_chain.sh: $record holds the chain of $(cat "$record/chain.args"), not $args" >&2
    exit 2
  fi
fi
[ "$program" = "$dir/bench_radial" ] || copy_whole "$bench" "$dir/bench_radial"
if [ -n "$record" ]; then
  mkdir -p "$record"
  [ -f "$record/program.sha256" ] || sum_of "$dir/bench_radial" >"$record/program.sha256"
  [ -f "$record/chain.args" ] || echo "$args" >"$record/chain.args"
  for f in "$record"/piece_*.log; do
    [ -e "$f" ] || continue
    b=$(basename "$f" .log)
    if [ ! -f "$dir/$b.done" ]; then
      copy_whole "$f" "$dir/$b.log"
      touch "$dir/$b.done"
    fi
  done
  for f in "$record"/state_*.h5; do
    if [ -e "$f" ] && [ ! -f "$dir/$(basename "$f")" ]; then copy_whole "$f" "$dir/$(basename "$f")"; fi
  done
fi
first=$(piece_start 0)
if [ -n "$seed" ] && [ ! -f "$dir/state_$first.h5" ]; then
  copy_whole "$seed" "$dir/state_$first.h5"
fi
[ -z "$record" ] || sync_record
for ((k = 0; k < npieces; ++k)); do
  t=$(piece_start "$k")
  t1=$(piece_start $((k + 1)))
  [ -f "$dir/piece_$t.done" ] && continue
  # Only the first piece may warm up; a later one must start from the previous piece's end.
  warm=()
  if [ "$k" -gt 0 ]; then
    if [ ! -f "$dir/state_$t.h5" ]; then
      echo "radial_chain.sh: $dir/state_$t.h5 missing (the piece before did not finish)" >&2
      exit 1
    fi
    warm=(--require-warm)
  fi
  # A recorded chain warms up in its record, which so keeps the warm-up's progress (every 5 ms of
  # simulated time) when the machine goes before the first piece is done.
  start="$dir/state_$t.h5"
  if [ "$k" -eq 0 ] && [ -n "$record" ]; then start="$record/state_$t.h5"; fi
  echo "== piece [$t, $t1] at $nodes nodes -> $dir/piece_$t.log"
  if ! "$dir/bench_radial" --nodes "$nodes" "${sheet[@]}" --threads "$threads" --t0 "$t" --dt "$piece" \
      --variants block-jacobi --explicit-span "$span" --warm-state "$start" "${warm[@]}" \
      --save-end "$dir/state_$t1.h5" --progress >"$dir/piece_$t.log.part" 2>&1; then
    echo "radial_chain.sh: bench_radial failed on [$t, $t1]; see $dir/piece_$t.log.part" >&2
    exit 1
  fi
  if [ "$(grep -c '^ *totals:' "$dir/piece_$t.log.part")" -ne 2 ] || [ ! -f "$dir/state_$t1.h5" ]; then
    echo "radial_chain.sh: [$t, $t1] ended without both variants' totals and its end state;" \
      "see $dir/piece_$t.log.part" >&2
    exit 1
  fi
  mv "$dir/piece_$t.log.part" "$dir/piece_$t.log"
  touch "$dir/piece_$t.done"
  [ -z "$record" ] || sync_record
done
summary
