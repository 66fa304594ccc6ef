#!/usr/bin/env bash
# segbrain on the real T1 head that Debian ships (insighttoolkit5-examples: 128x128x62,
# 2x2x3 mm, stored LSA): brain Dice against its skull-strip labels (target >= 0.90, docs/segbrain.md §5)
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
"$FEST_BIN/segbrain" eval --ref "$ref" --seg "$WORK/labels.nii.gz" --map "brain=2-8" --ref-map "brain=1-1000" >"$WORK/eval.tsv"
d=$(dice_of brain "$WORK/eval.tsv")
check "brain Dice >= 0.90 ($d)" at_least "$d" 0.90
check "orientation LSA reported" test "$(jq -r .input.orientation "$WORK/report.json")" = LSA
check "brain_filled accepted by the window clause" test "$(jq -r .accepted_by.find_brain "$WORK/report.json")" != null

# Storage and intensity invariance on the real head (docs/segbrain.md §5, orientation invariance,
# issue 9): the same voxels stored with rotated, flipped axes (LSA -> ARS, the sform
# rewritten) give the same labels voxel by voxel after mapping back; a smooth +-30 %
# intensity shading gives the same brain within Dice 0.97.
case_ "ITK head: reoriented storage gives identical labels; a +-30 % bias field the same brain"
R="$(dirname "$0")/segbrain/reorient.py"
"$FEST_BIN/fconv" "$head_t1" -o "$WORK/itk.nii" 2>/dev/null
python3 "$R" shuffle "$WORK/itk.nii" "$WORK/itk_ars.nii"
run segbrain run "$WORK/itk_ars.nii" -o "$WORK/ars_labels.nii" --report "$WORK/ars.json"
expect_status 0
check "orientation code ARS" test "$(jq -r .input.orientation "$WORK/ars.json")" = ARS
"$FEST_BIN/segbrain" run "$WORK/itk.nii" -o "$WORK/lsa_labels.nii"
check "labels identical voxel by voxel after mapping back" python3 "$R" unshuffled "$WORK/lsa_labels.nii" "$WORK/ars_labels.nii"
python3 "$R" bias "$WORK/itk.nii" "$WORK/itk_bias.nii" 0.3
run segbrain run "$WORK/itk_bias.nii" -o "$WORK/bias_labels.nii"
expect_status 0
"$FEST_BIN/segbrain" eval --ref "$WORK/lsa_labels.nii" --seg "$WORK/bias_labels.nii" --map "brain=2-8" >"$WORK/bias.tsv"
check "biased brain Dice >= 0.97 against the unbiased result ($(dice_of brain "$WORK/bias.tsv"))" at_least "$(dice_of brain "$WORK/bias.tsv")" 0.97

# Figure 2.5 on real data (docs/segbrain.md §3, leak recovery): the first window (0.50, 1.30)W
# with 2 mm separation joins the brain to the scalp; no_connection_to_skincontour measures
# the skin contact above its 0.3 % limit, the engine backtracks, and the next window passes
# every check of verify_brain_result.
case_ "leak check and retry on the ITK head (Fig. 2.5), visible in the trace"
run segbrain run "$head_t1" -o "$WORK/retry.nii.gz" --set "brain_window=[(0.50,1.30),(0.55,1.25)]" \
    --set "separation_mm=[2]" --trace "$WORK/retry.jsonl" --report "$WORK/retry.json"
expect_status 0
# Position of the first trace line with that port and goal (-1 when none).
first() { jq -s --arg p "$1" --arg g "$2" 'map(.port + " " + .goal) | index($p + " " + $g) // -1' "$WORK/retry.jsonl"; }
leak=$(first fail "no_connection_to_skincontour(brain_raw)")
accept=$(first exit "verify_brain_result(brain_raw)")
check "the skin-contact check fails first (line $leak)" test "$leak" -ge 0
check "verify_brain_result succeeds after it (line $accept)" test "$accept" -gt "$leak"
m=$(jq -s -c '[.[] | select(.port == "fail" and .goal == "no_connection_to_skincontour(brain_raw)")][0].measure' "$WORK/retry.jsonl")
check "the failure carries its measure and limit ($m)" \
    jq -n -e --argjson m "$m" '$m.skin_contact_fraction > $m.max and $m.max == 0.003'
