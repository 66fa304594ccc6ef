#!/usr/bin/env bash
# brdffit export: glTF 2.0 with the materials baked into a texture atlas (docs/brdffit.md §4,
# §6). Structure checked against the glTF and PNG specifications
# (brdffit_gltf.py), values against synth's truth.json: each triangle's base colour is
# sRGB(rho_d) of its material and its roughness sqrt(2/(N+2)); a one-material object bakes
# one constant colour. Then the fitted chain (lumitexels -> cluster -> project -> normals ->
# export) with a normal map, the .glb and stdout forms, and bad input.
source "$(dirname "$0")/lib.sh"

gltf_py="$(dirname "$0")/brdffit_gltf.py"
# Runs the checker like `run` runs a tool ($rc, $out, $err).
pycheck() { python3 "$gltf_py" "$@" >"$out" 2>"$err"; rc=$?; }
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }

case_ "synth: sphere, 3 materials"
run brdffit synth --sphere 3 --materials 3 --views 6 --width 160 --height 120 --seed 2 -o "$WORK/syn"
expect_status 0

case_ "export from truth.json: textures beside the .gltf"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --gltf "$WORK/out/obj.gltf" \
  --texture-size 256
expect_status 4  # the output folder does not exist
expect_stdout_empty
mkdir -p "$WORK/out"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --gltf "$WORK/out/obj.gltf" \
  --texture-size 256
expect_status 0
expect_stdout_empty
check "base colour PNG beside" test -f "$WORK/out/obj_basecolor.png"
check "metallic-roughness PNG beside" test -f "$WORK/out/obj_metalrough.png"
check "no normal map without --normals" test ! -e "$WORK/out/obj_normal.png"
pycheck check "$WORK/out/obj.gltf"
expect_status 0
expect_json '.triangles' 1280
expect_json '.textures' '["baseColor","metallicRoughness"]'
check "atlas about --texture-size on its longer side" le "$(jq '[.width, .height] | max' "$out")" 281
check "UVs inside [0, 1]" le 0 "$(jq .uv_min "$out")"
check "UVs inside [0, 1] (max)" le "$(jq .uv_max "$out")" 1
pycheck truth "$WORK/out/obj.gltf" "$WORK/syn/truth.json"
expect_status 0
expect_json '.base_steps <= 1' true
expect_json '.roughness_steps <= 1' true

case_ "one material bakes one constant colour: sRGB(rho_d)"
jq '.triangle_material |= map(0) | .materials[0].rho_d = [0.5, 0.25, 0.75]' "$WORK/syn/truth.json" > "$WORK/one.json"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/one.json" --gltf "$WORK/out/one.gltf" --texture-size 128
expect_status 0
# sRGB(0.5) = 0.7354 -> 188, sRGB(0.25) = 0.5371 -> 137, sRGB(0.75) = 0.8808 -> 225
pycheck constant "$WORK/out/one.gltf" 188 137 225
expect_status 0

case_ "same bytes with 1 and 2 threads"
mkdir -p "$WORK/t1"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --gltf "$WORK/t1/obj.gltf" \
  --texture-size 256 --threads 1
expect_status 0
check "same glTF" cmp "$WORK/t1/obj.gltf" "$WORK/out/obj.gltf"
check "same base colour" cmp "$WORK/t1/obj_basecolor.png" "$WORK/out/obj_basecolor.png"

case_ "fitted chain with refined normals: normal map, .glb"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" -o "$WORK/o.ltx"
expect_status 0
run_stdin "$WORK/o.ltx" brdffit cluster --clusters 3
expect_status 0
cp "$out" "$WORK/c.json"
run brdffit project --clusters "$WORK/c.json" "$WORK/o.ltx" -o "$WORK/s.ltw"
expect_status 0
run brdffit normals "$WORK/o.ltx" --svbrdf "$WORK/s.ltw" -o "$WORK/n.ply"
expect_status 0
run brdffit export --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/s.ltw" --ltx "$WORK/o.ltx" --normals "$WORK/n.ply" \
  --gltf "$WORK/out/fit.glb" --texture-size 256
expect_status 0
check "glb magic" test "$(head -c 4 "$WORK/out/fit.glb")" = glTF
check "no PNG files beside a .glb" test ! -e "$WORK/out/fit_basecolor.png"
pycheck check "$WORK/out/fit.glb"
expect_status 0
expect_json '.textures' '["baseColor","metallicRoughness","normal"]'

case_ "lumitexels --atlas: the home images' pixels packed (docs/brdffit.md §4), smaller than the images"
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" --atlas "$WORK/out/atlas.exr" \
  --report "$WORK/atlas_report.json" -o "$WORK/o_atlas.ltx"
