#!/usr/bin/env bash
# terrainlod end to end: analytic DEMs (a plane is two triangles, georeference carried into
# the mesh), every plain input format, standard input, stats, and bad input with clean
# errors and nothing written.
. "$(dirname "$0")/lib.sh"

# 5 x 4 samples, h = i - row + 4 (a tilted plane), 10 m cells, lower-left corner (100, 200).
plane_asc() {
  printf 'ncols 5\nnrows 4\nxllcorner 100\nyllcorner 200\ncellsize 10\nNODATA_value -9999\n'
  printf '1 2 3 4 5\n2 3 4 5 6\n3 4 5 6 7\n4 5 6 7 8\n'
}
plane_asc >"$WORK/plane.asc"

case_ "--help"
run terrainlod --help
expect_status 0
check "help names simplify" grep -q simplify "$out"

case_ "a plane simplifies to 2 triangles on its 4 corners, in world coordinates"
run terrainlod simplify "$WORK/plane.asc" --max-error 0 -o "$WORK/plane.obj" --report "$WORK/r.json"
expect_status 0
expect_stdout_empty
check "2 faces" test "$(grep -c '^f ' "$WORK/plane.obj")" -eq 2
check "4 vertices" test "$(grep -c '^v ' "$WORK/plane.obj")" -eq 4
# Sample centres: x = 105 .. 145, y = 205 .. 235; the north-west sample (row 0) is height 1.
check "north-west corner" grep -qx 'v 105 235 1' "$WORK/plane.obj"
check "south-east corner" grep -qx 'v 145 205 8' "$WORK/plane.obj"
cp "$WORK/r.json" "$out"
expect_json '.triangles' '2'
expect_json '.dem.georeferenced' 'true'
expect_json '.dem.format' '"AAIGrid"'

case_ "standard input through GDAL's memory files, PLY on stdout"
run_stdin "$WORK/plane.asc" terrainlod simplify - --max-error 0
expect_status 0
check "PLY with 2 faces" grep -qa 'element face 2' "$out"

case_ "--cell-size and --origin override the file; a bump keeps its vertex"
printf 'P2\n3 3\n65535\n0 0 0\n0 1000 0\n0 0 0\n' >"$WORK/bump.pgm"
run terrainlod simplify "$WORK/bump.pgm" --max-error 999 --cell-size 2 --origin 10,20 --to obj
expect_status 0
check "bump apex kept (error 1000 > 999)" grep -qx 'v 12 22 1000' "$out"
run terrainlod simplify "$WORK/bump.pgm" --max-error 1000 --to obj
expect_status 0
check "bump removed at 1000" test "$(grep -c '^f ' "$out")" -eq 2

case_ "--start rtin and lattice on a square 2^k + 1 DEM: both within --max-error, re-measured"
# 33 x 33 samples of a smooth bowl with integer ripples (h = (i - 16)^2 + (j - 16)^2 / 2 + (i j) mod 7).
awk 'BEGIN { print "ncols 33\nnrows 33\nxllcorner 0\nyllcorner 0\ncellsize 1";
  for (r = 0; r < 33; r++) { line = ""; for (i = 0; i < 33; i++) { j = 32 - r;
    line = line sprintf("%d ", (i - 16) * (i - 16) + int((j - 16) * (j - 16) / 2) + (i * j) % 7) } print line } }' >"$WORK/bowl.asc"
for start in rtin lattice; do
  run terrainlod simplify "$WORK/bowl.asc" --max-error 4 --start "$start" -o "$WORK/bowl.ply" --report "$WORK/b.json"
  expect_status 0
  cp "$WORK/b.json" "$out"
  expect_json '.start' "\"$start\""
  check "$start: measured error <= 4" jq -e '.measured_error <= 4 + .tolerance' "$out"
  check "$start: simplified" jq -e '.triangles < 2 * 32 * 32' "$out"
done

case_ "PFM and .npy without flags"
# 2 x 2 PFM (little-endian, rows bottom to top): heights 1 2 / 3 4.
printf 'Pf\n2 2\n-1.0\n\x00\x00\x80\x3f\x00\x00\x00\x40\x00\x00\x40\x40\x00\x00\x80\x40' >"$WORK/t.pfm"
run terrainlod stats "$WORK/t.pfm"
expect_status 0
expect_json '.dem.format' '"pfm"'
expect_json '[.dem.z_min, .dem.z_max]' '[1,4]'
{ printf '\x93NUMPY\x01\x00\x76\x00'; printf "%-117s\n" "{'descr': '<i2', 'fortran_order': False, 'shape': (2, 3), }"
  printf '\x01\x00\x02\x00\x03\x00\x04\x00\x05\x00\x06\x00'; } >"$WORK/t.npy"
run terrainlod stats "$WORK/t.npy" --tile 4
expect_status 0
expect_json '[.dem.width, .dem.height, .dem.integer, .levels]' '[3,2,true,0]'

case_ "16-bit PNG through GDAL (made by fconv from a plain PGM), with --z-scale/--z-offset"
printf 'P2\n3 2\n65535\n0 1000 65535\n7 8 9\n' >"$WORK/p16.pgm"
if "$FEST_BIN/fconv" "$WORK/p16.pgm" -o "$WORK/p16.png" 2>/dev/null; then
  run terrainlod stats "$WORK/p16.png" --tile 4 --z-scale 0.1 --z-offset -100
  expect_status 0
  expect_json '[.dem.format, .dem.z_min, .dem.z_max]' '["PNG",-100,6453.5]'
