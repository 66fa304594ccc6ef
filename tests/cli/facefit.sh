#!/usr/bin/env bash
# facefit end to end on the synthetic population (32×32 grid, 100 training faces):
# analytic cases (exact recovery, invariance, projection idempotence, U-shaped sweep),
# pipelines through standard input/output, a golden fit, and bad input.
. "$(dirname "$0")/lib.sh"
F="$FEST_BIN/facefit"
S="$WORK/syn"

case_ "synth and build: 99 components from 100 faces"
run facefit synth -o "$S" --resolution 32 --faces 110 --train 100 --seed 1
expect_status 0
check "faces written" test -s "$S/face110.ply"
check "set17 has 17 rows" test "$(tail -n +2 "$S/set17.tsv" | wc -l)" -eq 17
check "set50 has 50 rows" test "$(tail -n +2 "$S/set50.tsv" | wc -l)" -eq 50
run facefit build -o "$S/model.mmb" --list "$S/train.txt" --landmarks "$S/landmarks.tsv" --mask "$S/evalmask.tsv"
expect_status 0
expect_stdout_empty
run facefit info -m "$S/model.mmb"
expect_status 0
expect_json '.components' '99'
expect_json '.points' '1024'
expect_json '.training_examples' '100'
expect_json '.landmarks' '50'
check "magic" test "$(head -c 8 "$S/model.mmb")" = "MORPHMB1"

case_ "training face, known camera, eta 0: recovered exactly (T4)"
"$F" project --mesh "$S/face005.ply" --vertices "$S/set50.tsv" >"$WORK/lm5.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5.tsv" --camera fixed --eta 0 -o "$WORK/fit5.ply" --report "$WORK/fit5.json"
expect_status 0
expect_stdout_empty
run fcompare "$S/face005.ply" "$WORK/fit5.ply" --tol 0.01 --ordered -t 'vertex_max_abs<=0.01'
expect_status 0
check "E_r below 1e-3 px" jq -e '.E_r < 1e-3' "$WORK/fit5.json"
check "report names l and k" jq -e '.l == 100 and .k == 99 and .eta_source == "given"' "$WORK/fit5.json"

case_ "image space: the fitted landmark vertices land on the clicked points"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5.tsv" --camera fixed --eta 0 --space image --to plya -o "$WORK/img.ply"
expect_status 0
v=$(awk 'NR==2 {print $2}' "$S/set50.tsv"); u0=$(awk 'NR==2 {print $2}' "$WORK/lm5.tsv"); v0=$(awk 'NR==2 {print $3}' "$WORK/lm5.tsv")
check "vertex $v at ($u0, $v0)" awk -v n="$v" -v u="$u0" -v w="$v0" '/end_header/ {h=NR} h && NR == h + 1 + n {d = ($1-u)^2 + ($2-w)^2; ok = (d < 1e-6)} END {exit !ok}' "$WORK/img.ply"

case_ "texture: a photo whose colours encode pixel position colours each vertex by where it projects"
awk 'BEGIN {print "P3\n300 300\n255"; for (y = 0; y < 300; y++) for (x = 0; x < 300; x++) print int(x * 255 / 299 + 0.5), int(y * 255 / 299 + 0.5), 0}' >"$WORK/photo.ppm"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5.tsv" --camera fixed --eta 0 --texture "$WORK/photo.ppm" --to plya -o "$WORK/tex.ply" --report "$WORK/tex.json"
expect_status 0
nv=$(awk '$1 == "nose_tip" {print $2}' "$S/set50.tsv"); nu=$(awk '$1 == "nose_tip" {print $2}' "$WORK/lm5.tsv"); nvv=$(awk '$1 == "nose_tip" {print $3}' "$WORK/lm5.tsv")
check "nose tip coloured by its image position" awk -v n="$nv" -v u="$nu" -v w="$nvv" '/end_header/ {h=NR} h && NR == h + 1 + n {ok = ($4 - u * 255 / 299)^2 < 2.5 && ($5 - w * 255 / 299)^2 < 2.5} END {exit !ok}' "$WORK/tex.ply"
check "most vertices visible in the frontal view" jq -e '.texture.visible_vertices > 800' "$WORK/tex.json"
case_ "unreadable texture image"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5.tsv" --texture "$WORK/no_such_photo.png" --coeffs "$WORK/never.tsv"
expect_clean_failure 4 facefit
check "no coefficient file written" test ! -e "$WORK/never.tsv"

