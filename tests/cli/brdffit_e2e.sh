#!/usr/bin/env bash
# brdffit end to end, both halves together: synth (known materials on patches of a sphere,
# the real Blender HDR environment as background when fetched) -> lumitexels -> cluster ->
# project, checked against synth's truth (the true material of every lumitexel's
# triangle); then normals on a synth run with tilted mesh normals, checked against the
# true normals of mesh_true.ply. Expected values come from truth.json / mesh_true.ply
# (read by brdffit_e2e.py), never from earlier runs.
source "$(dirname "$0")/lib.sh"
check_py="$(dirname "$0")/brdffit_e2e.py"
bin="$FEST_BIN/brdffit"

le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

env_args=()
if env_map=$(need_testdata hdr/studio.exr 2>/dev/null); then env_args=(--env "$env_map"); fi

# docs/brdffit.md §7: >= 98 % of the lumitexels with >= 6 samples labelled right, 1 % noise.
case_ "synth (3 materials, 12 views x 3 lights, 1 % noise) -> lumitexels -> cluster -> project"
run brdffit synth --sphere 3 --materials 3 --views 12 --lights 3 --width 160 --height 120 --noise 0.01 --seed 1 \
  "${env_args[@]}" -o "$WORK/syn"
expect_status 0
run brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" --threads 2 -o "$WORK/syn.ltx"
expect_status 0
run brdffit cluster --clusters 3 --min-samples 6 --threads 2 "$WORK/syn.ltx"
expect_status 0
cp "$out" "$WORK/clusters.json"
expect_json '.clusters | length' "$(jq '.materials | length' "$WORK/syn/truth.json")"
run brdffit project --clusters "$WORK/clusters.json" --threads 2 --report "$WORK/project.json" "$WORK/syn.ltx" \
  -o "$WORK/syn.ltw"
expect_status 0
read -r rate used < <(python3 "$check_py" assignment "$WORK/syn.ltx" "$WORK/syn.ltw" "$WORK/syn/truth.json" 6)
echo "assignment: $rate of $used lumitexels with >= 6 samples"
check "at least 1000 lumitexels with >= 6 samples" test "$used" -ge 1000
check "98 % of them in the cluster of their true material" le 0.98 "$rate"
check "projected error below the per-cluster error" \
  lt "$(jq .error_projected "$WORK/project.json")" "$(jq .error_per_cluster "$WORK/project.json")"

# render --svbrdf: the fitted materials on the surface, each triangle its lumitexels'
# majority cluster (brdffit_e2e.py derives the same materials from the documented .ltx
# and .ltw layouts, so the two renderings must agree exactly).
case_ "render --svbrdf --ltx: the fitted per-cluster materials, re-rendering an input view"
python3 "$check_py" materials "$WORK/syn.ltx" "$WORK/syn.ltw" "$WORK/syn/mesh.ply" > "$WORK/fitted_materials.json"
run brdffit render --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/syn.ltw" --ltx "$WORK/syn.ltx" \
  --rig "$WORK/syn/rig.json" --image 13 --threads 2 -o "$WORK/fit13.exr" --png "$WORK/fit13.png"
expect_status 0
expect_stdout_empty
"$bin" render --mesh "$WORK/syn/mesh.ply" --materials "$WORK/fitted_materials.json" --rig "$WORK/syn/rig.json" \
  --image 13 --threads 2 -o "$WORK/fit13_json.exr"
run brdffit eval --photo "$WORK/fit13_json.exr" --render "$WORK/fit13.exr"
expect_status 0
check "same image as the materials derived from the files' layouts" le "$(jq .relative_l2 "$out")" 0
# docs/brdffit.md §7: re-rendering from the fitted materials within 6 % (relative L2 inside the
# mask, 2 % noise; 3 % noise-free) -- here over every one of the 36 input views, not a
# held-out one, so the worst view (grazing light L1, most of the surface at its rim)
# counts as much as the median. With 1 % noise the truth itself re-renders at ~1 %.
: > "$WORK/rerender.txt"
views=$(jq '.images | length' "$WORK/syn/rig.json")
for ((i = 0; i < views; i++)); do
  "$bin" render --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/syn.ltw" --ltx "$WORK/syn.ltx" --rig "$WORK/syn/rig.json" \
    --image "$i" --threads 2 -o "$WORK/fit.exr"
  "$bin" eval --photo "$WORK/syn/$(jq -r ".images[$i].file" "$WORK/syn/rig.json")" --render "$WORK/fit.exr" \
    --mask "$WORK/syn/$(jq -r ".images[$i].mask" "$WORK/syn/rig.json")" | jq .relative_l2 >> "$WORK/rerender.txt"
done
read -r median worst rendered < <(python3 "$check_py" rerender "$WORK/rerender.txt")
echo "re-rendering of the $rendered input views from the fitted materials: relative L2 median $median, max $worst"
check "every input view re-rendered" test "$rendered" -eq "$views"
check "median relative L2 within the noise-free 3 % of docs/brdffit.md §7" le "$median" 0.03
check "every view's relative L2 within the 6 % of docs/brdffit.md §7" le "$worst" 0.06
"$bin" synth --sphere 2 --materials 1 --views 1 --width 32 --height 24 -o "$WORK/other" 2>/dev/null
run brdffit render --mesh "$WORK/other/mesh.ply" --svbrdf "$WORK/syn.ltw" --ltx "$WORK/syn.ltx" \
  --rig "$WORK/syn/rig.json" --image 0 -o "$WORK/never.exr"
