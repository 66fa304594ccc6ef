#!/usr/bin/env bash
# terrainlod texture tiles and the directory container (docs/terrainlod.md §3-4, terrainlod-pyramid(5)): stored PNG
# tiles equal the input cut and box-filtered exactly; texture coordinates follow from the
# tile squares (corners 0/1, closing-only tiles in their ancestor's sub-square); the
# directory pyramid extracts exactly like the archive; --clip, --atlas, JPEG; bad input.
. "$(dirname "$0")/lib.sh"
uv_py="$(dirname "$0")/terrainlod_uv.py"

# 129 x 129 tilted plane, 10 m cells: 128 cells = 2^2 x 32 (L = 2 with --tile 32).
awk 'BEGIN { print "ncols 129\nnrows 129\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 129; r++) { s = ""; for (c = 0; c < 129; c++) s = s (c ? " " : "") (c + 2 * r); print s } }' >"$WORK/plane.asc"
# 128 x 128 RGB texture on the texel lattice of T = 32 (edges on the outer samples):
# pixel (c, r), r from the top: (3c + 5r, c r, 7c) mod 256.
ppm() {  # ppm W H X0 Y0 STEP: the image above (STEP 1) or its STEP x STEP box means,
         # rounded half up per halving, of the W x H block at (X0, Y0)
  awk -v W="$1" -v H="$2" -v X0="$3" -v Y0="$4" -v S="$5" '
    function px(c, r, k) { return k == 0 ? (3 * c + 5 * r) % 256 : k == 1 ? (c * r) % 256 : (7 * c) % 256 }
    function box(c, r, s, k,    h) { if (s == 1) return px(c, r, k)
      h = s / 2; return int((box(c, r, h, k) + box(c + h, r, h, k) + box(c, r + h, h, k) + box(c + h, r + h, h, k) + 2) / 4) }
    BEGIN { printf "P3\n%d %d\n255\n", W, H
      for (r = 0; r < H; r++) for (c = 0; c < W; c++)
        printf "%d %d %d\n", box(X0 + S * c, Y0 + S * r, S, 0), box(X0 + S * c, Y0 + S * r, S, 1), box(X0 + S * c, Y0 + S * r, S, 2) }'
}
ppm 128 128 0 0 1 >"$WORK/tex.ppm"

case_ "PNG texture tiles are the input cut into tiles and box-filtered per level, exactly"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/tex.ppm" -o "$WORK/p.tlp"
expect_status 0
expect_stdout_empty
run terrainlod decode "$WORK/p.tlp" --tile 2/1/2 --texture "$WORK/t212.png" -o "$WORK/t212.ply"
expect_status 0
# Tile (2, 1, 2): columns 32..63, and (rows from the north) the second row of tiles.
ppm 32 32 32 32 1 >"$WORK/want212.ppm"
check "leaf tile 2/1/2 = the input's 32 x 32 block" "$FEST_BIN/fcompare" "$WORK/t212.png" "$WORK/want212.ppm"
run terrainlod decode "$WORK/p.tlp" --tile 1/0/1 --texture "$WORK/t101.png" -o "$WORK/t101.ply"
expect_status 0
ppm 32 32 0 0 2 >"$WORK/want101.ppm"
check "level-1 tile 1/0/1 = 2 x 2 means of the north-west quarter" "$FEST_BIN/fcompare" "$WORK/t101.png" "$WORK/want101.ppm"
run terrainlod decode "$WORK/p.tlp" --tile 0/0/0 --texture "$WORK/t000.png" -o "$WORK/t000.ply"
ppm 32 32 0 0 4 >"$WORK/want000.ppm"
check "root = 2 x 2 means of the 2 x 2 means" "$FEST_BIN/fcompare" "$WORK/t000.png" "$WORK/want000.ppm"
run terrainlod stats "$WORK/p.tlp"
check "stats count the texture bytes" jq -e '.totals.texture_bytes > 0 and (.level | map(.bytes.texture) | add) == .totals.texture_bytes' "$out"