fi

case_ "stats: level plan of a 257 x 257 grid, B = 64: eps halves per level, 0 at the leaves"
awk 'BEGIN { print "ncols 257\nnrows 257\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 257; r++) { s = ""; for (c = 0; c < 257; c++) s = s (c ? " " : "") (r + c) % 7; print s } }' >"$WORK/g257.asc"
run terrainlod stats "$WORK/g257.asc"
expect_status 0
expect_json '[.levels, .padded_size, (.level | map(.eps))]' '[2,257,[40,20,0]]'
expect_json '.level[2] | [.tiles_x, .tiles_y]' '[4,4]'

case_ "nodata filled from the nearest valid sample"
printf 'ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\n5 -9999 5\n5 5 5\n' >"$WORK/nd.asc"
run terrainlod simplify "$WORK/nd.asc" --max-error 0 --report "$WORK/nd.json" -o "$WORK/nd.ply"
expect_status 0
cp "$WORK/nd.json" "$out"
expect_json '[.dem.nodata_samples, .triangles]' '[1,2]'

# --- bad input: one line on stderr, the exit status of README "Conventions", nothing written -------
bad() {  # bad STATUS REGEX ARGS...
  local status="$1" regex="$2"; shift 2
  rm -f "$WORK/out.ply"
  run terrainlod "$@"
  expect_clean_failure "$status"
  expect_stderr_has "$regex"
  check "no output file" test ! -e "$WORK/out.ply"
}

case_ "a DEM of one column"
printf 'ncols 1\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n2\n3\n' >"$WORK/col.asc"
bad 3 'DEM has 1 column and 3 rows; at least 2 x 2 samples needed \(.*col.asc\)' simplify "$WORK/col.asc" --max-error 1 -o "$WORK/out.ply"

case_ "all samples nodata"
printf 'ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -1\n-1 -1\n-1 -1\n' >"$WORK/none.asc"
bad 3 'all samples are nodata \(.*none.asc\)' simplify "$WORK/none.asc" --max-error 1 -o "$WORK/out.ply"

case_ "NaN heights: an error unless --nodata nan"
printf 'Pf\n2 2\n-1.0\n\x00\x00\x80\x3f\x00\x00\xc0\x7f\x00\x00\x40\x40\x00\x00\x80\x40' >"$WORK/nan.pfm"
bad 3 'DEM has 1 NaN height; pass --nodata nan' simplify "$WORK/nan.pfm" --max-error 1 -o "$WORK/out.ply"
run terrainlod simplify "$WORK/nan.pfm" --max-error 0 --nodata nan -o "$WORK/nan.ply"
expect_status 0

case_ "tile size not a power of two"
bad 2 'error: --tile must be a power of two between 4 and 4096 \(got 48\)' stats "$WORK/plane.asc" --tile 48

case_ "texels below the tile size"
bad 2 'texels \(32\) must be at least --tile \(64\)' stats "$WORK/plane.asc" --texels 32

case_ "negative --max-error"
bad 2 'max-error must be a finite number >= 0' simplify "$WORK/plane.asc" --max-error -1 -o "$WORK/out.ply"

case_ "not a DEM, empty file, missing file"
printf 'hello\n' >"$WORK/junk.txt"
bad 3 'not a DEM that GDAL can read' simplify "$WORK/junk.txt" --max-error 1 -o "$WORK/out.ply"
: >"$WORK/empty.asc"
bad 3 'empty file' simplify "$WORK/empty.asc" --max-error 1 -o "$WORK/out.ply"
bad 4 'nope.asc' simplify "$WORK/nope.asc" --max-error 1 -o "$WORK/out.ply"

case_ "truncated .npy"
head -c 130 "$WORK/t.npy" >"$WORK/short.npy"
bad 3 'npy data is truncated' simplify "$WORK/short.npy" --max-error 1 -o "$WORK/out.ply"

case_ "unknown output extension is a usage error before reading"
bad 2 'error:' simplify "$WORK/plane.asc" --max-error 1 -o "$WORK/out.xyz"
bad 2 'start' simplify "$WORK/bowl.asc" --max-error 4 --start quadtree -o "$WORK/out.ply"

case_ "GDAL is a plugin: PGM and PNG DEMs need none, an ASCII grid without it is exit 4 naming the package"
printf 'P2\n3 2\n65535\n0 1000 65535\n7 8 9\n' >"$WORK/nogdal.pgm"
FEST_PLUGIN_DIR="$WORK/no-plugins" run terrainlod stats "$WORK/nogdal.pgm" --tile 4
expect_status 0
if "$FEST_BIN/fconv" "$WORK/nogdal.pgm" -o "$WORK/nogdal.png" 2>/dev/null; then
  FEST_PLUGIN_DIR="$WORK/no-plugins" run terrainlod stats "$WORK/nogdal.png" --tile 4
  expect_status 0
  expect_json '[.dem.format, .dem.z_max]' '["PNG",65535]'
fi
FEST_PLUGIN_DIR="$WORK/no-plugins" run terrainlod stats "$WORK/plane.asc"
expect_clean_failure 4 terrainlod
expect_stderr_has "libgdal32"

finish
