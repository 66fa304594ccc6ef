#!/usr/bin/env bash
# brdffit (geometry stages) end to end: synth renders a sphere with known Lafortune
# materials under a real Blender HDR environment when fetched; lumitexels resamples the
# images (sample radiance checked against the materials' BRDFs through render/eval);
# render reproduces a synth photograph exactly; register recovers a turntable rig; then
# bad input: one clean line, the right status, nothing on standard output.
source "$(dirname "$0")/lib.sh"

le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }

case_ "help"
run brdffit --help
expect_status 0
check "help names the subcommands" grep -q "lumitexels" "$out"

env_args=()
if env_map=$(need_testdata hdr/studio.exr 2>/dev/null); then env_args=(--env "$env_map"); fi

case_ "synth: sphere, 3 materials, 8 views x 2 lights"
run brdffit synth --sphere 3 --materials 3 --views 8 --lights 2 --width 160 --height 120 --seed 1 \
  "${env_args[@]}" -o "$WORK/syn"
expect_status 0
expect_stdout_empty
check "rig.json lists 16 images" test "$(jq '.images | length' "$WORK/syn/rig.json")" = 16
check "rig frame is mesh" test "$(jq -r .frame "$WORK/syn/rig.json")" = mesh
check "truth has 3 materials" test "$(jq '.materials | length' "$WORK/syn/truth.json")" = 3
check "masks per angle" test -f "$WORK/syn/hdr/a007_mask.png"

case_ "synth is deterministic"
run brdffit synth --sphere 3 --materials 3 --views 8 --lights 2 --width 160 --height 120 --seed 1 \
  "${env_args[@]}" -o "$WORK/syn2"
check "same image bytes" cmp "$WORK/syn/hdr/a003_L1.exr" "$WORK/syn2/hdr/a003_L1.exr"
check "same rig" cmp "$WORK/syn/rig.json" "$WORK/syn2/rig.json"

case_ "render reproduces a synth photograph (same materials, camera, light)"
run brdffit render --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --rig "$WORK/syn/rig.json" \
  --image 5 -o "$WORK/r5.exr" --mask-out "$WORK/r5_mask.png" --png "$WORK/r5.png"
expect_status 0
run brdffit eval --photo "$WORK/syn/hdr/a002_L1.exr" --render "$WORK/r5.exr" --mask "$WORK/syn/hdr/a002_mask.png"
expect_status 0
check "relative L2 error below 1e-6" le "$(jq .relative_l2 "$out")" 1e-6
check "masks agree" cmp "$WORK/r5_mask.png" "$WORK/syn/hdr/a002_mask.png"

case_ "lumitexels"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" --report "$WORK/ltx.json" \
  -o "$WORK/syn.ltx"
expect_status 0
check "magic" test "$(head -c 8 "$WORK/syn.ltx")" = LUMITEX1
check "at least 4 samples per lumitexel on average" le 4 "$(jq .mean_samples "$WORK/ltx.json")"
check "header carries the mesh hash" grep -qa "$(jq -r .mesh_sha256 "$WORK/syn/truth.json")" "$WORK/syn.ltx"

case_ "lumitexels to a pipe, same bytes with 1 and 2 threads"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" --threads 1
expect_status 0
check "stdout equals the file" cmp "$out" "$WORK/syn.ltx"

case_ "eval: a darker rendering is 10 % off"
run brdffit render --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --rig "$WORK/syn/rig.json" \
  --image 0 -o "$WORK/r0.exr"
jq '.images[0].light.intensity |= map(. * 0.9)' "$WORK/syn/rig.json" > "$WORK/syn/rig_dim.json"
run brdffit render --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --rig "$WORK/syn/rig_dim.json" \
  --image 0 -o "$WORK/r0_dim.exr"
run brdffit eval --photo "$WORK/r0.exr" --render "$WORK/r0_dim.exr" --mask "$WORK/syn/hdr/a000_mask.png" \
  --error "$WORK/err.exr"
expect_status 0
check "relative L2 = 0.1" awk -v e="$(jq .relative_l2 "$out")" 'BEGIN { exit !(e > 0.0999 && e < 0.1001) }'
check "error image written" test -s "$WORK/err.exr"

# Rotate every camera by 4 degrees about z (R := R Rz(4 deg)): the mesh frame is off.
turn_rig() {
  local c s
  c=$(awk 'BEGIN { printf "%.17g", cos(4*atan2(0,-1)/180) }'); s=$(awk 'BEGIN { printf "%.17g", sin(4*atan2(0,-1)/180) }')
  jq --argjson c "$c" --argjson s "$s" '.frame = "turntable" | .images[].camera.R |= [
    .[0]*$c + .[1]*$s, -.[0]*$s + .[1]*$c, .[2],
    .[3]*$c + .[4]*$s, -.[3]*$s + .[4]*$c, .[5],
    .[6]*$c + .[7]*$s, -.[6]*$s + .[7]*$c, .[8]]' "$1" > "$2"
}
# Largest |R_ij| difference between the cameras of two rigs.
rig_r_diff() {
  jq -s '[.[0].images, .[1].images] | transpose | map([.[0].camera.R, .[1].camera.R] | transpose
         | map((.[0]-.[1]) | fabs) | max) | max' "$1" "$2"
}

