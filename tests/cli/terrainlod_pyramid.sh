#!/usr/bin/env bash
# terrainlod pyramids end to end: counts of a plane from geometry alone, the error bound
# and crack-freeness checked by verify on a bumpy DEM, transitions adding exactly one
# triangle per inserted border point, extraction, determinism over threads, bad input.
. "$(dirname "$0")/lib.sh"

# 65 x 65 tilted plane (h = i + 2 * row), 10 m cells.
awk 'BEGIN { print "ncols 65\nnrows 65\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 65; r++) { s = ""; for (c = 0; c < 65; c++) s = s (c ? " " : "") (c + 2 * r); print s } }' >"$WORK/plane.asc"
# 65 x 65 bumps: integer heights, ridges in both directions.
awk 'BEGIN { print "ncols 65\nnrows 65\nxllcorner 1000\nyllcorner 2000\ncellsize 10";
  for (r = 0; r < 65; r++) { s = ""; for (c = 0; c < 65; c++) s = s (c ? " " : "") int(40 * sin(c / 5.0) * cos(r / 7.0) + (c * r) % 7); print s } }' >"$WORK/bumps.asc"

case_ "a plane: every tile is its 4n border points and at most one interior vertex"
run terrainlod build "$WORK/plane.asc" --tile 16 -o "$WORK/plane.tlp"
expect_status 0
expect_stdout_empty
run terrainlod stats "$WORK/plane.tlp"
expect_status 0
# L = 2: 1 + 4 + 16 tiles of n = 16 lattice cells, 64 border points each. On a plane every
# interior vertex is removable except the last one of a tile (every half-edge collapse of
# it would make a triangle of three collinear border points). Euler for a triangulated
# polygon of B border and I interior points: T = 2 I + B - 2.
expect_json '[.manifest.levels, .totals.tiles]' '[2,21]'
check "at most one interior vertex per tile" jq -e '.totals.vertices >= 1344 and .totals.vertices <= 1344 + 21' "$out"
check "Euler: T = 2 I + B - 2 per tile" jq -e '.totals.triangles == 2 * (.totals.vertices - 1344) + 21 * 62' "$out"
expect_json '.level | map(.eps)' '[40,20,0]'

case_ "bumps: verify checks all 16 transitions of every tile against the DEM, and random cameras"
run terrainlod build "$WORK/bumps.asc" --tile 16 -o "$WORK/bumps.tlp" --threads 1
expect_status 0
run terrainlod verify "$WORK/bumps.tlp" --dem "$WORK/bumps.asc" --cameras 12 --seed 3
expect_status 0
expect_json '[.ok, .tiles_over_bound, .open_edges, .reencode_mismatches]' '[true,0,0,0]'
check "max error <= 4/3 eps" jq -e '.max_err_over_eps <= 1.3333334' "$out"
check "the cameras saw more than one level" jq -e '.camera_levels_seen >= 2' "$out"

case_ "--reference l+1 and original: verify holds each to its bound (2 eps, eps)"
run terrainlod build "$WORK/bumps.asc" --tile 8 --reference l+1 -o "$WORK/bumps_l1.tlp"
expect_status 0
run terrainlod verify "$WORK/bumps_l1.tlp" --dem "$WORK/bumps.asc"
expect_status 0
expect_json '[.ok, .tiles_over_bound, .bound_over_eps]' '[true,0,2]'
run terrainlod build "$WORK/bumps.asc" --tile 8 --reference original -o "$WORK/bumps_o.tlp"
expect_status 0
run terrainlod verify "$WORK/bumps_o.tlp" --dem "$WORK/bumps.asc"
expect_status 0
expect_json '[.ok, .tiles_over_bound, .bound_over_eps]' '[true,0,1]'
run terrainlod build "$WORK/bumps.asc" --reference l+3 -o "$WORK/never.tlp"
expect_clean_failure 2 terrainlod
check "nothing written" test ! -e "$WORK/never.tlp"

case_ "--start lattice (the engine from the full lattice) keeps the bound too; a bad --start is a usage error"
run terrainlod build "$WORK/bumps.asc" --tile 16 --start lattice -o "$WORK/bumps_lat.tlp" --threads 1
expect_status 0
run terrainlod verify "$WORK/bumps_lat.tlp" --dem "$WORK/bumps.asc"
expect_status 0
expect_json '[.ok, .tiles_over_bound]' '[true,0]'
check "max error <= 4/3 eps" jq -e '.max_err_over_eps <= 1.3333334' "$out"
run terrainlod build "$WORK/bumps.asc" --start quadtree -o "$WORK/never.tlp"
expect_clean_failure 2 terrainlod
check "nothing written" test ! -e "$WORK/never.tlp"

