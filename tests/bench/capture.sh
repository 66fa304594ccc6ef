#!/usr/bin/env bash
# capture benchmark (docs/capture.md §6): the fully simulated CI session, 24 angles x
# 1 light x 12 exposures (+ 1 silhouette per view) at 640 x 480, then hdrmerge
# --manifest, as one pipeline `capture run | hdrmerge --manifest -`. Prints one JSON line
# per stage and one for the whole: wall, user and system seconds, peak RSS. Target:
# <= 20 s in all on 2 cores (pin with `taskset -c 0,1`); on a loaded machine read the
# CPU seconds (user + sys) instead of the wall time. Not run by CTest.
#
#   tests/bench/capture.sh [build/bin]
set -euo pipefail
BIN=$(cd "${1:-build/bin}" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
D="$HERE/../data/capture"
W=$(mktemp -d "${TMPDIR:-/tmp}/fest-capture-bench.XXXXXX")
trap 'rm -rf "$W"' EXIT
cp "$D/sim_station.json" "$D/sim_scene.json" "$W/"
"$BIN/capture" plan --angles 24 --lights L0 --bracket 1/1000:1:12 --silhouette BG > "$W/plan.json"

measure() {  # measure NAME STDOUT-FILE CMD... : one JSON line from GNU time's figures
  local name="$1" to="$2"; shift 2
  /usr/bin/time -f '%e %U %S %M' -o "$W/time" "$@" > "$to"
  read -r wall user sys rss < "$W/time"
  printf '{"bench":"capture","case":"%s","angles":24,"lights":1,"exposures":12,"width":640,"height":480,"wall_s":%s,"user_s":%s,"sys_s":%s,"peak_rss_mb":%.1f,"cores":%s}\n' \
    "$name" "$wall" "$user" "$sys" "$(echo "$rss / 1024" | bc -l)" "$(nproc)"
}
measure capture_run "$W/manifest.json" "$BIN/capture" run --station "$W/sim_station.json" --plan "$W/plan.json" -o "$W/sess"
measure hdrmerge_manifest "$W/rig.json" "$BIN/hdrmerge" --manifest "$W/sess/manifest.json" -o "$W/sess/hdr"
rm -rf "$W/sess"
measure pipeline /dev/null bash -c "'$BIN/capture' run --station '$W/sim_station.json' --plan '$W/plan.json' -o '$W/sess' | '$BIN/hdrmerge' --manifest - -o '$W/sess/hdr' > '$W/rig.json'"
n=$(jq '.images | length' "$W/rig.json")
[ "$n" -eq 24 ] || { echo "capture bench: rig has $n images, expected 24" >&2; exit 1; }
# The same with the shots stored uncompressed (camera.png_compression 0).
rm -rf "$W/sess"
jq '.camera.png_compression = 0' "$D/sim_station.json" > "$W/sim_station.json"
measure pipeline_png_stored /dev/null bash -c "'$BIN/capture' run --station '$W/sim_station.json' --plan '$W/plan.json' -o '$W/sess' | '$BIN/hdrmerge' --manifest - -o '$W/sess/hdr' > '$W/rig.json'"
n=$(jq '.images | length' "$W/rig.json")
[ "$n" -eq 24 ] || { echo "capture bench: rig has $n images, expected 24" >&2; exit 1; }
