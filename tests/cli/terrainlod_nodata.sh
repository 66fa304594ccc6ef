#!/usr/bin/env bash
# terrainlod build --nodata fill|hole (issue 30, docs/terrainlod.md §5 "Holes"): on a DEM
# whose nodata samples are known exactly, `hole` draws no triangle over a nodata sample
# (measured from the mesh by tests/cli/terrainlod/holes.py, not by fest), the views stay
# crack-free (verify), `fill` is today's pyramid byte for byte, bad words are usage errors.
. "$(dirname "$0")/lib.sh"
HOLES="python3 $(dirname "$0")/terrainlod/holes.py"

# 65 x 49 samples at integer grid positions (xllcorner -0.5, cellsize 1: sample (i, j) at
# x = i, y = j). Nodata (-9999): the rectangle i 20..35, j 12..27, one lone sample (50, 40),
# and the block i 0..3, j 44..48 on the north-west corner (the padding repeats the edges).
awk 'BEGIN { print "ncols 65\nnrows 49\nxllcorner -0.5\nyllcorner -0.5\ncellsize 1\nNODATA_value -9999";
  for (r = 0; r < 49; r++) { line = ""; j = 48 - r; for (i = 0; i < 65; i++) {
    nd = (i >= 20 && i <= 35 && j >= 12 && j <= 27) || (i == 50 && j == 40) || (i <= 3 && j >= 44);
    line = line sprintf("%d ", nd ? -9999 : 100 + (i * 7 + j * 13) % 11 + (i * j) % 5 + int(i / 4) * 3) }
    print line } }' >"$WORK/dem.asc"
nodata_samples=$((16 * 16 + 1 + 4 * 5))

# From straight above the centre, fine enough that every drawn tile is a leaf.
echo '{"eye":[32,24,400],"target":[32,24,0],"up":[0,1,0],"fovy_deg":30,"width":400,"height":300,"tau_px":0.05}' >"$WORK/top.json"

case_ "--nodata fill is the default, byte for byte (archive and extracted mesh)"
run terrainlod build "$WORK/dem.asc" --tile 16 -o "$WORK/default.tlp"
expect_status 0
run terrainlod build "$WORK/dem.asc" --tile 16 --nodata fill -o "$WORK/fill.tlp" --report "$WORK/fill.json"
expect_status 0
check "fill archive = default archive" cmp "$WORK/default.tlp" "$WORK/fill.tlp"
check "fill archive is version 1 (no nodata section)" sh -c "head -c 5 '$WORK/fill.tlp' | tail -c 1 | od -An -tu1 | grep -qw 1"
cp "$WORK/fill.json" "$out"
expect_json '.nodata' '{"mask_bytes":0,"mode":"fill","samples":0}'
run terrainlod extract "$WORK/default.tlp" --camera "$WORK/top.json" -o "$WORK/default.obj"
run terrainlod extract "$WORK/fill.tlp" --camera "$WORK/top.json" -o "$WORK/fill.obj"
check "fill mesh = default mesh" cmp "$WORK/default.obj" "$WORK/fill.obj"
# Filled, the DEM is drawn whole: triangles over the nodata samples.
check "fill draws over nodata" sh -c "$HOLES '$WORK/fill.obj' '$WORK/dem.asc' | jq -e '.over_nodata > 0'"

case_ "--nodata hole: a version 2 archive holding the mask; the same tiles"
run terrainlod build "$WORK/dem.asc" --tile 16 --nodata hole -o "$WORK/hole.tlp" --report "$WORK/hole.json"
expect_status 0
cp "$WORK/hole.json" "$out"
expect_json '[.nodata.mode, .nodata.samples]' "[\"hole\",$nodata_samples]"
check "hole archive is version 2" sh -c "head -c 5 '$WORK/hole.tlp' | tail -c 1 | od -An -tu1 | grep -qw 2"
run terrainlod stats "$WORK/hole.tlp"
expect_status 0
run terrainlod verify "$WORK/hole.tlp" --cameras 0
expect_status 0
expect_json '[.nodata, .nodata_samples]' "[\"hole\",$nodata_samples]"