case_ "--diagonal ne and alternate: the leaves start from the DEM surface's own cells and verify holds"
for d in ne alternate; do
  run terrainlod build "$WORK/bumps.asc" --tile 16 --diagonal "$d" -o "$WORK/bumps_$d.tlp" --threads 1
  expect_status 0
  run terrainlod verify "$WORK/bumps_$d.tlp" --dem "$WORK/bumps.asc"
  expect_status 0
  expect_json '[.ok, .tiles_over_bound]' '[true,0]'
done

case_ "a transition towards a finer east neighbour adds one triangle per inserted point"
run terrainlod decode "$WORK/bumps.tlp" --tile 1/0/0 --mask 0 --to obj
expect_status 0
base=$(grep -c '^f ' "$out")
run terrainlod decode "$WORK/bumps.tlp" --tile 1/0/0 --mask 4 --to obj
expect_status 0
# n = 16 border edges on the east side, one fine midpoint each.
check "16 more triangles" test "$(grep -c '^f ' "$out")" -eq $((base + 16))

case_ "build is independent of the thread count"
run terrainlod build "$WORK/bumps.asc" --tile 16 -o "$WORK/bumps2.tlp" --threads 2
expect_status 0
check "same bytes" cmp -s "$WORK/bumps.tlp" "$WORK/bumps2.tlp"

case_ "extract: a camera over the bumps, mesh and PNG"
printf '{"eye": [1300, 1600, 300], "target": [1300, 2300, 0], "fovy_deg": 60, "width": 320, "height": 200, "near": 1}\n' >"$WORK/cam.json"
run terrainlod extract "$WORK/bumps.tlp" --camera "$WORK/cam.json" --tau 2 -o "$WORK/view.ply" --png "$WORK/view.png" --report "$WORK/x.json"
expect_status 0
check "PNG written" test -s "$WORK/view.png"
cp "$WORK/x.json" "$out"
check "triangles extracted" jq -e '.triangles > 0 and .tiles > 0' "$out"

case_ "extract --path: after the first frame, steps of 1 % of a leaf tile load no new tiles"
# Leaf tiles are 16 cells x 10 m = 160 m: steps of 1.6 m.
awk 'BEGIN { for (k = 0; k < 6; k++) printf "{\"eye\": [%.1f, 1600, 300], \"target\": [1300, 2300, 0], \"width\": 320, \"height\": 200, \"tau_px\": 2}\n", 1300 + 1.6 * k }' >"$WORK/path.jsonl"
mkdir -p "$WORK/frames"
run terrainlod extract "$WORK/bumps.tlp" --path "$WORK/path.jsonl" -o "$WORK/frames/%03d.ply" --report "$WORK/p.json"
expect_status 0
check "six frames" test -s "$WORK/frames/005.ply"
cp "$WORK/p.json" "$out"
check "frame 0 loads tiles" jq -e '.frames[0].tiles_loaded > 0' "$out"
expect_json '[.frames[1:][] | .tiles_loaded] | add' '0'
bad_pattern_out=$(mktemp -d)
run terrainlod extract "$WORK/bumps.tlp" --path "$WORK/path.jsonl" -o "$bad_pattern_out/frame.ply"
expect_clean_failure 2 terrainlod
expect_stderr_has 'needs one %d or %0Nd'
check "nothing written" test -z "$(ls "$bad_pattern_out")"

case_ "export-qm: one quantized-mesh tile per pyramid tile and a layer.json"
run terrainlod export-qm "$WORK/bumps.tlp" -o "$WORK/qm"
expect_status 0
check "21 tiles" test "$(find "$WORK/qm" -name '*.terrain' | wc -l)" -eq 21
check "layer.json" jq -e '.format == "quantized-mesh-1.0" and .scheme == "tms" and .maxzoom == 2' "$WORK/qm/layer.json"
# Root tile: vertex count after the 88-byte header equals the tile's vertex count.
run terrainlod stats "$WORK/bumps.tlp"
check "root vertex count" test "$(od -An -tu4 -j88 -N4 "$WORK/qm/0/0/0.terrain" | tr -d ' ')" -eq "$(jq '.level[0].vertices' "$out")"
run terrainlod export-qm "$WORK/bumps.tlp" -o "$WORK/qm"
expect_clean_failure 4 terrainlod
expect_stderr_has 'exists and is not an empty directory'

