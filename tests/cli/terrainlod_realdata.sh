#!/usr/bin/env bash
# terrainlod on real DEMs from Debian packages (scripts/fetch-test-data.sh): the GeoTIFFs
# of r-cran-terra (Luxembourg, int16 with nodata) and r-cran-stars (Olinda, float32, UTM).
. "$(dirname "$0")/lib.sh"
lux=$(need_testdata dem/luxembourg_elev.tif) || exit 77
olinda=$(need_testdata dem/olinda_dem_utm25s.tif) || exit 77

case_ "Luxembourg GeoTIFF: georeference, CRS and nodata from the tags"
run terrainlod stats "$lux" --tile 16
expect_status 0
expect_json '[.dem.format, .dem.width, .dem.height, .dem.georeferenced, .dem.integer, .dem.nodata_value]' \
  '["GTiff",95,90,true,true,-32768]'
check "nodata samples present" test "$(jq '.dem.nodata_samples' "$out")" -gt 0
check "CRS known" test "$(jq -r '.dem.crs' "$out")" != null
expect_json '.levels' '3'   # 94 cells -> 16 x 2^3 = 128

case_ "Olinda GeoTIFF: simplify within 2 m, re-measured error <= 2 (+ round-off)"
run terrainlod simplify "$olinda" --max-error 2 -o "$WORK/olinda.ply" --report "$WORK/o.json"
expect_status 0
cp "$WORK/o.json" "$out"
check "measured error <= bound" jq -e '.measured_error <= .max_error + .tolerance' "$out"
check "fewer triangles than the finest mesh (2 x 110^2)" jq -e '.triangles < 24200' "$out"
expect_json '.dem.format' '"GTiff"'

case_ "Jacksboro .npy (python-matplotlib-data) straight from the .npz: int16 344 x 403"
# (simplify on Jacksboro is timed in tests/bench/terrainlod.sh, not here: too slow for the suite)
npz=$(need_testdata dem/jacksboro_fault_dem.npz) || exit 77
unzip -p "$npz" elevation.npy >"$WORK/jb.npy"
run terrainlod stats "$WORK/jb.npy" --cell-size 74.5,92.5
expect_status 0
expect_json '[.dem.format, .dem.width, .dem.height, .dem.integer, .dem.z_min, .dem.z_max]' '["npy",403,344,true,236,1076]'
# 402 cells -> 64 x 2^3 = 512: L = 3; eps_0 = 512 x 74.5 / 64 = 596 (the smaller side is x)
expect_json '[.levels, .level[0].eps, .level[2].eps, .level[3].eps]' '[3,596,149,0]'

case_ "Jacksboro pyramid: progressive and standalone coding decode to the same tiles"
run terrainlod build "$WORK/jb.npy" --cell-size 74.5,92.5 -o "$WORK/jb.tlp" --threads 2
expect_status 0
run terrainlod build "$WORK/jb.npy" --cell-size 74.5,92.5 --coding standalone -o "$WORK/jb_s.tlp" --threads 2
expect_status 0
run terrainlod stats "$WORK/jb.tlp"
check "progressive is stored and smaller" \
  jq -e '.manifest.coding == "progressive" and .totals.tile_bytes == .totals.progressive_tile_bytes and .totals.progressive_tile_bytes < .totals.standalone_tile_bytes' "$out"
# Every tile's base triangulation, as export-qm writes it (one file per tile), from both.
run terrainlod export-qm "$WORK/jb.tlp" -o "$WORK/qm_p"
expect_status 0
run terrainlod export-qm "$WORK/jb_s.tlp" -o "$WORK/qm_s"
expect_status 0
check "one tile file per pyramid tile" test "$(find "$WORK/qm_p" -name '*.terrain' | wc -l)" -eq 59
check "the same tiles from both codings" diff -r "$WORK/qm_p" "$WORK/qm_s"
run terrainlod verify "$WORK/jb.tlp" --dem "$WORK/jb.npy" --cell-size 74.5,92.5 --cameras 6
expect_json '[.ok, .reencode_mismatches, .tiles_over_bound, .open_edges]' '[true,0,0,0]'

finish
