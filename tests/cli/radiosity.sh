#!/usr/bin/env bash
# radiosity: analytic cases (furnace, form factors of unit squares), the Cornell box,
# determinism, outputs and bad scenes.
source "$(dirname "$0")/lib.sh"
EX="$(dirname "$0")/../../examples/radiosity"

case_ "golden: the built-in Cornell box scene (the Cornell data, docs/radiosity.md §3)"
run radiosity cornell
expect_status 0
check "cornell.json equals the golden file" "$FEST_BIN/fcompare" -q "$FEST_FIXTURES/radiosity/cornell.json" "$out"
expect_json '.objects | map(.name) | join(",")' '"floor,ceiling,light,back_wall,right_wall,left_wall,short_block,tall_block"'

case_ "furnace: closed box, rho 0.5, E 1 -> B = E/(1 - rho) = 2 everywhere (analytic engine, to 1e-3)"
run radiosity solve "$EX/furnace.json" --emission exitance --ff analytic --samples 4 --tol 1e-6 --levels 0 \
  --report "$WORK/furnace.json" -o "$WORK/furnace.ply"
expect_status 0
check "min >= 1.998" jq -e '.radiosity.min | all(. >= 1.998)' "$WORK/furnace.json"
check "max <= 2.002" jq -e '.radiosity.max | all(. <= 2.002)' "$WORK/furnace.json"
check "closed scene" jq -e '.scene.closed == true' "$WORK/furnace.json"
check "emitted = absorbed" jq -e '.energy.relative_imbalance | fabs < 1e-3' "$WORK/furnace.json"
check "PLY header carries rad_r and object_id" grep -a -q 'property float rad_r' "$WORK/furnace.ply"

case_ "furnace as a PLY scene (face properties object_id, refl_*, emit_*) on standard input: B = 2"
run_stdin "$FEST_FIXTURES/radiosity/furnace_scene.ply" radiosity solve --emission exitance --ff analytic --samples 4 \
  --tol 1e-6 --levels 0 --patch-size 0.25 --report "$WORK/fply.json" -o "$WORK/fply.ply"
expect_status 0
check "B = 2 to 1e-3" jq -e '(.radiosity.min | all(. >= 1.998)) and (.radiosity.max | all(. <= 2.002))' "$WORK/fply.json"
check "object named from the header comment" jq -e '.scene.objects == ["box"]' "$WORK/fply.json"
sed 's/refl_g/gloss_g/' "$FEST_FIXTURES/radiosity/furnace_scene.ply" >"$WORK/norefl.ply"
run radiosity solve "$WORK/norefl.ply"; expect_clean_failure 3 radiosity; expect_stderr_has 'refl_r, refl_g, refl_b'

case_ "furnace with the default engine (hybrid: hemicube visibility, exact values): B = 2 to 1e-3"
run radiosity solve "$EX/furnace.json" --emission exitance --hemicube-res 64 --tol 1e-6 --levels 0 --report "$WORK/fhy.json" -o /dev/null
expect_status 0
check "min >= 1.998, max <= 2.002" jq -e '(.radiosity.min | all(. >= 1.998)) and (.radiosity.max | all(. <= 2.002))' "$WORK/fhy.json"

case_ "mesh file named by the scene (relative to the scene's folder), scaled by a transform: still B = 2"
mkdir -p "$WORK/meshdir"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 4 3 7 8\nf 1 4 8 5\nf 2 6 7 3\n' >"$WORK/meshdir/box.obj"
printf '{"objects": [{"name": "box", "mesh": "box.obj", "reflectance": 0.5, "emission": 1, "transform": [3,0,0,0, 0,3,0,0, 0,0,3,0, 0,0,0,1]}]}' >"$WORK/meshdir/scene.json"
run radiosity solve "$WORK/meshdir/scene.json" --emission exitance --ff analytic --samples 4 --tol 1e-6 --levels 0 \
  --patch-size 1 --report "$WORK/mesh_r.json" -o /dev/null
expect_status 0
check "B = 2 to 1e-3, diagonal 3 sqrt 3" jq -e '(.radiosity.min | all(. >= 1.998)) and (.radiosity.max | all(. <= 2.002)) and ((.scene.diagonal - 5.196152) | fabs < 1e-5)' "$WORK/mesh_r.json"

case_ "a glTF mesh whose geometry is in an external .bin, named by a scene in another folder"
# The quad (10,20,30)-(13,22,30) of fconv_scenes.sh; alone it sees nothing, so B = E = 1.
mkdir -p "$WORK/gltfscene"
printf '{"objects": [{"name": "quad", "mesh": "%s", "reflectance": 0.5, "emission": 1}]}' \
  "$FEST_FIXTURES/mesh/external_buffer/quad.gltf" >"$WORK/gltfscene/scene.json"
