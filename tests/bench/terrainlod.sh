#!/usr/bin/env bash
# terrainlod simplify against Martini and Delatin on the Jacksboro crop (docs/terrainlod.md
# §6: rows 40-296, columns 70-326 of python-matplotlib-data's jacksboro_fault_dem.npz,
# 257 x 257 samples), one JSON line per system and error. Run by hand:
#   tests/bench/terrainlod.sh [build/bin] [node_modules dir with @mapbox/martini and delatin]
# The anchors are skipped with a JSON note when Node or the packages are missing.
# Pyramids are built with the default coding (progressive); stats give both sizes (each
# tile coded both ways), so the build lines print both.
set -euo pipefail
BIN=${1:-build/bin}
MODULES=${2:-${ANCHOR_MODULES:-}}
TESTDATA=${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}
npz=$TESTDATA/dem/jacksboro_fault_dem.npz
[ -f "$npz" ] || { echo '{"bench":"terrainlod_simplify","skipped":"jacksboro_fault_dem.npz not fetched (scripts/fetch-test-data.sh)"}'; exit 0; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
unzip -p "$npz" elevation.npy >"$work/jb.npy"
# Crop with the .npy layout (int16, 344 x 403, C order; the header is 80 bytes, version 1).
node -e '
const fs = require("fs"); const b = fs.readFileSync(process.argv[1]);
const hl = b.readUInt16LE(8), W = 403, off = 10 + hl; const rows = [];
for (let r = 40; r <= 296; r++) { const v = [];
  for (let c = 70; c <= 326; c++) v.push(b.readInt16LE(off + 2 * (r * W + c))); rows.push(v.join(" ")); }
fs.writeFileSync(process.argv[2], "ncols 257\nnrows 257\nxllcorner 0\nyllcorner 0\ncellsize 1\n" + rows.join("\n") + "\n");
' "$work/jb.npy" "$work/jb257.asc"

ERRORS="5 10 20"
# The default start mesh (rtin) and the full lattice it replaced (lattice), same run.
for start in rtin lattice; do
for e in $ERRORS; do
  # CPU seconds of the whole process beside the wall time: the shared machine's load
  # inflates wall times (the anchors' too), CPU time much less.
  /usr/bin/time -f '%U %M' -o "$work/cpu" \
    "$BIN/terrainlod" simplify "$work/jb257.asc" --max-error "$e" --start "$start" -o "$work/m.ply" --report "$work/r.json"
  read -r cpu rss <"$work/cpu"
  jq -c --arg e "$e" --argjson cpu "$cpu" --argjson rss "$rss" '{bench: "terrainlod_simplify", system: "terrainlod",
    start, max_error: ($e | tonumber), vertices, triangles, ms: .time_ms.simplify, cpu_s: $cpu, peak_rss_kb: $rss,
    measured_error}' "$work/r.json"
done
done
if command -v node >/dev/null && [ -n "$MODULES" ] && [ -d "$MODULES/@mapbox/martini" ] && [ -d "$MODULES/delatin" ]; then
  ANCHOR_MODULES=$MODULES node "$(dirname "$0")/terrain_anchors.mjs" "$work/jb257.asc" $ERRORS
else
  echo '{"bench":"terrainlod_simplify","anchors":"skipped: pass a node_modules folder with @mapbox/martini and delatin (npm install @mapbox/martini delatin)"}'
fi

# --- the pyramid on the full Jacksboro DEM (403 x 344, 74.5 m x 92.5 m cells, B = T = 64) ---
/usr/bin/time -f '%U %S %e %M' -o "$work/cpu" \
  "$BIN/terrainlod" build "$work/jb.npy" --cell-size 74.5,92.5 -o "$work/jb.tlp" --threads 1 --report "$work/b.json"
read -r user sys wall rss <"$work/cpu"
"$BIN/terrainlod" stats "$work/jb.tlp" >"$work/s.json"
# Base triangulations of every tile as Cesium quantized-mesh-1.0 (export-qm), gzipped tile
# by tile as they are served.
"$BIN/terrainlod" export-qm "$work/jb.tlp" -o "$work/qm"
qm=$(find "$work/qm" -name '*.terrain' -exec sh -c 'gzip -6 -c "$1" | wc -c' _ {} \; | awk '{ s += $1 } END { print s }')
jq -c --argjson user "$user" --argjson sys "$sys" --argjson wall "$wall" --argjson rss "$rss" --argjson qm "$qm" \
  '{bench: "terrainlod_build", dem: "jacksboro 403x344", tiles: .totals.tiles, vertices: .totals.vertices,
    triangles: .totals.triangles, coding: .totals.coding, tile_bytes: .totals.tile_bytes, bytes_per_vertex: .totals.bytes_per_vertex,
    standalone_tile_bytes: .totals.standalone_tile_bytes, progressive_tile_bytes: .totals.progressive_tile_bytes,
    standalone_bytes_per_vertex: .totals.standalone_bytes_per_vertex, progressive_bytes_per_vertex: .totals.progressive_bytes_per_vertex,
    bytes_per_vertex_by_level: [.level[] | .bytes_per_vertex], qm_gzip_bytes: $qm, ratio_to_qm_gzip: (.totals.tile_bytes / $qm),
    build_cpu_s: ($user + $sys), build_wall_s: $wall, peak_rss_kb: $rss}' "$work/s.json"
