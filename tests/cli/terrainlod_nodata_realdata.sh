#!/usr/bin/env bash
# terrainlod --nodata hole on a real DEM that is mostly nodata: meuse.tif of r-cran-terra
# (80 x 115 int16 samples, 40 m, nodata -32768; scripts/fetch-test-data.sh). The valid
# fraction comes from GDAL (gdal_translate to an ESRI ASCII grid, counted by
# tests/cli/terrainlod/holes.py), the drawn area from the extracted mesh.
. "$(dirname "$0")/lib.sh"
meuse=$(need_testdata dem/meuse.tif) || exit 77
command -v gdal_translate >/dev/null || { echo "skipped: gdal_translate (gdal-bin) not installed" >&2; exit 77; }
HOLES="python3 $(dirname "$0")/terrainlod/holes.py"
gdal_translate -q -of AAIGrid "$meuse" "$WORK/meuse.asc"

# From straight above the centre, fine enough that every drawn tile is a leaf.
echo '{"eye":[180000,331700,20000],"target":[180000,331700,0],"up":[0,1,0],"fovy_deg":30,"width":400,"height":300,"tau_px":0.05}' >"$WORK/top.json"

case_ "meuse.tif: fill is the default, byte for byte"
run terrainlod build "$meuse" --tile 32 -o "$WORK/default.tlp"
expect_status 0
run terrainlod build "$meuse" --tile 32 --nodata fill -o "$WORK/fill.tlp"
expect_status 0
check "fill archive = default archive" cmp "$WORK/default.tlp" "$WORK/fill.tlp"

case_ "meuse.tif --nodata hole: the mask is GDAL's nodata, nothing drawn over it"
run terrainlod build "$meuse" --tile 32 --nodata hole -o "$WORK/hole.tlp" --report "$WORK/b.json"
expect_status 0
run terrainlod extract "$WORK/hole.tlp" --camera "$WORK/top.json" -o "$WORK/hole.obj"
expect_status 0
run terrainlod extract "$WORK/fill.tlp" --camera "$WORK/top.json" -o "$WORK/fill.obj"
expect_status 0
$HOLES "$WORK/hole.obj" "$WORK/meuse.asc" >"$WORK/hole.json"
$HOLES "$WORK/fill.obj" "$WORK/meuse.asc" >"$WORK/fill.json"
valid=$(jq '.valid_fraction' "$WORK/hole.json")
check "GDAL: about 65 % nodata (valid fraction $valid)" jq -e '.valid_fraction > 0.3 and .valid_fraction < 0.4' "$WORK/hole.json"
check "stored nodata samples = GDAL's count" jq -e --argjson v "$valid" '.nodata.samples == (9200 - ($v * 9200 | round))' "$WORK/b.json"
check "hole: no triangle over a nodata sample" jq -e '.over_nodata == 0 and .nonlattice == 0' "$WORK/hole.json"
check "fill: the whole DEM drawn" jq -e '.drawn_area > .dem_area - 1e-6' "$WORK/fill.json"
# The drawn fraction is at most the valid cells' (nothing over nodata) and loses at most a
# rim of triangles around the holes: between 0.8 and 1.0 times the valid fraction.
check "hole: drawn fraction within [0.8, 1.0] x valid fraction" \
  jq -e '(.drawn_area / .dem_area) as $d | $d <= .valid_fraction and $d >= 0.8 * .valid_fraction' "$WORK/hole.json"

case_ "meuse.tif --nodata hole: verify (crack-free, mask = DEM's) and an automatic view"
run terrainlod verify "$WORK/hole.tlp" --dem "$meuse" --cameras 8
expect_status 0
expect_json '[.ok, .open_edges, .nodata_mask_matches_dem]' '[true,0,true]'
run terrainlod extract "$WORK/hole.tlp" --camera-preset top --clip -o "$WORK/auto.obj" --png "$WORK/auto.png" --report "$WORK/auto.json"
expect_status 0
run terrainlod extract "$WORK/fill.tlp" --camera-preset top --clip -o "$WORK/fauto.obj" --report "$WORK/fauto.json"
expect_status 0
# From above, the hole pyramid's camera frames the valid samples' box, the filled one's the
# DEM rectangle (same heights: the same tiles): the first is closer.
check "top view of the holes closer than of the filled DEM" \
  sh -c "test \$(jq -n --slurpfile a '$WORK/auto.json' --slurpfile b '$WORK/fauto.json' '\$a[0].camera.eye[2] < \$b[0].camera.eye[2]') = true"
check "rendering written" test -s "$WORK/auto.png"

finish