case_ "a georeferenced texture (PNG + world file) lies where its georeference says"
# The ASCII grid's xllcorner 0 is the corner of its south-west cell: sample (0, 0) is at
# (5, 5), sample (128, 128) at (1285, 1285). Pixel c of the texture above is centred on
# grid x = c + 0.5, i.e. x = 10 + 10 c; the world file names the centre of the top-left
# pixel: (10, 1280).
"$FEST_BIN/fconv" "$WORK/tex.ppm" -o "$WORK/geo.png"
printf '10\n0\n0\n-10\n10\n1280\n' >"$WORK/geo.pgw"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/geo.png" -o "$WORK/geo.tlp"
expect_status 0
run terrainlod decode "$WORK/geo.tlp" --tile 2/1/2 --texture "$WORK/g212.png" -o "$WORK/g212.ply"
check "same tile as the image spanning the DEM" "$FEST_BIN/fcompare" "$WORK/g212.png" "$WORK/want212.ppm"
# One pixel (10 m) further east: every texel takes the pixel one column to the west.
printf '10\n0\n0\n-10\n20\n1280\n' >"$WORK/geo.pgw"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/geo.png" -o "$WORK/geo2.tlp"
expect_status 0
run terrainlod decode "$WORK/geo2.tlp" --tile 2/1/2 --texture "$WORK/g2.png" -o "$WORK/g2.ply"
ppm 32 32 31 32 1 >"$WORK/want_shift.ppm"
check "shifted by one pixel" "$FEST_BIN/fcompare" "$WORK/g2.png" "$WORK/want_shift.ppm"
printf '10\n0\n0\n-10\n90000\n1280\n' >"$WORK/geo.pgw"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/geo.png" -o "$WORK/geo3.tlp"
expect_clean_failure 3 terrainlod
expect_stderr_has "georeference does not overlap the DEM"

case_ "--texture-mip: a prefiltered pyramid gives each level its own image"
# PREFIX_<k>.png as `resample mip build` names them; here level k is the 2^k box mean, so
# every tile must come out as with the box filter above.
for k in 0 1 2; do
  s=$((1 << k)); ppm $((128 / s)) $((128 / s)) 0 0 $s >"$WORK/mip_$k.ppm"
  "$FEST_BIN/fconv" "$WORK/mip_$k.ppm" -o "$WORK/mip_$k.png"
done
run terrainlod build "$WORK/plane.asc" --tile 32 --texture-mip "$WORK/mip" -o "$WORK/mip.tlp"
expect_status 0
run terrainlod decode "$WORK/mip.tlp" --tile 1/0/1 --texture "$WORK/m101.png" -o "$WORK/m101.ply"
expect_status 0
check "level-1 tile from mip level 1" "$FEST_BIN/fcompare" "$WORK/m101.png" "$WORK/want101.ppm"
run terrainlod decode "$WORK/mip.tlp" --tile 0/0/0 --texture "$WORK/m000.png" -o "$WORK/m000.ply"
check "root from mip level 2" "$FEST_BIN/fcompare" "$WORK/m000.png" "$WORK/want000.ppm"
run terrainlod decode "$WORK/mip.tlp" --tile 2/1/2 --texture "$WORK/m212.png" -o "$WORK/m212.ply"
check "leaf from mip level 0" "$FEST_BIN/fcompare" "$WORK/m212.png" "$WORK/want212.ppm"
cp "$WORK/mip_0.png" "$WORK/badmip_0.png"
"$FEST_BIN/fconv" "$WORK/want212.ppm" -o "$WORK/badmip_1.png"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture-mip "$WORK/badmip" -o "$WORK/badmip.tlp"
expect_clean_failure 3 terrainlod
expect_stderr_has 'texture pyramid level 1 is 32 x 32 .* each level must halve the previous'
check "no pyramid written" test ! -e "$WORK/badmip.tlp"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture hillshade --texture-mip "$WORK/mip" -o "$WORK/x.tlp"
expect_clean_failure 2 terrainlod

case_ "directory container: pyramid.json + L/X/Y.tlt + L/X/Y.png, read like the archive"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/tex.ppm" -o "$WORK/pdir"
expect_status 0
check "tile and texture files" test -s "$WORK/pdir/2/1/2.tlt" -a -s "$WORK/pdir/2/1/2.png" -a -s "$WORK/pdir/0/0/0.png"
check "manifest names the textures" jq -e '.texture.format == "png" and .texture.texels == 32' "$WORK/pdir/pyramid.json"
check "same texture bytes as the archive" cmp -s "$WORK/pdir/2/1/2.png" "$WORK/t212.png"
run terrainlod verify "$WORK/pdir" --cameras 3
expect_status 0
expect_json '[.ok, .tiles, .bad_textures]' '[true,21,0]'
cp -r "$WORK/pdir" "$WORK/garbled"
printf 'not a png' >"$WORK/garbled/1/1/0.png"
run terrainlod verify "$WORK/garbled" --cameras 0
expect_status 1
expect_json '[.ok, .bad_textures]' '[false,1]'
printf '{"eye": [300, -200, 500], "target": [640, 640, 0], "fovy_deg": 60, "width": 160, "height": 120, "tau_px": 1}\n' >"$WORK/cam.json"
run terrainlod extract "$WORK/p.tlp" --camera "$WORK/cam.json" -o "$WORK/a.ply" --atlas "$WORK/a_atlas.png" --png "$WORK/a.png"
expect_status 0
run terrainlod extract "$WORK/pdir" --camera "$WORK/cam.json" -o "$WORK/d.ply" --atlas "$WORK/d_atlas.png" --png "$WORK/d.png"
expect_status 0
check "identical meshes" cmp -s "$WORK/a.ply" "$WORK/d.ply"
check "identical atlases" cmp -s "$WORK/a_atlas.png" "$WORK/d_atlas.png"
check "identical renderings" cmp -s "$WORK/a.png" "$WORK/d.png"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/tex.ppm" -o "$WORK/pdir"
expect_status 0
check "a pyramid directory is replaced" test -s "$WORK/pdir/pyramid.json" -a ! -e "$WORK/pdir.part-"*

