#!/usr/bin/env bash
# brdffit export (textured glTF, docs/brdffit.md §4, §6) and factor (§6) timings. The docs
# sets no target for either; the cases show how baking scales with the atlas size and the
# mesh, and what the fitted-surface lookup (nearest lumitexel per texel) costs. One JSON
# line per case: wall and CPU seconds, peak memory, atlas size.
#
#   tests/bench/brdffit_export.sh [BIN_DIR] [WORK_DIR]      (defaults: build/bin, a temp dir)
# Not run by CTest. Set THREADS (default 2, the project machine's cores).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bin="${1:-$here/../../build/bin}"
work="${2:-$(mktemp -d)}"
threads="${THREADS:-2}"
mkdir -p "$work"

# case_ NAME NOTE -- COMMAND...: {"case", "wall_s", "cpu_s", "peak_rss_mb", "note"}
case_() {
  local name="$1" note="$2"; shift 3
  local t0 t1
  t0=$(date +%s.%N)
  /usr/bin/time -f '%U %S %M' -o "$work/$name.time" "$@" > "$work/$name.stdout"
  t1=$(date +%s.%N)
  read -r user sys rss < "$work/$name.time"
  jq -cn --arg c "$name" --argjson wall "$(echo "$t1 - $t0" | bc)" --argjson cpu "$(echo "$user + $sys" | bc)" \
    --argjson rss "$((rss / 1024))" --arg note "$note" --argjson threads "$threads" \
    '{case: $c, threads: $threads, wall_s: $wall, cpu_s: $cpu, peak_rss_mb: $rss, note: $note}'
}

# A bird-size mesh (sphere L5, 20,480 triangles) with 5 materials: the bake from truth.json.
"$bin/brdffit" synth --sphere 5 --materials 5 --views 1 --width 64 --height 48 -o "$work/big" 2>/dev/null
for size in 1024 2048 4096; do
  case_ "export_truth_$size" "20480 triangles, --materials, --texture-size $size" -- \
    "$bin/brdffit" export --mesh "$work/big/mesh.ply" --materials "$work/big/truth.json" --texture-size "$size" \
    --threads "$threads" --gltf "$work/big_$size.glb"
done

# The fitted chain at the example's size (sphere L4, 8 views x 2 lights, 320x240), then
# the export with the nearest-lumitexel blend and refined normals.
"$bin/brdffit" synth --sphere 4 --materials 3 --views 8 --lights 2 --width 320 --height 240 -o "$work/fit" 2>/dev/null
"$bin/brdffit" lumitexels --mesh "$work/fit/mesh.ply" --rig "$work/fit/rig.json" --threads "$threads" -o "$work/fit.ltx"
"$bin/brdffit" cluster --clusters 3 "$work/fit.ltx" --threads "$threads" -o "$work/fit.clusters.json"
"$bin/brdffit" project --clusters "$work/fit.clusters.json" "$work/fit.ltx" --threads "$threads" -o "$work/fit.ltw"
"$bin/brdffit" normals "$work/fit.ltx" --svbrdf "$work/fit.ltw" --threads "$threads" -o "$work/fit_normals.ply"
case_ export_fitted_1024 "5120 triangles, $(jq -r '"\(.lumitexels) lumitexels"' <("$bin/brdffit" info "$work/fit.ltx")), --svbrdf --normals, --texture-size 1024" -- \
  "$bin/brdffit" export --mesh "$work/fit/mesh.ply" --svbrdf "$work/fit.ltw" --ltx "$work/fit.ltx" \
  --normals "$work/fit_normals.ply" --threads "$threads" --gltf "$work/fit.glb"
case_ lumitexels_atlas "the same rig with --atlas (home images re-read, charts, EXR)" -- \
  "$bin/brdffit" lumitexels --mesh "$work/fit/mesh.ply" --rig "$work/fit/rig.json" --threads "$threads" \
  --atlas "$work/fit_atlas.exr" --report "$work/fit_atlas.json" -o "$work/fit_atlas.ltx"
jq -c '{case: "lumitexels_atlas_size", atlas}' "$work/fit_atlas.json"

# factor at the default grid (32 x 64 x 32 x 64, a 2048 x 2048 matrix per channel).
jq '.materials[0]' "$work/fit/truth.json" > "$work/paint.json"
case_ factor_32x64 "one lobe, half/difference and (omega_o, omega_i)" -- \
  "$bin/brdffit" factor --brdf "$work/paint.json" --threads "$threads" -o "$work/paint_"
jq -c '{case: "factor_errors", half_difference: .half_difference.relative_rms, out_in: .out_in.relative_rms}' \
  "$work/factor_32x64.stdout"