case_ "--nodata hole: no drawn triangle holds a nodata sample; the rest of the DEM is drawn"
run terrainlod extract "$WORK/hole.tlp" --camera "$WORK/top.json" -o "$WORK/hole.obj" --report "$WORK/hx.json"
expect_status 0
check "holes.py measures the mesh" sh -c "$HOLES '$WORK/hole.obj' '$WORK/dem.asc' >'$WORK/holes_top.json'"
cp "$WORK/holes_top.json" "$out"
expect_json '[.over_nodata, .nonlattice]' '[0,0]'
# The 15 x 15 cells inside the rectangle (all four corners nodata) get nothing; at most
# slivers of triangles passing between nodata samples could reach in: none here.
expect_json '.all_nodata_area' '0'
# Leaves without tolerance keep every sample of this DEM (its heights are coplanar over no
# two cells), so the drawn leaves are half cells. A cell with no nodata corner is drawn
# whole; one with two or more none (each half misses one corner only); one with exactly one
# nodata corner at most by its other half. Cells with a nodata corner: 17 x 17 around the
# rectangle, 2 x 2 around the lone sample, 4 x 5 by the corner block = 313; with exactly
# one: the rectangle's 4 outer diagonal cells, the lone sample's 4, the block's 1 = 9. The
# DEM has 64 x 48 = 3072 cells: 3072 - 313 <= drawn <= 3072 - 313 + 9 / 2.
check "drawn area in [2759, 2763.5]" jq -e '.drawn_area >= 2759 - 1e-9 and .drawn_area <= 2763.5 + 1e-9' "$WORK/holes_top.json"
cp "$WORK/hx.json" "$out"
check "extract reports the triangles left out" jq -e '.hole_triangles > 0' "$out"

case_ "--nodata hole in a camera path: the same holes as the single view"
cp "$WORK/top.json" "$WORK/path.jsonl"
run terrainlod extract "$WORK/hole.tlp" --path "$WORK/path.jsonl" -o "$WORK/path%d.obj" --report "$WORK/path.json"
expect_status 0
check "path frame 0 = the single view" cmp "$WORK/hole.obj" "$WORK/path0.obj"
check "path report counts the triangles left out" jq -e '.frames[0].hole_triangles > 0' "$WORK/path.json"

case_ "--nodata hole with --clip and an automatic camera: still nothing over nodata on the lattice"
run terrainlod extract "$WORK/hole.tlp" --clip -o "$WORK/clip.obj" --report "$WORK/clip.json"
expect_status 0
check "clipped: no lattice triangle over nodata" sh -c "$HOLES '$WORK/clip.obj' '$WORK/dem.asc' | jq -e '.over_nodata == 0 and .all_nodata_area == 0'"
# The camera frames the valid samples' box (here the whole DEM: valid samples on every
# edge): every drawn vertex projects inside the 1280 x 800 image (pinhole, docs §5).
check "automatic camera: every drawn vertex inside the image" sh -c "python3 '$(dirname "$0")/terrainlod/project.py' '$WORK/clip.json' '$WORK/clip.obj' | grep -q '^1 '"

case_ "verify: crack-free with holes at several error thresholds (edges may border a hole)"
for f in 0.5 2 8; do
  run terrainlod build "$WORK/dem.asc" --tile 16 --nodata hole --error-fraction "$f" -o "$WORK/h$f.tlp"
  expect_status 0
  run terrainlod verify "$WORK/h$f.tlp" --dem "$WORK/dem.asc" --cameras 12 --seed 3
  expect_status 0
  expect_json '[.ok, .open_edges, .tiles_over_bound, .nodata_mask_matches_dem, .views_drawing_other_triangles]' '[true,0,0,true,0]'
  check "error fraction $f: some edges border holes" jq -e '.hole_edges > 0 and .hole_triangles > 0' "$out"
done

