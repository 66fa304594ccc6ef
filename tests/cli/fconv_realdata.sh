#!/usr/bin/env bash
# fconv on the real data fetched from Debian packages (scripts/fetch-test-data.sh).
. "$(dirname "$0")/lib.sh"
bunny=$(need_testdata meshes/bunny00.off) || exit 77
head=$(need_testdata mri/t1_head.nii.gz) || exit 77
camera=$(need_testdata images/camera.png) || exit 77
city=$(need_testdata hdr/city.exr) || exit 77

# The bunny has 37 706 vertices and 75 408 triangles (CGAL's data; checked with
# OpenMesh).
case_ "bunny: PLY -> OFF -> PLY (binary) -> OBJ through standard input/output"
"$FEST_BIN/fconv" "$bunny" -o "$WORK/bunny.ply"
"$FEST_BIN/fconv" --to off <"$WORK/bunny.ply" | "$FEST_BIN/fconv" --to ply | "$FEST_BIN/fconv" --to obj >"$WORK/bunny.obj"
run fconv --info "$WORK/bunny.obj"
expect_status 0
expect_json '.vertices' '37706'
expect_json '.faces' '75408'
run fcompare --ordered "$WORK/bunny.ply" "$WORK/bunny.obj" --report "$WORK/report.json"
expect_status 0
check "zero surface distance" grep -qx "hausdorff 0" "$out"
check "bit-identical vertices" grep -qx "vertex_max_abs 0" "$out"
check "report says pass" test "$(jq .pass "$WORK/report.json")" = "true"
check "bunny is closed genus 0" test "$(jq -c '[.details.topology_a.genus, .details.topology_a.boundary_loops]' "$WORK/report.json")" = "[0,0]"

case_ "a truncated bunny: one line on standard error, nothing on standard output"
head -c 300 "$WORK/bunny.ply" >"$WORK/cut.ply"
run_stdin "$WORK/cut.ply" fconv --to off
expect_clean_failure 3 fconv

case_ "T1 head: NIfTI.gz -> NRRD -> MHA -> NIfTI keeps voxels and geometry"
run fconv --info "$head"
expect_json '.dimensions' '[128,128,62]'
expect_json '.spacing' '[2,2,3]'
expect_json '.value_type' '"int16"'
"$FEST_BIN/fconv" --to nrrd <"$head" | "$FEST_BIN/fconv" --to mha | "$FEST_BIN/fconv" --to nii.gz >"$WORK/head.nii.gz"
run fcompare "$head" "$WORK/head.nii.gz"
expect_status 0

case_ "camera: PNG -> PGM -> PNG is exact"
"$FEST_BIN/fconv" --to pgm <"$camera" | "$FEST_BIN/fconv" --to png >"$WORK/camera.png"
run fcompare "$camera" "$WORK/camera.png"
expect_status 0
check "max_abs 0" grep -qx "max_abs 0" "$out"

case_ "HDR: EXR -> PFM -> EXR (float) is exact"
"$FEST_BIN/fconv" --to pfm <"$city" | "$FEST_BIN/fconv" --to exr >"$WORK/city.exr"
run fcompare "$city" "$WORK/city.exr"
expect_status 0

finish