"$BIN/terrainlod" verify "$work/jb.tlp" --dem "$work/jb.npy" --cell-size 74.5,92.5 --cameras 20 |
  jq -c '{bench: "terrainlod_verify", dem: "jacksboro 403x344", ok, triangulations_checked, tiles_over_bound, max_err_over_eps, open_edges}'
# fBm 1025^2 (L = 4) and the 4097^2 case of docs/terrainlod.md §6 (L = 6; <= 60 s on 2 cores, <= 1 GB), 30 m
# cells, 1500 m amplitude, 2 threads, the default --reference l+2. max_err_over_eps is
# the largest error of any tile's triangulation against the DEM (measured by the builder
# on every mask), in units of its level's eps; the bound is 4/3.
for k in 10 12; do
  n=$(( (1 << k) + 1 ))
  python3 "$(dirname "$0")/terrain_fbm.py" "$k" 1500 "$work/fbm.pgm"
  /usr/bin/time -f '%U %S %e %M' -o "$work/cpu" \
    "$BIN/terrainlod" build "$work/fbm.pgm" --cell-size 30 -o "$work/fbm.tlp" --threads 2 --report "$work/b.json"
  read -r user sys wall rss <"$work/cpu"
  "$BIN/terrainlod" stats "$work/fbm.tlp" | jq -c --arg dem "fbm ${n}x${n}" --argjson user "$user" --argjson sys "$sys" \
    --argjson wall "$wall" --argjson rss "$rss" --slurpfile b "$work/b.json" \
    '{bench: "terrainlod_build", dem: $dem, threads: 2, reference: .manifest.reference, levels: .manifest.levels,
      tiles: .totals.tiles, vertices: .totals.vertices, coding: .totals.coding, bytes_per_vertex: .totals.bytes_per_vertex,
      standalone_tile_bytes: .totals.standalone_tile_bytes, progressive_tile_bytes: .totals.progressive_tile_bytes,
      standalone_bytes_per_vertex: .totals.standalone_bytes_per_vertex, progressive_bytes_per_vertex: .totals.progressive_bytes_per_vertex,
      max_err_over_eps: ([.level[] | .max_err_over_eps | numbers] | max), build_ms: $b[0].time_ms.build,
      build_cpu_s: ($user + $sys), build_wall_s: $wall, peak_rss_kb: $rss, target: "<= 60 s wall on 2 cores, <= 1 GB (4097^2)"}'
  if [ "$k" = 12 ]; then
    # The view of docs/terrainlod.md §6 (1920 x 1080, 30 degrees below the horizon, tau = 1 px; the target
    # names a 16385^2 DEM, this is the 4097^2 one): eye 4 km up over the south-west
    # quarter, looking north-east. select_close reads tile headers only; decode = the
    # drawn tiles' decoding and triangulation for their masks.
    echo '{"eye":[15000,15000,4000],"target":[21124,21124,-1000],"up":[0,0,1],"fovy_deg":60,"width":1920,"height":1080,"near":1,"far":1e7,"tau_px":1}' >"$work/cam.json"
    /usr/bin/time -f '%e %M' -o "$work/cpu" \
      "$BIN/terrainlod" extract "$work/fbm.tlp" --camera "$work/cam.json" -o "$work/view.ply" --report "$work/x.json"
    read -r wall rss <"$work/cpu"
    jq -c --argjson wall "$wall" --argjson rss "$rss" '{bench: "terrainlod_view", dem: "fbm 4097x4097", width: 1920, height: 1080,
      tau_px: 1, tiles, triangles, select_close_ms: .time_ms.select_close, decode_ms: .time_ms.decode,
      decode_mtriangles_per_s: (.triangles / .time_ms.decode / 1000), write_ms: .time_ms.write, extract_wall_s: $wall,
      peak_rss_kb: $rss, target: "<= 3000 tiles, <= 600K triangles, select + close + decode <= 15 ms, decode >= 20 M triangles/s (16385^2)"}' "$work/x.json"
  fi
  rm -f "$work/fbm.pgm" "$work/fbm.tlp"
done
