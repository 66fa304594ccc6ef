#!/usr/bin/env bash
# segbrain on the inputs users have besides whole heads (docs/segbrain.md §1, "What the
# volume holds"): a field of view that cuts through the brain (nibabel's anatomical.nii,
# Debian python3-nibabel) and a brain that is already skull-stripped (Colin27's ch2bet,
# mricron-data). The scene is recognised, what it rules out is said on one line of
# standard error and in the report, and the labels of what was found are written.
# Skipped (77) when the data is not fetched.
. "$(dirname "$0")/lib.sh"
S="$FEST_BIN/segbrain"

anat=$(need_testdata volumes/nibabel/anatomical.nii) || exit 77

case_ "anatomical.nii (66x82x50 mm of brain): partial field of view, no skull, labels written"
run segbrain run "$anat" -o "$WORK/anat.nii.gz" --report "$WORK/anat.json"
expect_status 0
# The field of view from the header (dims x spacing), not from the program's own line.
fov=$(jq -r '[.input.dims, .input.spacing] | transpose | map(.[0] * .[1] | round | tostring) | join("x")' "$WORK/anat.json")
check "the header's field of view is 66x82x50 mm ($fov)" test "$fov" = 66x82x50
check "one line on stderr" test "$(wc -l <"$WORK/stderr")" -eq 1
expect_stderr_has "field of view $fov mm covers part of the brain"
expect_stderr_has "no skull in the volume, skull stripping skipped"
expect_stderr_has "brainstem, cerebellum not sought"  # in the order they are sought
check "report: scene partial" test "$(jq -r .scene "$WORK/anat.json")" = partial
check "report: not skull-stripped input (the crop is)" test "$(jq -r .skull_stripped_input "$WORK/anat.json")" = false
check "report: the stderr line is the summary" test "segbrain: $(jq -r .summary "$WORK/anat.json")" = "$(cat "$WORK/stderr")"
nots=$(jq -r '[.not_sought[].object] | sort | join(",")' "$WORK/anat.json")
check "report: brainstem, cerebellum, eyes, optic nerve not sought ($nots)" test "$nots" = brainstem,cerebellum,eyes,optic_nerve
check "every not-sought object has a reason" jq -e '.not_sought | all(.reason | length > 10)' "$WORK/anat.json"
# Brain-only crop: every tissue voxel is brain; the volume of the brain is at most the
# field of view's 66 x 82 x 50 mm = 270.6 ml.
bv=$(jq '.objects.brain_filled.volume_ml' "$WORK/anat.json")
check "brain 200-270.6 ml of the 270.6 ml in view ($bv)" awk -v v="$bv" 'BEGIN { exit !(v >= 200 && v <= 270.6) }'
# The lateral ventricles are in view (the crop is centred on them); the knowledge base's
# bounds for a whole pair are 5-80 ml.
vv=$(jq '.objects.ventricles.volume_ml // 0' "$WORK/anat.json")
check "ventricles found, 5-80 ml ($vv)" awk -v v="$vv" 'BEGIN { exit !(v >= 5 && v <= 80) }'
check "label volume written with the input's dims" test "$(python3 "$(dirname "$0")/segbrain/reorient.py" centroid "$WORK/anat.nii.gz" 6 6 | wc -w)" -eq 3

case_ "anatomical.nii: an object asked for by name that the view rules out is an error naming it"
run segbrain run "$anat" -o "$WORK/bs.nii.gz" --objects brain,brainstem
expect_status 1
expect_stderr_has "brainstem not sought: the field of view ends"
check "no label volume on failure" test ! -e "$WORK/bs.nii.gz"

case_ "anatomical.nii: -q silences the note"
run segbrain run "$anat" -o "$WORK/q.nii.gz" -q
expect_status 0
check "stderr empty with -q" test ! -s "$WORK/stderr"

ch2bet=$(need_testdata mri/ch2bet.nii.gz) || { finish; exit; }
case_ "ch2bet (skull-stripped Colin27): brain only, said with -v and in the report"
run segbrain run "$ch2bet" -o "$WORK/bet.nii.gz" --objects brain --report "$WORK/bet.json" -v
expect_status 0
expect_stderr_has "already skull-stripped .brain only.: skull stripping skipped"
check "said on one line" test "$(wc -l <"$WORK/stderr")" -eq 1
check "report: skull_stripped_input true" test "$(jq -r .skull_stripped_input "$WORK/bet.json")" = true
check "report: scene brain_only" test "$(jq -r .scene "$WORK/bet.json")" = brain_only
check "report: the note" jq -e '.notes | any(.level == "info" and (.text | test("already skull-stripped")))' "$WORK/bet.json"
# Without -v the info note is not shown; nothing was skipped (--objects brain seeks no eyes).
"$S" run "$ch2bet" -o "$WORK/bet2.nii.gz" --objects brain 2>"$WORK/bet2.err"
check "without -v nothing is said" test ! -s "$WORK/bet2.err"
# No extracranial label (1) in a brain-only volume: the stripping removed it.
"$S" eval --ref "$WORK/bet.nii.gz" --seg "$WORK/bet.nii.gz" --map "extracranial=1" >"$WORK/bet.tsv"
check "no extracranial label ($(awk '$1 == "extracranial" { print $4 }' "$WORK/bet.tsv") ml)" \
    awk '$1 == "extracranial" { found = 1; if ($4 != 0) exit 1 } END { exit !found }' "$WORK/bet.tsv"

finish