case_ "pipeline: project | fit | eval through standard streams"
"$F" project --mesh "$S/face105.ply" --vertices "$S/set50.tsv" | "$F" fit -m "$S/model.mmb" --camera fixed --eta 2 --eta-units px2 \
  | "$F" eval --truth "$S/face105.ply" --estimate - --mask "$S/evalmask.tsv" >"$out"
check "eval header" grep -q "^vertices	E_full	rms	max" "$out"
check "E_full of a novel face is a few mm" awk 'NR==2 && $2 > 0.5 && $2 < 10 {ok=1} END {exit !ok}' "$out"

case_ "similarity camera: translating and scaling the landmarks changes nothing in model space"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5.tsv" -o "$WORK/sim1.ply" --report "$WORK/sim1.json"
expect_status 0
awk 'NR==1 {print; next} {printf "%s\t%.12g\t%.12g\n", $1, 2*($2-150)+300.5, 2*($3-150)+240}' "$WORK/lm5.tsv" >"$WORK/lm5x2.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5x2.tsv" -o "$WORK/sim2.ply" --report "$WORK/sim2.json"
expect_status 0
run fcompare "$WORK/sim1.ply" "$WORK/sim2.ply" --tol 1e-4 --ordered -t 'vertex_max_abs<=1e-4'
expect_status 0
check "E_r doubles" jq -e --slurpfile a "$WORK/sim1.json" '(.E_r / $a[0].E_r - 2) | fabs < 1e-4' "$WORK/sim2.json"
check "camera scale 2" jq -e '(.camera.s / 2 - 1) | fabs < 0.05' "$WORK/sim2.json"

case_ "iBUG .pts input with a map"
awk 'NR>1 {printf "%d\t%s\n", NR-1, $2}' "$S/set17.tsv" >"$WORK/map17.tsv"
{ echo "version: 1"; echo "n_points: 17"; echo "{"; "$F" project --mesh "$S/face105.ply" --vertices "$S/set17.tsv" | awk 'NR>1 {print $2+1, $3+1}'; echo "}"; } >"$WORK/lm.pts"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm.pts" --map "$WORK/map17.tsv" --report "$WORK/pts.json" -o "$WORK/pts.ply"
expect_status 0
check "17 points used" jq -e '.f == 17' "$WORK/pts.json"

case_ "automatic eta and the affine camera"
"$F" project --mesh "$S/face105.ply" --vertices "$S/set50.tsv" --yaw 20 --pitch 5 --scale 1.5 --noise-sigma 0.5 --seed 3 >"$WORK/lm_pose.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm_pose.tsv" --camera affine --eta auto=evidence --report "$WORK/aff.json" -o "$WORK/aff.ply"
expect_status 0
check "yaw recovered within 3 degrees" jq -e '(.camera.yaw_deg - 20) | fabs < 3' "$WORK/aff.json"
check "eta from the evidence" jq -e '.eta_source == "evidence" and .eta > 0' "$WORK/aff.json"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm_pose.tsv" --camera affine --eta auto=gcv -o "$WORK/gcv.ply"
expect_status 0

case_ "full shape at eta 0 leaves a model face unchanged (orthogonal projection)"
run facefit fit -m "$S/model.mmb" --full-shape "$S/face005.ply" --eta 0 -o "$WORK/proj.ply"
expect_status 0
run fcompare "$S/face005.ply" "$WORK/proj.ply" --tol 1e-3 --ordered -t 'vertex_max_abs<=1e-3'
expect_status 0

