#!/usr/bin/env bash
# isosurf on real data from Debian packages: the Cranium CT (invesalius-examples) bone
# surface and the Colin27 brain (mricron-data), against the reference counts measured with
# VTK 9.1 (vtkMarchingCubes / vtkFlyingEdges3D, docs/isosurf.md "Validation"):
#   CT bone iso 225.5, padded -1024: 339 096 vertices, 678 480 triangles, chi -144,
#     area 297 930.8 mm^2, volume 661 509.5 mm^3, closed
#   ch2bet iso 50.5, padded 0: 252 992 vertices, 504 948 triangles, area 174 487.6, volume 1 655 514.9
# The vertex count is the number of crossed voxel edges (no table can change it); with
# --face-rule separate (VTK's ambiguity choice) the triangle count and chi must match too.
# Watertightness is checked by isosurf stats and independently by isovol/fixtures.py.
source "$(dirname "$0")/lib.sh"
FX="python3 $(dirname "$0")/isovol/fixtures.py"
ct=$(need_testdata volumes/cranium.nrrd) || exit 77
mri=$(need_testdata mri/ch2bet.nii.gz) || exit 77
W="$WORK"

within() {  # within VALUE REFERENCE RELATIVE_TOLERANCE
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = (a - b) / b; if (d < 0) d = -d; exit !(d <= t) }'
}

case_ "Cranium bone, decider (default)"
run isosurf exact "$ct" --iso 225.5 --cap -1024 -o "$W/bone.ply" --report "$W/bone.json"
expect_status 0
check "vertices 339096" test "$(jq .vertices "$W/bone.json")" = 339096
check "closed (stats)" test "$(jq .closed "$W/bone.json")" = true
check "no non-manifold vertices" test "$(jq .nonmanifold_vertices "$W/bone.json")" = 0
read -r closed v f chi area vol < <($FX plycheck "$W/bone.ply")
check "closed (independent)" test "$closed" = closed
check "triangles = 2 (V - chi)" test "$f" = $((2 * (v - chi)))
# minimal-area loop triangulation gives 0.30 % less area than VTK's table (measured)
check "area within 0.5 % of VTK ($area)" within "$area" 297930.8 0.005
check "volume within 0.1 % of VTK ($vol)" within "$vol" 661509.5 0.001

case_ "Cranium bone, --face-rule separate: VTK's topology exactly"
run isosurf exact "$ct" --iso 225.5 --cap -1024 --face-rule separate --tri fan -o "$W/bone_s.ply" --report "$W/bone_s.json"
expect_status 0
check "vertices" test "$(jq .vertices "$W/bone_s.json")" = 339096
check "triangles 678480" test "$(jq .triangles "$W/bone_s.json")" = 678480
check "chi -144" test "$(jq .euler "$W/bone_s.json")" = -144
check "closed" test "$(jq .closed "$W/bone_s.json")" = true
check "area within 0.05 %" within "$(jq .area "$W/bone_s.json")" 297930.8 0.0005
check "volume within 0.1 %" within "$(jq .volume "$W/bone_s.json")" 661509.5 0.001

case_ "Cranium bone, adaptive around the volume centre (r0 16 mm, distance rule only): closed, >= 5x fewer triangles"
# The plan asks >= 5x fewer than exact (678 348 here). Edge rule `transitions` (default):
# measured 14.8x (45 944); `all` keeps every thin feature that crosses a leaf edge: 4.4x.
run isosurf adaptive "$ct" --iso 225.5 --cap -1024 --focus 122,122,80 --focus-radius 16 --max-error inf -o "$W/bone_ad.ply" --report "$W/bone_ad.json"
expect_status 0
check "closed" test "$(jq .closed "$W/bone_ad.json")" = true
check ">= 5x fewer triangles ($(jq .triangles "$W/bone_ad.json"))" test "$(jq '.triangles * 5 <= 678348' "$W/bone_ad.json")" = true
read -r closed _ < <($FX plycheck "$W/bone_ad.ply")
check "closed (independent)" test "$closed" = closed
run isosurf adaptive "$ct" --iso 225.5 --cap -1024 --focus 122,122,80 --focus-radius 16 --max-error inf --edge-rule all -o "$W/bone_ad_all.ply" --report "$W/bone_ad_all.json"
expect_status 0
read -r closed _ < <($FX plycheck "$W/bone_ad_all.ply")
check "edge rule all: closed (independent)" test "$closed" = closed
check "edge rule all: more triangles than transitions" test "$(jq .triangles "$W/bone_ad_all.json")" -gt "$(jq .triangles "$W/bone_ad.json")"

case_ "Colin27 brain (ch2bet)"
run isosurf exact "$mri" --iso 50.5 --cap 0 --face-rule separate -o "$W/brain.ply" --report "$W/brain.json"
expect_status 0
check "vertices 252992" test "$(jq .vertices "$W/brain.json")" = 252992
check "triangles 504948" test "$(jq .triangles "$W/brain.json")" = 504948
check "closed" test "$(jq .closed "$W/brain.json")" = true
read -r closed _ < <($FX plycheck "$W/brain.ply")
check "closed (independent)" test "$closed" = closed
check "volume within 0.1 %" within "$(jq .volume "$W/brain.json")" 1655514.9 0.001
run isosurf stats "$W/brain.ply"
expect_json .closed true
expect_json .triangles 504948

finish