run radiosity solve "$WORK/gltfscene/scene.json" --emission exitance --ff analytic --levels 0 --patch-size 1 \
  --report "$WORK/gltf_r.json" -o /dev/null
expect_status 0
check "B = 1, diagonal sqrt 13" jq -e '(.radiosity.min | all(. > 0.999)) and (.radiosity.max | all(. < 1.001)) and ((.scene.diagonal - 3.605551) | fabs < 1e-5)' "$WORK/gltf_r.json"

case_ "furnace rho 0.9 with the hemicube: mean B = 10 (energy), every element within 5 %"
sed 's/0.5, 0.5, 0.5/0.9, 0.9, 0.9/' "$EX/furnace.json" >"$WORK/furnace9.json"
run radiosity solve "$WORK/furnace9.json" --emission exitance --ff hemicube --hemicube-res 128 --tol 1e-4 --max-shots 100000 --levels 0 \
  --report "$WORK/f9.json" -o /dev/null
expect_status 0
check "mean 10 +- 0.01" jq -e '.radiosity.mean | all(. > 9.99 and . < 10.01)' "$WORK/f9.json"
check "min/max within 5 %" jq -e '(.radiosity.min | all(. > 9.5)) and (.radiosity.max | all(. < 10.5))' "$WORK/f9.json"

case_ "form factors of unit squares: parallel at distance 1 (0.19982), perpendicular (0.20004)"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' >"$WORK/bottom.obj"
printf 'v 0 0 1\nv 0 1 1\nv 1 1 1\nv 1 0 1\nf 1 2 3 4\n' >"$WORK/top.obj"
printf 'v 0 0 0\nv 0 1 0\nv 0 1 1\nv 0 0 1\nf 1 2 3 4\n' >"$WORK/wall.obj"
for ff in analytic hemicube; do
  run radiosity formfactor --ff "$ff" "$WORK/bottom.obj" "$WORK/top.obj"
  expect_status 0
  check "$ff parallel" jq -e '(.F_AB - 0.19982 | fabs) < 0.002 and (.F_BA - 0.19982 | fabs) < 0.002' "$out"
  run radiosity formfactor --ff "$ff" "$WORK/bottom.obj" "$WORK/wall.obj"
  expect_status 0
  check "$ff perpendicular" jq -e '(.F_AB - 0.20004 | fabs) < 0.002' "$out"
done

case_ "Cornell box: 8 objects split, report with time split, orpr <= 0.75 x pr shots, picture"
run radiosity solve "$FEST_FIXTURES/radiosity/cornell.json" --hemicube-res 64 --levels 0 --solver pr \
  --report "$WORK/pr.json" -o /dev/null
expect_status 0
expect_stderr_has 'warning: the scene is open'
run radiosity solve "$FEST_FIXTURES/radiosity/cornell.json" --hemicube-res 64 --levels 1 --report "$WORK/orpr.json" \
  --log "$WORK/shots.csv" --split-objects "$WORK/split" --view "$WORK/view.png" --view-width 64 -o "$WORK/lit.ply"
expect_status 0
check "8 object files" test "$(ls "$WORK/split" | wc -l)" -eq 8
check "time split" jq -e '.time | has("visibility_s") and has("solve_s") and has("subdivision_s")' "$WORK/orpr.json"
check "radiosity range" jq -e '.radiosity | has("min") and has("max") and has("mean")' "$WORK/orpr.json"
check "orpr needs <= 0.75 x the shots of pr" jq -e --slurpfile pr "$WORK/pr.json" \
  '.shots_per_level[0] <= 0.75 * $pr[0].shots' "$WORK/orpr.json"
check "log header" grep -q '^shot,patch,object,unshot_fraction,omega,seconds,level$' "$WORK/shots.csv"
check "PNG picture" sh -c "head -c 8 '$WORK/view.png' | od -An -tx1 | grep -q '89 50 4e 47'"
check "lit PLY reads back" "$FEST_BIN/fconv" --info "$WORK/lit.ply"
run radiosity render "$WORK/lit.ply" --width 32 -o "$WORK/render.png"
expect_status 0
check "render PNG" test -s "$WORK/render.png"

case_ "deterministic: 1 and 2 threads give the same bytes"
"$FEST_BIN/radiosity" solve "$FEST_FIXTURES/radiosity/cornell.json" --hemicube-res 32 --levels 1 --threads 1 -q -o "$WORK/t1.ply"
"$FEST_BIN/radiosity" solve "$FEST_FIXTURES/radiosity/cornell.json" --hemicube-res 32 --levels 1 --threads 2 -q -o "$WORK/t2.ply"
check "identical" cmp "$WORK/t1.ply" "$WORK/t2.ply"

