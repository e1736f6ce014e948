#!/usr/bin/env bash
# tests/bench/radial_chain.sh on a 100-node sheet: pieces chain through their end states (whose
# times land above, on or below the next piece's decimal start), a rerun skips finished pieces
# and redoes an unfinished one, the summary sums the pieces (and projects an unfinished chain),
# --record keeps the chain where it survives the build directory, and --thickness and --mesh-seed
# keep sheets apart.
#   test_radial_chain.sh BENCH_RADIAL
set -euo pipefail
bench=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# 0.05 + 0.01 is a hair above 0.06 in binary, 0.06 + 0.01 a hair below 0.07.
chain() { tests/bench/radial_chain.sh --bench "$bench" --nodes 100 --from 0.05 --to 0.08 \
  --piece 0.01 --span 0.0005 --dir "$dir/chain" "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

out=$(chain)
for t in 0.0500 0.0600 0.0700; do
  [ -f "$dir/chain/piece_$t.done" ] || fail "piece $t not finished: $out"
done
for t in 0.06 0.07; do
  grep -q "warm state at t0 = $t s read from" "$dir/chain/piece_${t}00.log" ||
    fail "the piece from $t did not start from the previous piece's end state"
done
# The hybrid's steps in the summary against the pieces' own totals lines.
steps=$(awk '/^hybrid, CG \+ block Jacobi 18 /{h=1} /^ +totals:/{if(h){gsub(",","");s+=$9}; h=0} END{print s}' \
  "$dir"/chain/piece_*.log)
grep -q "3 of 3 pieces finished" <<<"$out" || fail "summary: $out"
grep -q "hybrid, block Jacobi 18: .* s wall, $steps steps" <<<"$out" ||
  fail "summary does not sum the pieces' $steps steps: $out"
grep -q "explicit only: .* over 3 spans" <<<"$out" || fail "explicit-only spans: $out"
grep -q "projected" <<<"$out" && fail "a finished chain was projected: $out"

# A rerun runs nothing; an unfinished piece is redone, alone, and the chain is whole again.
out=$(chain)
grep -q "== piece" <<<"$out" && fail "a rerun ran a finished piece again: $out"
rm "$dir/chain/piece_0.0600.done"
out=$(chain)
[ "$(grep -c "== piece" <<<"$out")" = 1 ] || fail "expected one piece redone: $out"
[ -f "$dir/chain/piece_0.0600.done" ] || fail "the redone piece did not finish"
grep -q "3 of 3 pieces finished" <<<"$out" || fail "summary after the redo: $out"

# --record: after each piece the record holds the finished logs and only the next start state;
# a new chain directory is filled from it and runs only what it lacks, and so does --summary.
rec=$dir/record
chain --dir "$dir/r1" --record "$rec" --to 0.07 --seed "$dir/chain/state_0.0500.h5" >/dev/null ||
  fail "the recorded chain failed"
listing() { (cd "$1" && echo *); }
[ "$(listing "$rec")" = "chain.args piece_0.0500.log piece_0.0600.log program.sha256 state_0.0700.h5" ] ||
  fail "record after two pieces: $(listing "$rec")"
out=$(chain --dir "$dir/r2" --record "$rec")
[ "$(grep -c "== piece" <<<"$out")" = 1 ] && grep -q "== piece \[0.0700, 0.0800\]" <<<"$out" ||
  fail "a chain from the record did not run just the missing piece: $out"
grep -q "warm state at t0 = 0.07 s read from" "$dir/r2/piece_0.0700.log" ||
  fail "the piece after the record did not start from the record's state"
grep -q "3 of 3 pieces finished" <<<"$out" || fail "summary with the record: $out"
whole="chain.args piece_0.0500.log piece_0.0600.log piece_0.0700.log program.sha256 state_0.0800.h5"
[ "$(listing "$rec")" = "$whole" ] || fail "record after the third piece: $(listing "$rec")"
grep -q "3 of 3 pieces finished" <<<"$(chain --dir "$dir/none" --record "$rec" --summary)" ||
  fail "--summary does not count the record's pieces"
# A recorded chain warms up in its record: an earlier state there is where the warm-up goes on.
"$bench" --nodes 100 --t0 0.02 --dt 0.005 --variants hybrid --warm-state "$dir/early.h5" >/dev/null ||
  fail "bench_radial to t = 0.02 s failed"
mkdir "$dir/rec0"
cp "$dir/early.h5" "$dir/rec0/state_0.0500.h5"
chain --dir "$dir/r0" --record "$dir/rec0" --to 0.06 >/dev/null || fail "the chain from rec0 failed"
grep -q "warm state at t = 0.02 s read from $dir/rec0/state_0.0500.h5" "$dir/r0/piece_0.0500.log" ||
  fail "the first piece of a recorded chain did not warm up from the record's state"
[ "$(listing "$dir/rec0")" = "chain.args piece_0.0500.log program.sha256 state_0.0600.h5" ] ||
  fail "rec0 after its piece: $(listing "$dir/rec0")"
cp "$bench" "$dir/other_bench"
echo >>"$dir/other_bench"
if chain --bench "$dir/other_bench" --dir "$dir/r3" --record "$rec" >/dev/null 2>"$dir/r3.err"; then
  fail "a record was continued with another bench_radial"
fi
grep -q "measured with another bench_radial" "$dir/r3.err" || fail "refusal: $(cat "$dir/r3.err")"
[ "$(cat "$rec/program.sha256")" = "$(sha256sum "$bench" | cut -d' ' -f1)" ] ||
  fail "a refused program changed the record's checksum"
[ ! -e "$dir/r3/bench_radial" ] || fail "a refused program was copied into the chain directory"
# Nor does it go on with other parameters.
if chain --dir "$dir/r4" --record "$rec" --span 0.001 >/dev/null 2>"$dir/r4.err"; then
  fail "a record was continued with another span"
fi
grep -q "holds the chain of .*span 0.0005 s" "$dir/r4.err" || fail "refusal: $(cat "$dir/r4.err")"
# A record given to a chain that is ahead of it (pieces finished without --record) catches up,
# and one state too many (a run stopped between its copies) goes.
mkdir "$dir/late"
cp "$dir/chain/state_0.0600.h5" "$dir/late/state_0.0600.h5"
out=$(chain --record "$dir/late")
grep -q "== piece" <<<"$out" && fail "a record catching up ran a piece: $out"
[ "$(listing "$dir/late")" = "$whole" ] || fail "the late record did not catch up: $(listing "$dir/late")"

# A later piece never warms up: a start state from another time is an error, as is none.
rm "$dir/chain/piece_0.0700.done"
# Meanwhile the summary of the two finished pieces projects the whole interval.
out=$(chain --summary)
grep -q "2 of 3 pieces finished" <<<"$out" || fail "summary of 2 pieces: $out"
grep -Eq "projected to the whole \[0.05, 0.08\] at the rate of the finished pieces: hybrid [0-9]+ s, explicit only [0-9]+ s" <<<"$out" ||
  fail "no projection of the unfinished chain: $out"
cp "$dir/chain/state_0.0600.h5" "$dir/chain/state_0.0700.h5"
if chain >/dev/null 2>&1; then fail "a piece started from a state at another time"; fi
grep -q "require-warm" "$dir/chain/piece_0.0700.log.part" || fail "no --require-warm refusal"
rm "$dir/chain/state_0.0700.h5"
if chain >/dev/null 2>&1; then fail "a piece without its start state ran"; fi
# --thickness reaches bench_radial, and a state of the default sheet is no start for another one:
# the piece warms up from rest.
tests/bench/radial_chain.sh --bench "$bench" --nodes 100 --from 0.06 --to 0.07 --piece 0.01 \
  --span 0.0005 --dir "$dir/thick" --thickness 0.25 --seed "$dir/chain/state_0.0600.h5" >/dev/null ||
  fail "the chain with --thickness failed"
grep -q "h_eff 0.25 mm" "$dir/thick/piece_0.0600.log" || fail "--thickness not passed on"
grep -q "from t = 0 s to t0 = 0.06 s" "$dir/thick/piece_0.0600.log" ||
  fail "a 0.25 mm piece started from the 0.125 mm sheet's state"
# Nor is it one for another mesh of the same sheet (bench_radial --mesh-seed).
cp "$dir/chain/state_0.0600.h5" "$dir/seed2_warm.h5"
"$bench" --nodes 100 --t0 0.06 --dt 0.01 --variants hybrid --mesh-seed 2 \
  --warm-state "$dir/seed2_warm.h5" >"$dir/seed2.log" ||
  fail "bench_radial --mesh-seed 2 failed"
grep -q "from t = 0 s to t0 = 0.06 s" "$dir/seed2.log" ||
  fail "mesh seed 2 started from the state of mesh seed 1"
# --explicit-samples: K spans timed along the first hybrid, reported after it.
"$bench" --nodes 100 --t0 0.05 --dt 0.03 --variants block-jacobi --explicit-span 0.0005 \
  --explicit-samples 3 --warm-state "$dir/chain/state_0.0500.h5" >"$dir/samples.log" ||
  fail "bench_radial --explicit-samples 3 failed"
[ "$(grep -c "explicit-only sample \[" "$dir/samples.log")" = 3 ] || fail "not 3 samples"
grep -q "over 3 spans of 0.0005 s, each timed when the first hybrid" "$dir/samples.log" ||
  fail "the sampled explicit-only row is missing"
grep -q "^speed-up of hybrid, CG + block Jacobi 18 against explicit-only" "$dir/samples.log" ||
  fail "no speed-up against the sampled explicit-only"
# Bad arguments are refused.
if tests/bench/radial_chain.sh --bogus 1 2>/dev/null; then fail "--bogus accepted"; fi
if tests/bench/radial_chain.sh --from 3 --to 3.13 --piece 0.05 2>/dev/null; then
  fail "a range that is not a whole number of pieces was accepted"
fi
echo "radial_chain.sh: chaining, resuming and summing pass"