case_ "sample: zero coefficients give the mean; uncertainty and coefficients files"
printf 'index\tc\n' >"$WORK/zero.tsv"
run facefit sample -m "$S/model.mmb" --coeffs "$WORK/zero.tsv" -o "$WORK/mean_a.ply"
expect_status 0
run facefit sample -m "$S/model.mmb" -o "$WORK/mean_b.ply"
run fcompare "$WORK/mean_a.ply" "$WORK/mean_b.ply"
expect_status 0
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm5.tsv" --uncertainty "$WORK/unc.tsv" --coeffs "$WORK/c.tsv" -o "$WORK/u.ply"
expect_status 0
check "one uncertainty per vertex" test "$(tail -n +2 "$WORK/unc.tsv" | wc -l)" -eq 1024
check "99 coefficients" test "$(tail -n +2 "$WORK/c.tsv" | wc -l)" -eq 99

case_ "batch: one model load, a mesh and a coefficient file, equal to single fits"
printf '%s %s\n' "$WORK/lm5.tsv" "$WORK/batch_a.ply" "$WORK/lm5.tsv" "$WORK/batch_b.tsv" >"$WORK/batch.txt"
run facefit fit -m "$S/model.mmb" --batch "$WORK/batch.txt"
expect_status 0
expect_stdout_empty
run fcompare "$WORK/u.ply" "$WORK/batch_a.ply"
expect_status 0
check "coefficients equal" cmp "$WORK/c.tsv" "$WORK/batch_b.tsv"

case_ "sweep: U-shaped E_full against eta on novel faces (T2)"
run facefit sweep -m "$S/model.mmb" --faces "$S/test.txt" --vertices "$S/set50.tsv" --summary
expect_status 0
check "minimum strictly inside the eta grid" awk -F'\t' 'NR>1 {e[NR]=$9; if (min=="" || $9<min) {min=$9; at=NR}} END {exit !(at>3 && at<NR-1)}' "$out"
check "E_r non-decreasing" awk -F'\t' 'NR>2 && $6 < prev*(1-1e-9) {bad=1} NR>1 {prev=$6} END {exit bad}' "$out"

case_ "convert: .mmb -> .mmb and a NumPy .npz"
run facefit convert --from mmb "$S/model.mmb" -o "$WORK/copy.mmb"
expect_status 0
check "identical bytes" cmp "$S/model.mmb" "$WORK/copy.mmb"
run facefit convert --from npz "$FEST_FIXTURES/facefit/model_bfm_deflated_f4.npz" -o "$WORK/npz.mmb"
expect_status 0
run facefit info -m "$WORK/npz.mmb"
expect_json '.points' '4'
expect_json '.components' '2'

case_ "golden: synth seed 1, 32×32, set17, eta 2 (mesh within 1e-5 mm)"
"$F" project --mesh "$S/face105.ply" --vertices "$S/set17.tsv" >"$WORK/lm17.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/lm17.tsv" --eta 2 -o "$WORK/golden.ply"
expect_status 0
run fcompare "$FEST_FIXTURES/facefit/golden_fit_set17.ply" "$WORK/golden.ply" --tol 1e-5 --ordered -t 'vertex_max_abs<=1e-5'
expect_status 0

case_ "conventions: --help, --version, unknown flag, unknown subcommand"
run facefit --help
expect_status 0
check "usage" grep -q "Usage" "$out"
run facefit fit --help
expect_status 0
check "fit usage names --eta" grep -q -- "--eta" "$out"
run facefit --version
expect_status 0
check "version names fest" grep -q "(fest)" "$out"
run facefit fit --no-such-flag
expect_clean_failure 2 facefit
run facefit frobnicate
expect_clean_failure 2 facefit

