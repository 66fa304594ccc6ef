#!/usr/bin/env bash
# segbrain --threads (deterministic output, docs/segbrain.md §5): the label volume, the masks and the
# report's objects are byte-identical for any thread count; a bad count is a usage error.
. "$(dirname "$0")/lib.sh"
S="$FEST_BIN/segbrain"
P="$WORK/phantom.nii"
"$S" synth -o "$P" --truth "$WORK/truth.nii" --size 80,96,80 --spacing 2,2,2 --seed 3 --bias 0.3

case_ "labels, masks and report identical for 1 and 3 threads"
for n in 1 3; do
  mkdir -p "$WORK/m$n"
  run segbrain run "$P" -o "$WORK/l$n.nii" --threads "$n" --masks "$WORK/m$n" --report "$WORK/r$n.json"
  expect_status 0
  expect_stdout_empty
done
for n in 3; do
  check "label volume: 1 thread = $n threads" cmp "$WORK/l1.nii" "$WORK/l$n.nii"
  check "object masks: 1 thread = $n threads" diff -r "$WORK/m1" "$WORK/m$n"
  check "report (but for wall_s): 1 thread = $n threads" cmp <(jq -S 'del(.wall_s)' "$WORK/r1.json") <(jq -S 'del(.wall_s)' "$WORK/r$n.json")
done
check "masks were written" test -s "$WORK/m1/brain_filled.nii.gz"

case_ "--threads 0 means all cores; a negative count is a usage error"
run segbrain run "$P" -o "$WORK/l0.nii" --threads 0
expect_status 0
check "label volume: all cores = 1 thread" cmp "$WORK/l1.nii" "$WORK/l0.nii"
run segbrain run "$P" -o "$WORK/bad.nii" --threads -2
expect_clean_failure 2 segbrain
check "no output file on a usage error" test ! -e "$WORK/bad.nii"

finish
