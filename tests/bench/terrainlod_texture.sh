#!/usr/bin/env bash
# terrainlod texture tiles (docs/terrainlod.md §3-4): what textures add to a build of
# the real Jacksboro DEM (403 x 344, B = T = 64, L = 3) -- time of the texture stage
# (resample, box-filter, encode), bytes per level and per texel for PNG and JPEG, the
# directory container against the archive -- and a textured extraction. One JSON line per
# case. Run by hand:  tests/bench/terrainlod_texture.sh [build/bin]
set -euo pipefail
BIN=${1:-build/bin}
TESTDATA=${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}
npz=$TESTDATA/dem/jacksboro_fault_dem.npz
[ -f "$npz" ] || { echo '{"bench":"terrainlod_texture","skipped":"jacksboro_fault_dem.npz not fetched (scripts/fetch-test-data.sh)"}'; exit 0; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
unzip -p "$npz" elevation.npy >"$work/jb.npy"

build() {  # build NAME ARGS...: one JSON line with CPU, wall, peak memory and the sizes
  local name="$1"; shift
  /usr/bin/time -f '%U %S %e %M' -o "$work/cpu" \
    "$BIN/terrainlod" build "$work/jb.npy" --cell-size 74.5,92.5 --threads 1 --report "$work/b.json" "$@"
  read -r user sys wall rss <"$work/cpu"
  jq -c --arg name "$name" --argjson user "$user" --argjson sys "$sys" --argjson wall "$wall" --argjson rss "$rss" \
    '{bench: "terrainlod_texture", case: $name, container, tiles, bytes, texture_bytes,
      texture_bytes_per_texel: (.texture_bytes / (.tiles * 64 * 64)), texture_ms: .time_ms.texture,
      build_ms: .time_ms.build, cpu_s: ($user + $sys), wall_s: $wall, peak_rss_kb: $rss}' "$work/b.json"
}
build "no texture" -o "$work/plain.tlp"
build "hillshade png" -o "$work/png.tlp" --texture hillshade
build "hillshade jpeg q90" -o "$work/jpg.tlp" --texture hillshade --texture-format jpeg
build "hillshade png, directory" -o "$work/dir" --texture hillshade
"$BIN/terrainlod" stats "$work/png.tlp" | jq -c '{bench: "terrainlod_texture", case: "png texture bytes by level",
  by_level: [.level[] | {level, tiles, texture: .bytes.texture, geometry: (.bytes.total)}]}'
printf '{"eye": [15000, -6000, 5000], "target": [15000, 12000, 400], "fovy_deg": 50, "width": 800, "height": 500, "near": 10, "tau_px": 4}\n' >"$work/cam.json"
for pyr in plain.tlp png.tlp dir; do
  /usr/bin/time -f '%U %S %e %M' -o "$work/cpu" \
    "$BIN/terrainlod" extract "$work/$pyr" --camera "$work/cam.json" --clip -o "$work/v.ply" --png "$work/v.png" --report "$work/x.json"
  read -r user sys wall rss <"$work/cpu"
  jq -c --arg p "$pyr" --argjson user "$user" --argjson sys "$sys" --argjson wall "$wall" --argjson rss "$rss" \
    '{bench: "terrainlod_texture", case: ("extract + render 800x500 from " + $p), tiles, textures, triangles, bytes_touched,
      time_ms, cpu_s: ($user + $sys), wall_s: $wall, peak_rss_kb: $rss}' "$work/x.json"
done