windows=$(jq -s -c '[.[] | select(.port == "exit" and (.goal | startswith("member((") and endswith("[(0.5, 1.3), (0.55, 1.25)])"))) | .goal | capture("member\\(\\((?<w>[^)]*)\\)").w] | unique' "$WORK/retry.jsonl")
check "both windows were tried ($windows)" test "$windows" = '["0.5, 1.3","0.55, 1.25"]'
"$FEST_BIN/segbrain" eval --ref "$ref" --seg "$WORK/retry.nii.gz" --map "brain=2-8" --ref-map "brain=1-1000" >"$WORK/retry.tsv"
good=$(dice_of brain "$WORK/retry.tsv")
check "the accepted brain has Dice >= 0.90 ($good)" at_least "$good" 0.90
# The rejected candidate really is worse: accepted anyway (limit lifted), it loses Dice.
run segbrain run "$head_t1" -o "$WORK/leak.nii.gz" --set "brain_window=[(0.50,1.30)]" --set "separation_mm=[2]" --set "skin_contact_max=1"
expect_status 0
"$FEST_BIN/segbrain" eval --ref "$ref" --seg "$WORK/leak.nii.gz" --map "brain=2-8" --ref-map "brain=1-1000" >"$WORK/leak.tsv"
bad=$(dice_of brain "$WORK/leak.tsv")
check "the leaking candidate is worse by >= 0.03 Dice ($bad vs $good)" at_least "$(awk -v a="$good" -v b="$bad" 'BEGIN { print a - b }')" 0.03