case_ "texture coordinates: (u, v) = position in the texture tile's square; corners 0 and 1"
run terrainlod extract "$WORK/p.tlp" --camera "$WORK/cam.json" -o "$WORK/view.obj"
expect_status 0
check "MTL and per-tile textures beside the OBJ" test -s "$WORK/view.mtl" -a -s "$WORK/view-2-0-0.png"
run terrainlod stats "$WORK/p.tlp"
cp "$out" "$WORK/p_stats.json"
python3 "$uv_py" "$WORK/view.obj" "$WORK/p_stats.json" >"$out"
expect_json '[.mismatches, .corner_mismatches, .outside]' '[0,0,0]'
check "faces and tile corners seen" jq -e '.faces > 0 and .corners > 0' "$out"

case_ "closing-only tiles use their ancestor's texture, mapped to the sub-square"
# Flat 129 x 129 DEM with a 300 m block inside leaf tile (3, 3, 3) (--tile 16, L = 3);
# a camera hovering beside it: that tile's box is next to the eye (level 3), the flat
# level-1 tile east of it is far enough for level 1, so closing splits it.
awk 'BEGIN { print "ncols 129\nnrows 129\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 128; r >= 0; r--) { s = ""; for (c = 0; c < 129; c++) s = s (c ? " " : "") ((c >= 54 && c <= 58 && r >= 54 && r <= 58) ? 300 : 0); print s } }' >"$WORK/spike.asc"
run terrainlod build "$WORK/spike.asc" --tile 16 --texture hillshade -o "$WORK/spike.tlp"
expect_status 0
printf '{"eye": [560, 560, 290], "target": [1000, 1000, 0], "fovy_deg": 70, "width": 320, "height": 240, "tau_px": 24}\n' >"$WORK/scam.json"
run terrainlod extract "$WORK/spike.tlp" --camera "$WORK/scam.json" -o "$WORK/spike.obj" --report "$WORK/spike.json"
expect_status 0
cp "$WORK/spike.json" "$out"
check "closing-only tiles drawn" jq -e '.closing_only > 0' "$out"
check "they share their ancestors' textures (fewer textures than tiles)" jq -e '.textures < .tiles' "$out"
run terrainlod stats "$WORK/spike.tlp"
cp "$out" "$WORK/spike_stats.json"
python3 "$uv_py" "$WORK/spike.obj" "$WORK/spike_stats.json" >"$out"
expect_json '[.mismatches, .corner_mismatches, .outside]' '[0,0,0]'
check "level-1 textures used by finer tiles" jq -e '.material_levels | index(1) != null' "$out"

case_ "the renderer samples the texture: a uniform texture seen from above is that colour"
awk 'BEGIN { printf "P3\n128 128\n255\n"; for (k = 0; k < 128 * 128; k++) print "200 100 50" }' >"$WORK/flat.ppm"
run terrainlod build "$WORK/plane.asc" --tile 32 --texture "$WORK/flat.ppm" -o "$WORK/flat.tlp"
expect_status 0
printf '{"eye": [640, 640, 3000], "target": [640, 640, 0], "up": [0, 1, 0], "fovy_deg": 10, "width": 40, "height": 30}\n' >"$WORK/top.json"
run terrainlod extract "$WORK/flat.tlp" --camera "$WORK/top.json" -o "$WORK/top.ply" --png "$WORK/top.png"
expect_status 0
awk 'BEGIN { printf "P3\n40 30\n255\n"; for (k = 0; k < 40 * 30; k++) print "200 100 50" }' >"$WORK/top_want.ppm"
check "every pixel (200, 100, 50)" "$FEST_BIN/fcompare" "$WORK/top.png" "$WORK/top_want.ppm"