expect_clean_failure 3
expect_stderr_has "does not match the lumitexel file"
run brdffit render --mesh "$WORK/syn/mesh_nope.ply" --svbrdf "$WORK/syn.ltw" --ltx "$WORK/syn.ltx" \
  --rig "$WORK/syn/rig.json" --image 0 -o "$WORK/never.exr"
expect_clean_failure 4
run brdffit render --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/syn.ltw" --rig "$WORK/syn/rig.json" --image 0 \
  -o "$WORK/never.exr"
expect_clean_failure 2
expect_stderr_has "--svbrdf needs --ltx"
run brdffit render --mesh "$WORK/syn/mesh.ply" --svbrdf "$WORK/syn.ltw" --ltx "$WORK/syn.ltx" \
  --materials "$WORK/syn/truth.json" --rig "$WORK/syn/rig.json" --image 0 -o "$WORK/never.exr"
expect_clean_failure 2
check "nothing written" test ! -e "$WORK/never.exr"

# docs/brdffit.md §7 on synth's data: the written mesh's normals are tilted (mesh_true.ply keeps
# the truth); the refined normals must be closer to the truth than the tilted ones.
case_ "synth --perturb-normals 8 -> lumitexels -> cluster -> project -> normals"
run brdffit synth --sphere 3 --materials 3 --views 8 --lights 2 --width 160 --height 120 --perturb-normals 8 \
  --seed 1 -o "$WORK/tilt"
expect_status 0
check "mesh_true.ply written" test -s "$WORK/tilt/mesh_true.ply"
"$bin" lumitexels --mesh "$WORK/tilt/mesh.ply" --rig "$WORK/tilt/rig.json" --threads 2 -o "$WORK/tilt.ltx"
"$bin" cluster --clusters 3 --threads 2 "$WORK/tilt.ltx" -o "$WORK/tilt_clusters.json"
"$bin" project --clusters "$WORK/tilt_clusters.json" --threads 2 "$WORK/tilt.ltx" -o "$WORK/tilt.ltw"
run brdffit normals --svbrdf "$WORK/tilt.ltw" --threads 2 --report "$WORK/normals.json" "$WORK/tilt.ltx"
expect_status 0
cp "$out" "$WORK/normals.ply"
read -r refined given < <(python3 "$check_py" normals "$WORK/tilt.ltx" "$WORK/normals.ply" "$WORK/tilt/mesh_true.ply")
echo "median angle to the true normals: refined $refined deg, mesh $given deg"
check "the mesh normals are tilted (median above 1 degree)" lt 1 "$given"
check "refined normals closer to the truth than the mesh normals" lt "$refined" "$given"
check "residual decreased" lt "$(jq .residual_after "$WORK/normals.json")" "$(jq .residual_before "$WORK/normals.json")"

# capture.md 5.1: the simulated station (a sphere of two Lafortune materials, material 1
# where x < the centre's x) -> hdrmerge's rig (frame "turntable") -> lumitexels on a
# sphere mesh placed where the scene puts it -> cluster --clusters 2 finds both halves.
if [ -x "$FEST_BIN/capture" ] && [ -x "$FEST_BIN/hdrmerge" ]; then
  case_ "capture run | hdrmerge --manifest - -> lumitexels -> cluster --clusters 2"
  cp "$FEST_FIXTURES/capture/small_scene.json" "$FEST_FIXTURES/capture/small_station.json" "$WORK/"
  scene="$WORK/small_scene.json"
  ( cd "$WORK" && "$FEST_BIN/capture" plan --angles 8 --lights L0 --bracket 1/1000:1:12 --silhouette BG > plan.json &&
    "$FEST_BIN/capture" run --station small_station.json --plan plan.json -o sess 2>/dev/null |
    "$FEST_BIN/hdrmerge" --manifest - -o sess/hdr > rig.json )
  check "hdrmerge wrote a turntable rig" test "$(jq -r .frame "$WORK/rig.json" 2>/dev/null)" = turntable
  radius=$(jq '.object.radius_mm' "$scene")
  "$bin" synth --sphere 4 --radius "$radius" --materials 1 --views 1 --width 16 --height 16 -o "$WORK/ball" 2>/dev/null
  python3 "$check_py" translate "$WORK/ball/mesh.ply" $(jq -r '.object.centre_mm | map(tostring) | join(" ")' "$scene") \
    > "$WORK/sphere_tt.ply"
  run brdffit lumitexels --mesh "$WORK/sphere_tt.ply" --rig "$WORK/rig.json" --threads 2 -o "$WORK/cap.ltx"
  expect_status 0
  run brdffit cluster --clusters 2 --threads 2 "$WORK/cap.ltx"
  expect_status 0
  cp "$out" "$WORK/cap_clusters.json"
  expect_json '.clusters | length' 2
  "$bin" project --clusters "$WORK/cap_clusters.json" --threads 2 "$WORK/cap.ltx" -o "$WORK/cap.ltw"
  read -r rate used < <(python3 "$check_py" halves "$WORK/cap.ltx" "$WORK/cap.ltw" "$(jq '.object.centre_mm[0]' "$scene")" 2)
  echo "capture: $rate of $used lumitexels with >= 2 samples in their half's cluster"
  check "at least 1000 lumitexels" test "$used" -ge 1000
  check "98 % of them in the cluster of their half" le 0.98 "$rate"
fi

finish