case_ "coding: progressive by default, standalone on request; same tiles; stats give both sizes"
run terrainlod build "$WORK/bumps.asc" --tile 16 --coding standalone -o "$WORK/bumps_s.tlp" --threads 1
expect_status 0
run terrainlod stats "$WORK/bumps.tlp"
cp "$out" "$WORK/stats_p.json"
expect_json '[.manifest.coding, .totals.coding]' '["progressive","progressive"]'
check "stored = progressive size, smaller than standalone" \
  jq -e '.totals.tile_bytes == .totals.progressive_tile_bytes and .totals.progressive_tile_bytes < .totals.standalone_tile_bytes' "$out"
check "the root has no parent: same size both ways" jq -e '.level[0].progressive_bytes == .level[0].standalone_bytes' "$out"
run terrainlod stats "$WORK/bumps_s.tlp"
expect_json '.manifest.coding' '"standalone"'
check "stored = standalone size" jq -e '.totals.tile_bytes == .totals.standalone_tile_bytes' "$out"
# Recoding keeps the strip order: either archive gives both sizes exactly.
check "both archives agree on both sizes" test "$(jq -c '[.totals.standalone_tile_bytes, .totals.progressive_tile_bytes]' "$out")" = \
  "$(jq -c '[.totals.standalone_tile_bytes, .totals.progressive_tile_bytes]' "$WORK/stats_p.json")"
same=0
for l in 0 1 2; do
  for x in $(seq 0 $(( (1 << l) - 1 ))); do
    for y in $(seq 0 $(( (1 << l) - 1 ))); do
      "$FEST_BIN/terrainlod" decode "$WORK/bumps.tlp" --tile "$l/$x/$y" -o "$WORK/dp.ply" 2>/dev/null &&
        "$FEST_BIN/terrainlod" decode "$WORK/bumps_s.tlp" --tile "$l/$x/$y" -o "$WORK/ds.ply" 2>/dev/null &&
        cmp -s "$WORK/dp.ply" "$WORK/ds.ply" && same=$((same + 1))
    done
  done
done
check "all 21 tiles decode the same from both codings" test "$same" -eq 21
run terrainlod verify "$WORK/bumps_s.tlp" --dem "$WORK/bumps.asc" --cameras 4
expect_json '[.ok, .reencode_mismatches]' '[true,0]'
run terrainlod build "$WORK/bumps.asc" --tile 16 --coding delta -o "$WORK/never.tlp"
expect_clean_failure 2 terrainlod
check "nothing written" test ! -e "$WORK/never.tlp"

case_ "progressive: --threads 1 and 2 give the same archive; the directory holds the same tiles"
run terrainlod build "$WORK/bumps.asc" --tile 16 -o "$WORK/bumps_t2.tlp" --threads 2
expect_status 0
check "byte-identical archives" cmp "$WORK/bumps.tlp" "$WORK/bumps_t2.tlp"
run terrainlod build "$WORK/bumps.asc" --tile 16 -o "$WORK/bumps_dir" --threads 2
expect_status 0
run terrainlod decode "$WORK/bumps_dir" --tile 2/3/1 -o "$WORK/dd.ply"
expect_status 0
run terrainlod decode "$WORK/bumps.tlp" --tile 2/3/1 -o "$WORK/da.ply"
check "same tile from the directory" cmp "$WORK/dd.ply" "$WORK/da.ply"

case_ "progressive: a child whose parent is missing from the archive is bad input"
# Drop the root's entry from the index (offsets are absolute: the other tiles stay valid).
python3 - "$WORK/bumps.tlp" "$WORK/orphan.tlp" <<'PY'
import struct, sys
b = open(sys.argv[1], "rb").read()
m = struct.unpack_from("<I", b, 5)[0]
at = 9 + m
n = struct.unpack_from("<I", b, at)[0]
entries = [b[at + 4 + 33 * i: at + 4 + 33 * (i + 1)] for i in range(n)]
keep = [e for e in entries if struct.unpack_from("<BII", e) != (0, 0, 0)]
assert len(keep) == n - 1
head = b[:at] + struct.pack("<I", n - 1) + b"".join(keep)
# Pad where the dropped entry was, so the absolute offsets still point at the blobs.
open(sys.argv[2], "wb").write(head + b"\0" * 33 + b[at + 4 + 33 * n:])
PY
run terrainlod decode "$WORK/orphan.tlp" --tile 1/0/0 -o "$WORK/out.ply"
expect_clean_failure 3 terrainlod
expect_stderr_has 'tile 1/0/0 is coded relative to its parent 0/0/0, which the pyramid lacks'
run terrainlod decode "$WORK/orphan.tlp" --tile 2/3/3 -o "$WORK/out.ply"
expect_clean_failure 3 terrainlod
expect_stderr_has 'which the pyramid lacks'

