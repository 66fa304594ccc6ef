#!/usr/bin/env bash
# segbrain on the real T1 head that Debian ships (insighttoolkit5-examples: 128x128x62,
# 2x2x3 mm, stored LSA): brain Dice against its skull-strip labels (spec §5 target >= 0.90)
# and the orientation code in the report. Skipped (77) when the data is not fetched.
. "$(dirname "$0")/lib.sh"
head_t1=$(need_testdata mri/t1_head.nii.gz) || exit 77
ref=$(need_testdata mri/t1_skullstrip_labels.nii.gz) || exit 77

dice_of() { awk -v o="$1" '$1 == o { print $2 }' "$2"; }
at_least() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a >= b) }'; }

case_ "ITK Kmeans T1 head: brain Dice >= 0.90"
run segbrain run "$head_t1" -o "$WORK/labels.nii.gz" --report "$WORK/report.json" --trace "$WORK/trace.jsonl"
expect_status 0
expect_stdout_empty
"$FEST_BIN/segbrain" eval --ref "$ref" --seg "$WORK/labels.nii.gz" --map "brain=2,3" --ref-map "brain=1-1000" >"$WORK/eval.tsv"
d=$(dice_of brain "$WORK/eval.tsv")
check "brain Dice >= 0.90 ($d)" at_least "$d" 0.90
check "orientation LSA reported" test "$(jq -r .input.orientation "$WORK/report.json")" = LSA
check "brain_filled accepted by the window clause" test "$(jq -r .accepted_by.find_brain "$WORK/report.json")" != null

finish