# Colin27 (mricron-data), the one whole-head run of this suite: brain against ch2bet,
# cerebellum against the AAL labels drawn on this subject, ventricles against the JHU
# atlas (another subject, so loose targets; docs/segbrain.md §5).
ch2=$(need_testdata mri/ch2.nii.gz) && ch2bet=$(need_testdata mri/ch2bet.nii.gz) &&
    aal=$(need_testdata mri/aal.nii.gz) && jhu=$(need_testdata mri/jhu189.nii.gz) && {
case_ "Colin27: brain, ventricles, cerebellum and brainstem against ch2bet, JHU and AAL"
run segbrain run "$ch2" -o "$WORK/ch2_labels.nii.gz" --report "$WORK/ch2.json" --trace "$WORK/ch2.jsonl"
expect_status 0
E="$FEST_BIN/segbrain"
"$E" eval --ref "$ch2bet" --seg "$WORK/ch2_labels.nii.gz" --map "brain=2-8" --ref-map "brain=1-1000" >"$WORK/ch2_brain.tsv"
"$E" eval --ref "$aal" --seg "$WORK/ch2_labels.nii.gz" --map "cerebellum=7" --ref-map "cerebellum=91-116" >"$WORK/ch2_cb.tsv"
"$E" eval --ref "$jhu" --seg "$WORK/ch2_labels.nii.gz" --map "ventricles=6" --ref-map "ventricles=171-181" >"$WORK/ch2_v.tsv"
check "brain Dice >= 0.95 ($(dice_of brain "$WORK/ch2_brain.tsv"))" at_least "$(dice_of brain "$WORK/ch2_brain.tsv")" 0.95
check "cerebellum Dice >= 0.75 vs AAL ($(dice_of cerebellum "$WORK/ch2_cb.tsv"))" at_least "$(dice_of cerebellum "$WORK/ch2_cb.tsv")" 0.75
check "ventricles Dice >= 0.40 vs JHU ($(dice_of ventricles "$WORK/ch2_v.tsv"))" at_least "$(dice_of ventricles "$WORK/ch2_v.tsv")" 0.40
vv=$(jq '.objects.ventricles.volume_ml' "$WORK/ch2.json")
check "ventricles 15-60 ml ($vv)" awk -v v="$vv" 'BEGIN { exit !(v >= 15 && v <= 60) }'
# Eyes: no reference labels; the knowledge base asks for two globes of radius 10-14 mm.
ev=$(jq '.objects.eyes.volume_ml' "$WORK/ch2.json")
check "eyes: two globes of radius 10-14 mm ($ev ml)" awk -v v="$ev" 'BEGIN { r = (3 * v / 2 / (4 * 3.14159265)) ^ (1 / 3) * 10; exit !(r >= 10 && r <= 14) }'
# Brainstem: the JHU labels of the midbrain, pons and medulla (99-104, 107-116, 21 ml, the
# set docs/segbrain.md §5 evaluates against); the knowledge base asks for 15-50 ml, and its
# centroid within 10 mm of theirs (6.4 mm measured; 11.1 mm from that of the upper subset
# 99/100/113-116 alone, which misses the medulla the rule now includes).
bv=$(jq '.objects.brainstem.volume_ml' "$WORK/ch2.json")
check "brainstem 15-50 ml ($bv)" awk -v v="$bv" 'BEGIN { exit !(v >= 15 && v <= 50) }'
ref_c=$(python3 "$(dirname "$0")/segbrain/reorient.py" centroid "$jhu" 99 104 107 116)
our_c=$(jq -r '.objects.brainstem.centroid_mm | map(tostring) | join(" ")' "$WORK/ch2.json")
d=$(echo "$ref_c $our_c" | awk '{ print sqrt(($1 - $4)^2 + ($2 - $5)^2 + ($3 - $6)^2) }')
check "brainstem centroid within 10 mm of JHU's ($d mm)" awk -v d="$d" 'BEGIN { exit !(d <= 10) }'
# Dice against those labels (99-104, 107-116, 21 ml): 0.649 measured with the rule whose
# sides end at the CSF and are bridged across the peduncles (docs/segbrain.md §5, "The
# brainstem"; 0.616 with the former +-14 mm column, 0.43-0.51 for regions that took the
# cerebellum or the temporal lobes); the bound sits just under the measure.
"$E" eval --ref "$jhu" --seg "$WORK/ch2_labels.nii.gz" --map "brainstem=8" --ref-map "brainstem=99-104,107-116" >"$WORK/ch2_bs.tsv"
check "brainstem Dice >= 0.64 vs JHU ($(dice_of brainstem "$WORK/ch2_bs.tsv"))" at_least "$(dice_of brainstem "$WORK/ch2_bs.tsv")" 0.64
# Optic nerves: no reference labels either; plausibility (docs/segbrain.md §4): two tracked paths of
# 35-65 mm (Colin27's chord from the posterior pole of a globe to the chiasm is itself
# about 52 mm), each starting at its globe and heading back and towards the midline,
# the two meeting behind the eyes.
lens=$(jq -s -r '[.[] | select(.port == "exit" and (.goal | startswith("line_track("))) | .measure.path_length_mm] | map(. * 10 | round / 10) | join(" ")' "$WORK/ch2.jsonl")
check "two nerve paths of 35-65 mm ($lens)" sh -c "echo '$lens' | awk '{ exit !(NF == 2 && \$1 >= 35 && \$1 <= 65 && \$2 >= 35 && \$2 <= 65) }'"
python3 "$(dirname "$0")/segbrain/reorient.py" nerves "$WORK/ch2_labels.nii.gz" 9 10 >"$WORK/nerves.txt"
# side touches_eye front_R front_A back_R back_A (world mm)
check "each nerve touches its globe ($(awk '{ printf "%s %s ", $1, $2 }' "$WORK/nerves.txt"))" \
    awk 'END { exit !(NR == 2 && ok == 2) } $2 > 0 { ok++ }' "$WORK/nerves.txt"
# The midline: halfway between the two back ends.
check "each nerve heads back >= 25 mm and >= 15 mm towards the midline ($(awk '{ printf "%s A %s->%s R %s->%s; ", $1, $4, $6, $3, $5 }' "$WORK/nerves.txt"))" \
    awk 'function abs(x) { return x < 0 ? -x : x }
         { fa[NR] = $4; ba[NR] = $6; fr[NR] = $3; br[NR] = $5 }
         END { if (NR != 2) exit 1; m = (br[1] + br[2]) / 2
               for (k = 1; k <= 2; k++) if (fa[k] - ba[k] < 25 || abs(fr[k] - m) - abs(br[k] - m) < 15) exit 1 }' "$WORK/nerves.txt"
check "the nerves meet behind the eyes (back ends <= 15 mm apart, front ends >= 45 mm)" \
    awk 'NR == 1 { fr = $3; br = $5 } NR == 2 { exit !($3 - fr >= 45 && $5 - br <= 15 && br - $5 <= 15) }' "$WORK/nerves.txt"
}

finish