# ---- bad input: one line on stderr, the right status, nothing on stdout ----
case_ "unknown landmark id"
printf 'id\tu\tv\nnose_tip\t150\t140\near_lobe\t10\t10\n' >"$WORK/unknown.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/unknown.tsv"
expect_clean_failure 3 facefit
expect_stderr_has "ear_lobe"
case_ "fewer than 3 mapped landmarks"
printf 'id\tu\tv\nnose_tip\t150\t140\nchin\t150\t210\n' >"$WORK/two.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/two.tsv"
expect_clean_failure 3 facefit
case_ "NaN coordinate"
printf 'id\tu\tv\nnose_tip\tnan\t140\nchin\t150\t210\nsubnasale\t150\t150\n' >"$WORK/nan.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/nan.tsv"
expect_clean_failure 3 facefit
expect_stderr_has "nan.tsv:2"
case_ "landmark TSV without a header"
printf 'nose_tip\t150\t140\n' >"$WORK/nohead.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/nohead.tsv"
expect_clean_failure 3 facefit
case_ "vertex index out of range"
printf 'vertex\tu\tv\n1\t1\t1\n2\t2\t2\n5000\t3\t3\n' >"$WORK/range.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/range.tsv"
expect_clean_failure 3 facefit
case_ "model with the wrong magic"
{ printf 'NOTAMODL'; tail -c +9 "$S/model.mmb"; } >"$WORK/magic.mmb"
run_stdin "$WORK/lm5.tsv" facefit fit -m "$WORK/magic.mmb"
expect_clean_failure 3 facefit
expect_stderr_has "magic"
case_ "truncated model"
head -c 100000 "$S/model.mmb" >"$WORK/trunc.mmb"
run_stdin "$WORK/lm5.tsv" facefit fit -m "$WORK/trunc.mmb"
expect_clean_failure 3 facefit
expect_stderr_has "truncated"
case_ "model header that is not JSON"
{ head -c 16 "$S/model.mmb"; printf '#'; tail -c +18 "$S/model.mmb"; } >"$WORK/json.mmb"
run facefit info -m "$WORK/json.mmb"
expect_clean_failure 3 facefit
case_ "missing model file"
run_stdin "$WORK/lm5.tsv" facefit fit -m "$WORK/nothere.mmb"
expect_clean_failure 4 facefit
case_ "no model at all"
FACEFIT_MODEL= run_stdin "$WORK/lm5.tsv" facefit fit
expect_clean_failure 2 facefit
case_ "negative eta"
run_stdin "$WORK/lm5.tsv" facefit fit -m "$S/model.mmb" --eta -1
expect_clean_failure 2 facefit
case_ "all landmarks on one point: degenerate affine camera"
awk 'NR==1 {print; next} {print $1 "\t150\t150"}' "$WORK/lm5.tsv" >"$WORK/same.tsv"
run facefit fit -m "$S/model.mmb" --landmarks "$WORK/same.tsv" --camera affine
expect_clean_failure 1 facefit

case_ "an .mmb header with a number where a word belongs: one line in the reader's words, exit 3"
# "units": "mm" -> "units": 9999 (same length, so the header length still holds).
python3 -c "import sys; d=open(sys.argv[1],'rb').read(); open(sys.argv[2],'wb').write(d.replace(b'\"units\": \"mm\"', b'\"units\": 9999', 1))" \
  "$FEST_FIXTURES/facefit/seeds/tiny.mmb" "$WORK/units_number.mmb"
run facefit info -m "$WORK/units_number.mmb"
expect_clean_failure 3 facefit
expect_stderr_has "mmb header: expected a string, got a number"

case_ "an .npz whose zip directory claims a member larger than the archive: refused before allocating"
# Found by fuzz_npz_model: a 1,244-byte archive whose stored sigma.npy claims 1.7 GB.
run facefit convert --from npz "$FEST_FIXTURES/regress/facefit/npz_member_beyond_archive.npz" -o "$WORK/oom.mmb"
expect_clean_failure 3 facefit
expect_stderr_has "claims 1601069426 compressed bytes in an archive of 1244"

finish