expect_status 0
check "the .ltx does not change" cmp "$WORK/o_atlas.ltx" "$WORK/o.ltx"
pycheck exr_size "$WORK/out/atlas.exr"
expect_json "[.width, .height]" "$(jq -c '[.atlas.width, .atlas.height]' "$WORK/atlas_report.json")"
check "atlas smaller than its home images" le "$(jq '.atlas.width * .atlas.height' "$WORK/atlas_report.json")" \
  "$(jq '.atlas.home_image_pixels' "$WORK/atlas_report.json")"
check "mesh with texture coordinates" grep -aq "^property float s$" "$WORK/out/atlas.ply"
check "three vertices per face" test "$(grep -a '^element vertex' "$WORK/out/atlas.ply" | cut -d' ' -f3)" = \
  "$(( 3 * $(grep -a '^element face' "$WORK/out/atlas.ply" | cut -d' ' -f3) ))"

case_ "standard output: one .gltf with data URIs"
run brdffit export --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/s.ltw" --ltx "$WORK/o.ltx" --gltf - --texture-size 128
expect_status 0
cp "$out" "$WORK/stdout.gltf"
pycheck check "$WORK/stdout.gltf"
expect_status 0
expect_json '.images | length' 2

case_ "--flat keeps one constant material per BRDF"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --flat --gltf -
expect_status 0
expect_json '.materials | length' 3
expect_json '[.materials[].pbrMetallicRoughness.baseColorTexture] | map(select(. != null)) | length' 0

case_ "factor: a Lambertian BRDF is exactly rank 1 (docs/brdffit.md §6, factor)"
echo '{"model":"lafortune","lobes":0,"rho_d":[0.5,0.3,0.1],"Cxy":[],"Cz":[],"N":[]}' > "$WORK/lambert.json"
run brdffit factor --brdf "$WORK/lambert.json" -o "$WORK/lam_" --theta-bins 16 --phi-bins 32
expect_status 0
check "half/difference error 0" le "$(jq .half_difference.relative_rms "$out")" 1e-6
check "(omega_o, omega_i) error 0" le "$(jq .out_in.relative_rms "$out")" 1e-6
pycheck exr_size "$WORK/lam_g.exr"
expect_json '[.width, .height]' '[32,16]'
check "h written" test -f "$WORK/lam_h.exr"

case_ "factor: a Lafortune lobe (N = 20) is more separable in half/difference angles"
echo '{"model":"lafortune","lobes":1,"rho_d":[0.1,0.1,0.1],"Cxy":[[-1,-1,-1]],"Cz":[[1,1,1]],"N":[[20,20,20]]}' \
  > "$WORK/lobe.json"
run brdffit factor --brdf "$WORK/lobe.json" -o "$WORK/lobe_" --theta-bins 16 --phi-bins 32
expect_status 0
echo "  factor N=20: $(jq -c '[.half_difference.relative_rms, .out_in.relative_rms]' "$out")"
check "half/difference error below (omega_o, omega_i)" le "$(jq .half_difference.relative_rms "$out")" \
  "$(jq '.out_in.relative_rms * 0.999' "$out")"

case_ "factor: bad input"
run brdffit factor --brdf "$WORK/missing.json" -o "$WORK/x_"
expect_clean_failure 4 brdffit
echo '{"model":"lafortune"}' > "$WORK/broken.json"
run brdffit factor --brdf "$WORK/broken.json" -o "$WORK/x_"
expect_clean_failure 3 brdffit
check "no factor written" test ! -e "$WORK/x_g.exr"
run brdffit factor --brdf "$WORK/lobe.json" -o "$WORK/x_" --theta-bins 100 --phi-bins 100
expect_clean_failure 2 brdffit

case_ "bad input"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --svbrdf "$WORK/s.ltw" --gltf -
expect_clean_failure 2 brdffit
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --normals "$WORK/n.ply" --gltf -
expect_clean_failure 2 brdffit
run brdffit export --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/s.ltw" --gltf -
expect_clean_failure 2 brdffit
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" --texel 1e-5 --gltf -
expect_clean_failure 2 brdffit
expect_stderr_has "texels"
run brdffit synth --sphere 2 --materials 1 --views 2 --width 32 --height 32 -o "$WORK/other"
run brdffit export --mesh "$WORK/other/mesh.ply" --svbrdf "$WORK/s.ltw" --ltx "$WORK/o.ltx" --gltf -
expect_clean_failure 3 brdffit
expect_stderr_has "does not match"
run brdffit export --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/s.ltw" --ltx "$WORK/o.ltx" \
  --normals "$WORK/other/mesh.ply" --gltf "$WORK/out/never.gltf"
expect_clean_failure 3 brdffit
check "nothing written" test ! -e "$WORK/out/never.gltf"
check "no texture written" test ! -e "$WORK/out/never_basecolor.png"
jq '.triangle_material = [0, 1]' "$WORK/syn/truth.json" > "$WORK/bad_mats.json"
run brdffit export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/bad_mats.json" --gltf -
expect_clean_failure 3 brdffit

finish