# --- bad input ------------------------------------------------------------------------
bad() {  # bad STATUS REGEX ARGS...
  local status="$1" regex="$2"; shift 2
  rm -f "$WORK/out.tlp" "$WORK/out.ply"
  run terrainlod "$@"
  expect_clean_failure "$status" terrainlod
  expect_stderr_has "$regex"
  check "no output file" test ! -e "$WORK/out.tlp" -a ! -e "$WORK/out.ply"
}

case_ "build: DEM of one column, all nodata, NaN heights"
printf 'ncols 1\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n2\n3\n' >"$WORK/col.asc"
bad 3 'DEM has 1 column and 3 rows' build "$WORK/col.asc" -o "$WORK/out.tlp"
printf 'ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -1\n-1 -1\n-1 -1\n' >"$WORK/none.asc"
bad 3 'all samples are nodata' build "$WORK/none.asc" -o "$WORK/out.tlp"
printf 'Pf\n2 2\n-1.0\n\x00\x00\x80\x3f\x00\x00\xc0\x7f\x00\x00\x40\x40\x00\x00\x80\x40' >"$WORK/nan.pfm"
bad 3 'NaN height' build "$WORK/nan.pfm" -o "$WORK/out.tlp"
printf 'ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 nan 6\n7 8 9\n' >"$WORK/nan.asc"
bad 3 'NaN height' build "$WORK/nan.asc" -o "$WORK/out.tlp"
printf 'ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 abc 6\n7 8 9\n' >"$WORK/word.asc"
bad 3 "non-numeric value 'abc' at row 2, column 2" build "$WORK/word.asc" -o "$WORK/out.tlp"
printf 'ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 5 6\n7 8\n' >"$WORK/short.asc"
bad 3 'has 8 of its 3 x 3 values' build "$WORK/short.asc" -o "$WORK/out.tlp"
check "no pyramid written" test ! -e "$WORK/out.tlp"

case_ "build: tile size not a power of two, a directory pyramid over a file"
bad 2 '--tile must be a power of two between 4 and 4096 \(got 48\)' build "$WORK/plane.asc" --tile 48 -o "$WORK/out.tlp"
printf 'keep me\n' >"$WORK/notes.txt"
run terrainlod build "$WORK/plane.asc" -o "$WORK/notes.txt"
expect_clean_failure 4 terrainlod
expect_stderr_has 'exists and is not a pyramid directory'
check "the file is untouched" grep -q 'keep me' "$WORK/notes.txt"

case_ "truncated pyramid, bad magic"
size=$(stat -c %s "$WORK/bumps.tlp")
head -c $((size - 100)) "$WORK/bumps.tlp" >"$WORK/short.tlp"
bad 3 'tile 2/3/3 is truncated: [0-9]+ of [0-9]+ bytes' stats "$WORK/short.tlp"
bad 3 'is truncated' extract "$WORK/short.tlp" --camera "$WORK/cam.json" -o "$WORK/out.ply"
printf 'FTLX' >"$WORK/magic.tlp"
bad 3 'not a terrainlod pyramid \(bad magic\)' decode "$WORK/magic.tlp" --tile 0/0/0 -o "$WORK/out.ply"
# A manifest key renamed in place (same length, so every offset still holds; the archive
# has no checksum): refused on opening in fest's words, not by the JSON library (a zzuf
# variant of mutate.sh got "[json.exception.out_of_range.403]" out of stats).
perl -pe 's/"lattice_bits"/"lattice_bitz"/' "$WORK/bumps.tlp" >"$WORK/renamed.tlp"
bad 3 "pyramid manifest is malformed: field 'lattice_bits' missing" stats "$WORK/renamed.tlp"
perl -pe 's/"width"/"widtx"/' "$WORK/bumps.tlp" >"$WORK/renamed.tlp"
bad 3 "pyramid manifest is malformed: field 'width' missing" stats "$WORK/renamed.tlp"

case_ "camera looking along its up vector; mask out of range"
printf '{"eye": [1300, 1600, 300], "target": [1300, 1600, 0]}\n' >"$WORK/down.json"
bad 3 'camera looks along its up vector \(.*down.json\)' extract "$WORK/bumps.tlp" --camera "$WORK/down.json" -o "$WORK/out.ply"
bad 2 '--mask: must be in \[0, 15\], not 16' decode "$WORK/bumps.tlp" --tile 1/0/0 --mask 16 -o "$WORK/out.ply"

finish