case_ "a pyramid directory with holes draws the same mesh as the archive"
run terrainlod build "$WORK/dem.asc" --tile 16 --nodata hole -o "$WORK/holedir/"
expect_status 0
check "nodata.bin written" test -s "$WORK/holedir/nodata.bin"
run terrainlod extract "$WORK/holedir" --camera "$WORK/top.json" -o "$WORK/holedir.obj"
expect_status 0
check "directory mesh = archive mesh" cmp "$WORK/hole.obj" "$WORK/holedir.obj"

case_ "--nodata with a value and a mode; simplify and export-qm cut the same holes"
awk 'NR == 6 { print "NODATA_value -1"; next } { print }' "$WORK/dem.asc" >"$WORK/dem_m1.asc"
run terrainlod build "$WORK/dem_m1.asc" --tile 16 --nodata -9999,hole -o "$WORK/value.tlp"
expect_status 0
run terrainlod extract "$WORK/value.tlp" --camera "$WORK/top.json" -o "$WORK/value.obj"
check "--nodata -9999,hole = --nodata hole with the file's value" cmp "$WORK/hole.obj" "$WORK/value.obj"
run terrainlod build "$WORK/dem_m1.asc" --tile 16 --nodata hole --nodata -9999 -o "$WORK/value2.tlp"
check "the flag given twice: the same archive" cmp "$WORK/value.tlp" "$WORK/value2.tlp"
run terrainlod simplify "$WORK/dem.asc" --max-error 0 --nodata hole -o "$WORK/simp.obj" --report "$WORK/simp.json"
expect_status 0
check "simplify --nodata hole: nothing over nodata" sh -c "$HOLES '$WORK/simp.obj' '$WORK/dem.asc' | jq -e '.over_nodata == 0 and .triangles > 0'"
run terrainlod export-qm "$WORK/hole.tlp" -o "$WORK/qm"
expect_status 0

case_ "bad --nodata words are usage errors (exit 2, one line naming the flag)"
run terrainlod build "$WORK/dem.asc" --nodata foo -o "$WORK/bad.tlp"
expect_clean_failure 2 terrainlod
expect_stderr_has "--nodata expects fill, hole, a nodata value or nan \(got 'foo'\)"
check "nothing written" test ! -e "$WORK/bad.tlp"
run terrainlod build "$WORK/dem.asc" --nodata hole,fill -o "$WORK/bad.tlp"
expect_clean_failure 2 terrainlod
expect_stderr_has "--nodata takes one of fill or hole"
run terrainlod build "$WORK/dem.asc" --nodata 1,2 -o "$WORK/bad.tlp"
expect_clean_failure 2 terrainlod
expect_stderr_has "--nodata takes one nodata value"
run terrainlod build "$WORK/dem.asc" --nodata inf -o "$WORK/bad.tlp"
expect_clean_failure 2 terrainlod

case_ "damaged nodata sections are bad input (exit 3)"
# Version byte 1 on an archive whose manifest says hole: no section where the manifest wants one.
python3 - "$WORK/hole.tlp" "$WORK/v1.tlp" <<'PY'
import sys
b = bytearray(open(sys.argv[1], "rb").read()); b[4] = 1; open(sys.argv[2], "wb").write(b)
PY
run terrainlod extract "$WORK/v1.tlp" --camera "$WORK/top.json" -o "$WORK/x.obj"
expect_clean_failure 3 terrainlod
expect_stderr_has "nodata"
# A fill archive given a section (version byte 2): its index runs into the blobs.
python3 - "$WORK/fill.tlp" "$WORK/v2.tlp" <<'PY'
import sys
b = bytearray(open(sys.argv[1], "rb").read()); b[4] = 2; open(sys.argv[2], "wb").write(b)
PY
run terrainlod extract "$WORK/v2.tlp" --camera "$WORK/top.json" -o "$WORK/x.obj"
expect_clean_failure 3 terrainlod
cp "$WORK/holedir/nodata.bin" "$WORK/nodata.bin.ok"
head -c 30 "$WORK/nodata.bin.ok" >"$WORK/holedir/nodata.bin"
run terrainlod extract "$WORK/holedir" --camera "$WORK/top.json" -o "$WORK/x.obj"
expect_clean_failure 3 terrainlod
expect_stderr_has "nodata mask"

finish