case_ "bad scenes: exit 3, one message, nothing written"
scene() { printf '{"objects": [{"name": "q", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "faces": [%s], "reflectance": %s, "emission": %s}]}' "$1" "$2" "$3"; }
scene '[0,1,2,3]' '[1.2,0.5,0.5]' '[1,1,1]' >"$WORK/rho.json"
run radiosity solve "$WORK/rho.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'reflectance'
scene '[0,1,2,3]' '0.999' '1' >"$WORK/rho1.json"
run radiosity solve "$WORK/rho1.json"; expect_status 0
scene '[0,1,2,3]' '1.0' '1' >"$WORK/rho2.json"
run radiosity solve "$WORK/rho2.json"; expect_clean_failure 3 radiosity
scene '[0,1,2,3]' '-0.1' '1' >"$WORK/neg.json"
run radiosity solve "$WORK/neg.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'outside \[0, 0.999\]'
scene '[0,1,2,3]' '0.5' '[-1,0,0]' >"$WORK/emit.json"
run radiosity solve "$WORK/emit.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'negative emission'
scene '[0,1,2,3]' '0.5' '0' >"$WORK/dark.json"
run radiosity solve "$WORK/dark.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'no emitter'
scene '[0,1,2,7]' '0.5' '1' >"$WORK/index.json"
run radiosity solve "$WORK/index.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'names vertex 7'
scene '[0,1,2,3],[0,1,1]' '0.5' '1' >"$WORK/zero.json"
run radiosity solve "$WORK/zero.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'zero-area'
scene '[0,1,2,3]' '"NaN"' '1' >"$WORK/nan.json"
run radiosity solve "$WORK/nan.json"; expect_clean_failure 3 radiosity
printf '' >"$WORK/empty.json"
run radiosity solve "$WORK/empty.json"; expect_clean_failure 3 radiosity
printf '{"objects": []}' >"$WORK/none.json"
run radiosity solve "$WORK/none.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'no objects'
printf '{"objects": [{"mesh": "missing.obj", "reflectance": 0.5, "emission": 1}]}' >"$WORK/missing.json"
run radiosity solve "$WORK/missing.json"; expect_clean_failure 4 radiosity
printf '{"objects": [{"mesh": "a.obj", "reflectance": 0.5, "texture": "w.png"}]}' >"$WORK/tex.json"
run radiosity solve "$WORK/tex.json"; expect_clean_failure 3 radiosity; expect_stderr_has 'texture'
check "no output file after bad input" test ! -e "$WORK/never.ply"
run radiosity solve "$WORK/rho.json" -o "$WORK/never.ply"; check "still no file" test ! -e "$WORK/never.ply"

case_ "open scene: allowed, reported"
scene '[0,1,2,3]' '0.5' '1' >"$WORK/open.json"
run radiosity solve "$WORK/open.json" --report "$WORK/open_r.json" -o "$WORK/open.ply"
expect_status 0
expect_stderr_has 'open: 4 edge'
check "closed false" jq -e '.scene.closed == false and .scene.open_edges == 4' "$WORK/open_r.json"

case_ "--help, --version, a missing scene (exit 4)"
run radiosity --help; expect_status 0; check "usage" grep -q "Usage" "$out"
run radiosity --version; expect_status 0; check "names fest" grep -q "(fest)" "$out"
run radiosity solve "$WORK/does-not-exist.json"; expect_clean_failure 4 radiosity; expect_stderr_has 'does-not-exist'

case_ "usage errors: exit 2"
run radiosity solve "$EX/furnace.json" --hemicube-res 7; expect_clean_failure 2 radiosity
run radiosity solve "$EX/furnace.json" --solver jacobi; expect_clean_failure 2 radiosity
run radiosity frobnicate; expect_clean_failure 2 radiosity

case_ "a PLY whose list count is a float of 1e120: one line, exit 3 (fuzz_radiosity_scene)"
run radiosity solve "$FEST_FIXTURES/regress/radiosity/ply_list_count_1e120.ply" -o "$WORK/never.ply"
expect_clean_failure 3 radiosity
expect_stderr_has "bad vertex_indices list"

case_ "fuzz_radiosity_scene finding: a propertyless vertex element of 6.7e12 instances (38 s per input before) is refused at once"
run radiosity solve "$FEST_FIXTURES/regress/radiosity/ply_propertyless_element_6.7e12.ply" -o "$WORK/never.ply"
expect_clean_failure 3 radiosity
expect_stderr_has "declares 6666666666666 instances but no properties"

finish
