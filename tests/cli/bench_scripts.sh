#!/usr/bin/env bash
# The batch and start-up benchmarks (tests/bench/batch.sh, startup.sh) do not rot: a tiny
# batch of fest's own tools finishes and prints valid JSON lines with figures, and both
# scripts refuse bad arguments. Timings are never checked here (benchmarks, not tests).
. "$(dirname "$0")/lib.sh"
bench="$(cd "$(dirname "$0")/../bench" && pwd)"
command -v make >/dev/null && command -v python3 >/dev/null && command -v jq >/dev/null ||
  { echo "bench_scripts: make, python3 and jq are needed: skipped"; exit 77; }

case_ "batch.sh --files 4 --tools fest"
bash "$bench/batch.sh" --files 4 --tools fest --bin "$FEST_BIN" >"$out" 2>"$err"
rc=$?
[ "$rc" -eq 77 ] && { echo "bench_scripts: real test data not fetched: skipped"; exit 77; }
expect_status 0
check "every line is one JSON object" jq -e -s 'length == 4 and all(type == "object")' "$out"
check "the inputs line counts 4 photos and 4 meshes" jq -e -s '.[0].photos == 4 and .[0].jpeg == 2 and .[0].meshes == 4' "$out"
for b in resize:4 convert:2 ply2off:4; do
  check "batch ${b%:*}: fest converted ${b#*:} files with figures" jq -e -s --arg b "${b%:*}" --argjson n "${b#*:}" \
    'map(select(.batch == $b and .tool == "fest")) | length == 1 and (.[0].files == $n) and (.[0].files_per_s > 0)
     and (.[0].peak_rss_mb > 0) and (.[0].out_mb > 0)' "$out"
done

case_ "bad arguments"
bash "$bench/batch.sh" --files 1 >"$out" 2>"$err"; rc=$?
expect_status 2
expect_stderr_has '^batch.sh: --files needs a whole number from 2 to 9999$'
bash "$bench/batch.sh" --frobnicate >"$out" 2>"$err"; rc=$?
expect_status 2
expect_stderr_has "^batch.sh: unknown argument '--frobnicate'"
bash "$bench/startup.sh" "$WORK/nowhere" >"$out" 2>"$err"; rc=$?
if command -v hyperfine >/dev/null; then
  expect_status 2
  expect_stderr_has "^startup.sh: no folder $WORK/nowhere"
fi
check "startup.sh --help" bash "$bench/startup.sh" --help

finish
