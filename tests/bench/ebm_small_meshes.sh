#!/bin/bash
# .ebm size against Draco on small meshes (issue 23: "no larger than Draco's file at equal
# quantisation from 200 vertices up"): each fetched OFF at qp 11 with ebcode (container 2.0
# and, for reference, --ebm-version 1) and with draco_encoder -qp 11 -cl 7 on an OBJ of the
# same OFF (the anchor, same run). One JSON line per mesh.
#
#   tests/bench/ebm_small_meshes.sh [BIN_DIR] [TESTDATA_DIR]
#       (defaults: build/bin, $FEST_TESTDATA or ~/.cache/fest/testdata; MESHES="a b" to choose)
set -u
bin=${1:-build/bin}
data=${2:-${FEST_TESTDATA:-$HOME/.cache/fest/testdata}}/meshes
command -v draco_encoder >/dev/null || { echo '{"bench":"ebm_small_meshes","skipped":"draco_encoder not installed (Debian package draco)"}'; exit 0; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
off2obj() {  # OFF (triangles or polygons, optional comments) -> OBJ
  awk 'BEGIN { s = 0 } /^#/ || NF == 0 { next }
       s == 0 && $1 ~ /OFF/ { if (NF > 1) { nv = $2; nf = $3; s = 2 } else s = 1; next }
       s == 1 { nv = $1; nf = $2; s = 2; next }
       s == 2 && nv > 0 { print "v", $1, $2, $3; nv--; next }
       s == 2 && nf > 0 { line = "f"; for (i = 2; i <= $1 + 1; i++) line = line " " ($i + 1); print line; nf-- }' "$1"
}
for m in ${MESHES:-ellipsoid eight hand head blobby bones mushroom elephant elephant-with-holes cow knot1 femur turbine homer}; do
  f=$data/$m.off
  [ -f "$f" ] || { echo "{\"bench\":\"ebm_small_meshes\",\"mesh\":\"$m\",\"skipped\":\"not fetched\"}"; continue; }
  off2obj "$f" >"$out/m.obj"
  draco_encoder -i "$out/m.obj" -o "$out/m.drc" -qp 11 -cl 7 >/dev/null 2>&1 || { echo "{\"bench\":\"ebm_small_meshes\",\"mesh\":\"$m\",\"skipped\":\"draco_encoder failed\"}"; continue; }
  d=$(wc -c <"$out/m.drc")
  e2=$("$bin/ebcode" --qp 11 "$f" -o - | wc -c)
  e1=$("$bin/ebcode" --ebm-version 1 --qp 11 "$f" -o - | wc -c)
  echo "{\"bench\":\"ebm_small_meshes\",\"mesh\":\"$m\",\"vertices\":$(grep -c '^v ' "$out/m.obj"),\"faces\":$(grep -c '^f ' "$out/m.obj"),\"qp\":11,\"ebm2_bytes\":$e2,\"ebm1_bytes\":$e1,\"draco_cl7_bytes\":$d,\"ebm2_over_draco\":$(awk -v a="$e2" -v b="$d" 'BEGIN { printf "%.4f", a / b }')}"
done