case_ "register --rig: silhouettes of a sphere stay matched (its turn about z is invisible)"
turn_rig "$WORK/syn/rig.json" "$WORK/syn/rig_off.json"
run brdffit register --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig_off.json" --fix-focal --iters 60 \
  --report "$WORK/reg.json" -o "$WORK/syn/rig_back.json"
expect_status 0
check "frame mesh" test "$(jq -r .frame "$WORK/syn/rig_back.json")" = mesh
check "XOR below 1 %" le "$(jq .xor "$WORK/reg.json")" 0.01

if bunny=$(need_testdata meshes/bunny_scan.ply 2>/dev/null); then
  case_ "register --rig: the bunny's rig turned by 4 degrees is brought back (every camera)"
  "$FEST_BIN/brdffit" synth --mesh "$bunny" --materials 1 --views 8 --width 200 --height 150 --elevation 35 \
    -o "$WORK/tb" 2>/dev/null
  turn_rig "$WORK/tb/rig.json" "$WORK/tb/rig_off.json"
  check "the turned rig is 4 degrees off" le 0.05 "$(rig_r_diff "$WORK/tb/rig.json" "$WORK/tb/rig_off.json")"
  run brdffit register --mesh "$WORK/tb/mesh.ply" --rig "$WORK/tb/rig_off.json" --fix-focal --iters 150 \
    --report "$WORK/treg.json" -o "$WORK/tb/rig_back.json"
  expect_status 0
  check "cameras within 0.01 (about 0.5 degrees) of the truth" le "$(rig_r_diff "$WORK/tb/rig.json" "$WORK/tb/rig_back.json")" 0.01
  check "XOR below 0.5 %" le "$(jq .xor "$WORK/treg.json")" 0.005
fi

# ------------------------------------------------------------------------- bad input
case_ "info: the .ltx belongs to its mesh, not to another"
"$FEST_BIN/brdffit" synth --sphere 2 --materials 1 --views 2 --width 64 --height 48 -o "$WORK/tiny" 2>/dev/null
run brdffit info "$WORK/syn.ltx" --mesh "$WORK/syn/mesh.ply"
expect_status 0
expect_json .mesh_matches true
run brdffit info "$WORK/syn.ltx" --mesh "$WORK/tiny/mesh.ply"
expect_clean_failure 3
expect_stderr_has "does not match the lumitexel file"

case_ ".ltx with a wrong magic, truncated"
{ printf 'LUMITEXX'; tail -c +9 "$WORK/syn.ltx"; } > "$WORK/bad_magic.ltx"
run brdffit info "$WORK/bad_magic.ltx"
expect_clean_failure 3
head -c 20000 "$WORK/syn.ltx" > "$WORK/short.ltx"
run_stdin "$WORK/short.ltx" brdffit info
expect_clean_failure 3
expect_stderr_has "truncated"

case_ "no lumitexel with enough samples"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" --min-samples 60000
expect_clean_failure 3
expect_stderr_has "no lumitexel has >= 60000 samples"

case_ "image size does not match the camera"
jq '.images[3].camera.width = 170' "$WORK/syn/rig.json" > "$WORK/syn/rig_bad.json"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig_bad.json"
expect_clean_failure 3
expect_stderr_has "160x120 but its camera is 170x120"

case_ "rig image missing"
jq '.images[1].file = "hdr/none.exr"' "$WORK/syn/rig.json" > "$WORK/syn/rig_missing.json"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig_missing.json"
expect_clean_failure 4

case_ "mesh without faces"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n' > "$WORK/nofaces.ply"
run brdffit lumitexels --mesh "$WORK/nofaces.ply" --rig "$WORK/syn/rig.json"
expect_clean_failure 3
expect_stderr_has "no faces"

case_ "render: materials do not fit the mesh"
jq '.triangle_material = [0, 1]' "$WORK/syn/truth.json" > "$WORK/bad_mats.json"
run brdffit render --mesh "$WORK/syn/mesh.ply" --materials "$WORK/bad_mats.json" --rig "$WORK/syn/rig.json" \
  --image 0 -o "$WORK/never.exr"
expect_clean_failure 3
check "nothing written" test ! -e "$WORK/never.exr"

case_ "eval: sizes differ"
run brdffit eval --photo "$WORK/syn/hdr/a000_L0.exr" --render "$WORK/tiny/hdr/a000_L0.exr"
expect_clean_failure 3

case_ "register: XOR above --max-xor fails with status 1"
run brdffit register --mesh "$WORK/tiny/mesh.ply" --mask "$WORK/syn/hdr/a000_mask.png" \
  --camera <(jq '.images[0].camera' "$WORK/syn/rig.json") --iters 5 --max-xor 0.0001
expect_clean_failure 1

case_ "usage"
run brdffit lumitexels --rig "$WORK/syn/rig.json"
expect_clean_failure 2
run brdffit synth --views 0 -o "$WORK/x"
expect_clean_failure 2

finish