case_ "--clip cuts the triangles at the DEM's edges; JPEG texture tiles"
# 50 x 40 samples: padded to 65 x 65 with --tile 16.
awk 'BEGIN { print "ncols 50\nnrows 40\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 40; r++) { s = ""; for (c = 0; c < 50; c++) s = s (c ? " " : "") int(20 * sin(c / 4.0) + r); print s } }' >"$WORK/small.asc"
run terrainlod build "$WORK/small.asc" --tile 16 --texture hillshade --texture-format jpeg -o "$WORK/small.tlp"
expect_status 0
run terrainlod decode "$WORK/small.tlp" --tile 2/0/0 --texture "$WORK/small.jpg" -o "$WORK/small.ply"
expect_status 0
check "a JPEG tile" test "$(head -c 3 "$WORK/small.jpg" | od -An -tx1 | tr -d ' ')" = ffd8ff
printf '{"eye": [320, -300, 600], "target": [320, 320, 0], "fovy_deg": 70, "width": 160, "height": 120}\n' >"$WORK/scam2.json"
run terrainlod extract "$WORK/small.tlp" --camera "$WORK/scam2.json" -o "$WORK/all.obj" --png "$WORK/small.png"
expect_status 0
run terrainlod extract "$WORK/small.tlp" --camera "$WORK/scam2.json" -o "$WORK/clip.obj" --clip
expect_status 0
# Sample centres x = 5 .. 495, y = 5 .. 395: --clip cuts the triangles there (the padding
# was in view without it), and reaches both edges.
extent() { awk '$1 == "v" { if (n++ == 0 || $2 > mx) mx = $2; if (n == 1 || $3 > my) my = $3 } END { print mx, my }' "$1"; }
read -r all_x all_y < <(extent "$WORK/all.obj")
read -r clip_x clip_y < <(extent "$WORK/clip.obj")
check "without --clip the padding is drawn" awk -v x="$all_x" -v y="$all_y" 'BEGIN { exit !(x > 495 || y > 395) }'
check "with --clip the mesh ends at the last sample column and row" awk -v x="$clip_x" -v y="$clip_y" \
  'BEGIN { exit !(x > 495 - 1e-3 && x < 495 + 1e-3 && y > 395 - 1e-3 && y < 395 + 1e-3) }'

# --- bad input ------------------------------------------------------------------------
bad() {  # bad STATUS REGEX ARGS...
  local status="$1" regex="$2"; shift 2
  rm -rf "$WORK/out.tlp" "$WORK/out.ply" "$WORK/outdir"
  run terrainlod "$@"
  expect_clean_failure "$status" terrainlod
  expect_stderr_has "$regex"
  check "no output" test ! -e "$WORK/out.tlp" -a ! -e "$WORK/out.ply" -a ! -e "$WORK/outdir"
}

case_ "texture size mismatch, unreadable texture, missing texture file, --atlas without textures"
awk 'BEGIN { printf "P3\n100 20\n255\n"; for (k = 0; k < 2000; k++) print "1 2 3" }' >"$WORK/wide.ppm"
bad 3 'texture is 100 x 20 pixels, which does not fit a DEM of 129 x 129 samples.*wide.ppm' build "$WORK/plane.asc" --texture "$WORK/wide.ppm" -o "$WORK/out.tlp"
printf 'P6\n4 4\n255\nxx' >"$WORK/short.ppm"
bad 3 'short.ppm' build "$WORK/plane.asc" --texture "$WORK/short.ppm" -o "$WORK/outdir"
bad 2 'texture-format' build "$WORK/plane.asc" --texture hillshade --texture-format gif -o "$WORK/out.tlp"
cp -r "$WORK/pdir" "$WORK/broken"
rm "$WORK/broken/2/0/3.png"
bad 3 'pyramid directory lacks the texture of tile 2/0/3 \(.*broken/2/0/3.png\)' extract "$WORK/broken" --camera "$WORK/cam.json" -o "$WORK/out.ply"
rm "$WORK/broken/1/1/1.tlt"
bad 3 'pyramid directory lacks tile 1/1/1' stats "$WORK/broken"
run terrainlod build "$WORK/plane.asc" --tile 32 -o "$WORK/bare.tlp"
bad 2 '--atlas needs a pyramid with textures' extract "$WORK/bare.tlp" --camera "$WORK/cam.json" -o "$WORK/out.ply" --atlas "$WORK/out.png"
bad 3 'pyramid has no textures' decode "$WORK/bare.tlp" --tile 0/0/0 --texture "$WORK/out.png" -o "$WORK/out.ply"
check "no atlas written" test ! -e "$WORK/out.png"
size=$(stat -c %s "$WORK/p.tlp")
head -c $((size - 10)) "$WORK/p.tlp" >"$WORK/cut.tlp"
bad 3 'texture of tile 2/3/3 is truncated' stats "$WORK/cut.tlp"

finish
