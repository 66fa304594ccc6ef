#!/usr/bin/env bash
# feshape speed and quality on real points (docs/feshape.md §3 set-ups), one JSON line per run:
# the solvers (equilibrium, equilibrium with --reassign-every 10, the seed's explicit
# Euler) on a lung-sized set (857 of the kitten's points) and a head-sized one (all 5210),
# and as the anchor, measured in the same run, a uniform model with at least as many
# nodes as the adaptive one. Run by hand:
#
#   tests/bench/feshape_bench.sh [BUILD_BIN]
set -eu
bin="${1:-build/bin}"
data="${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}/points/kitten.xyz"
[ -f "$data" ] || { echo "no $data (run scripts/fetch-test-data.sh)" >&2; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
awk 'NR % 6 == 1 && c < 857 { print $1, $2, $3; c++ }' "$data" >"$work/lung_like.xyz"
cp "$data" "$work/head_like.xyz"
W=0.5,5,5,0,0,0

# one CASE POINTS SOLVER-LABEL FLAGS...: fit, then print a JSON line from the report.
one() {
  local name="$1" points="$2" label="$3"; shift 3
  local t0 t1
  t0=$(date +%s.%N)
  "$bin/feshape" fit "$points" "$@" --report "$work/r.json" -o "$work/out.ply" 2>/dev/null
  t1=$(date +%s.%N)
  jq -c --arg case "$name" --arg solver "$label" --argjson wall "$(echo "$t1 - $t0" | bc)" \
    '{case: $case, solver: $solver, points: .points, levels: (.levels | length), nodes: .levels[-1].nodes,
      iterations: ([.levels[].iterations] | add), mean: .levels[-1].mean, max: .levels[-1].max,
      folded: .levels[-1].folded, wall_s: $wall}' "$work/r.json"
}

for c in "lung_like 8x8 0.01" "head_like 8x8 0.01"; do
  set -- $c
  name=$1 grid=$2 tau=$3
  pts="$work/$name.xyz"
  one "$name" "$pts" equilibrium --grid "$grid" --levels 3 --tau "$tau" --w "$W"
  nodes=$(jq '.levels[-1].nodes' "$work/r.json")
  one "$name" "$pts" equilibrium_reassign10 --grid "$grid" --levels 3 --tau "$tau" --w "$W" --reassign-every 10
  one "$name" "$pts" explicit_seed_dt --grid "$grid" --levels 3 --tau "$tau" --w "$W" --solver explicit --max-iter 20000
  m=3
  while [ $((m * m + 2)) -lt "$nodes" ]; do m=$((m + 1)); done
  one "$name" "$pts" "anchor_uniform_${m}x${m}" --grid "${m}x${m}" --levels 0 --w "$W"
done
