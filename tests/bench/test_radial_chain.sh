#!/usr/bin/env bash
# tests/bench/radial_chain.sh on a 100-node sheet: pieces chain through their end states, a
# rerun skips finished pieces and redoes an unfinished one, and the summary sums the pieces.
#   test_radial_chain.sh BENCH_RADIAL
set -euo pipefail
bench=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
chain() { tests/bench/radial_chain.sh --bench "$bench" --nodes 100 --from 0.02 --to 0.04 \
  --piece 0.01 --span 0.0005 --dir "$dir/chain" "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

out=$(chain)
[ -f "$dir/chain/piece_0.0200.done" ] && [ -f "$dir/chain/piece_0.0300.done" ] || fail "pieces not finished"
grep -q "warm state at t0 = 0.03 s read from" "$dir/chain/piece_0.0300.log" ||
  fail "the second piece did not start from the first one's end state"
# The hybrid's steps in the summary against the pieces' own totals lines.
steps=$(awk '/^hybrid, CG \+ block Jacobi 18 /{h=1} /^ +totals:/{if(h){gsub(",","");s+=$9}; h=0} END{print s}' \
  "$dir"/chain/piece_*.log)
echo "$out" | grep -q "2 of 2 pieces finished" || fail "summary: $out"
echo "$out" | grep -q "hybrid, block Jacobi 18: .* s wall, $steps steps" ||
  fail "summary does not sum the pieces' $steps steps: $out"
echo "$out" | grep -q "explicit only: .* over 2 spans" || fail "explicit-only spans: $out"

# A rerun runs nothing; an unfinished piece is redone, alone.
chain | grep -q "== piece" && fail "a rerun ran a finished piece again"
rm "$dir/chain/piece_0.0300.done"
redo=$(chain | grep -c "== piece" || true)
[ "$redo" = 1 ] || fail "expected one piece redone, got $redo"

# Bad arguments are refused.
if tests/bench/radial_chain.sh --bogus 1 2>/dev/null; then fail "--bogus accepted"; fi
echo "radial_chain.sh: chaining, resuming and summing pass"
