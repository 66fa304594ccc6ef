#!/usr/bin/env bash
# Every JSON report fest writes parses as strict JSON in Python's json module (no NaN,
# no Infinity, one document), whatever the kind of input.
. "$(dirname "$0")/../cli/lib.sh"
. "$(dirname "$0")/interop_lib.sh"

command -v python3 >/dev/null || { echo "interop: skip: python3 not installed"; exit 77; }
strict_json() {
  python3 -c '
import json, sys
def no_constant(c): raise ValueError("non-standard JSON constant " + c)
json.load(open(sys.argv[1]), parse_constant=no_constant)' "$1"
}

m="$FEST_FIXTURES/mesh/cube_quads.off"
i="$FEST_FIXTURES/image/pattern_raw.ppm"
v="$FEST_FIXTURES/volume/be_int16.nii"
d="$FEST_FIXTURES/dataset/rotating_tets.vtu"
n=0
for f in "$m" "$i" "$v" "$d" "$FEST_FIXTURES/mesh/tetra_colors_normals.ply"; do
  n=$((n + 1))
  "$FEST_BIN/fconv" --info "$f" -o "$WORK/info$n.json"
  case_ "fconv --info $(basename "$f")"
  check "strict JSON" strict_json "$WORK/info$n.json"
done

# fcompare reports, also where metrics are infinite (identical images: PSNR +inf).
"$FEST_BIN/fcompare" "$i" "$i" --report "$WORK/same.json" >/dev/null
"$FEST_BIN/fcompare" "$m" "$FEST_FIXTURES/mesh/tetra_colors_normals.ply" --report "$WORK/diff.json" >/dev/null 2>&1
for f in same diff; do
  case_ "fcompare --report ($f)"
  check "strict JSON" strict_json "$WORK/$f.json"
done

"$FEST_BIN/ebcode" --qp 0 "$m" -o "$WORK/cube.ebm" --report "$WORK/eb.json"
case_ "ebcode --report"
check "strict JSON" strict_json "$WORK/eb.json"

"$FEST_BIN/lemtrace" gen helix --n 3 -o "$WORK/h.vtu"
"$FEST_BIN/lemtrace" "$WORK/h.vtu" --seed-line 0.2,0,-0.5:0.6,0,-0.5:4 -o "$WORK/l.csv" --report "$WORK/lt.json" 2>/dev/null
if [ -f "$WORK/lt.json" ]; then
  case_ "lemtrace --report"
  check "strict JSON" strict_json "$WORK/lt.json"
fi

finish_interop
