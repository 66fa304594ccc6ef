#!/usr/bin/env bash
# VTK datasets fest writes (legacy .vtk, XML .vtu/.vti/.vtp), read by VTK's own Python
# readers -- what ParaView uses. Expected counts come from the inputs' own headers or
# from the parameters that made them.
. "$(dirname "$0")/../cli/lib.sh"
. "$(dirname "$0")/interop_lib.sh"
here=$(cd "$(dirname "$0")" && pwd)

py_has vtk python3-vtk9 || finish_interop

# vtk_check FILE EXPR: VTK reads FILE and the Python expression EXPR holds for its facts d.
vtk_check() {
  "$PY" "$here/vtk_read.py" "$1" >"$out" 2>"$err"; rc=$?
  expect_status 0
  check "$2" "$PY" -c "import json,sys; d=json.load(open('$out')); sys.exit(0 if ($2) else 1)"
}

src="$FEST_FIXTURES/dataset/rotating_tets.vtu"
np=$(grep -o 'NumberOfPoints="[0-9]*"' "$src" | grep -o '[0-9]*')
nc=$(grep -o 'NumberOfCells="[0-9]*"' "$src" | grep -o '[0-9]*')
for ext in vtk vtu; do
  "$FEST_BIN/fconv" "$src" -o "$WORK/tets.$ext"
  case_ "VTK reads fconv's tets.$ext"
  vtk_check "$WORK/tets.$ext" "d['points'] == $np and d['cells'] == $nc and 'point:velocity' in d['arrays']"
done

# A helix grid of n^3 cells as lemtrace makes it, and 10 streamlines through it.
"$FEST_BIN/lemtrace" gen helix --n 4 -o "$WORK/helix.vtu"
case_ "VTK reads lemtrace's generated grid"
vtk_check "$WORK/helix.vtu" "d['cells'] > 0 and 'point:velocity' in d['arrays']"
"$FEST_BIN/lemtrace" "$WORK/helix.vtu" --seed-line 0.2,0,-0.5:0.6,0,-0.5:10 -o "$WORK/lines.vtp"
case_ "VTK reads lemtrace's streamlines (.vtp)"
vtk_check "$WORK/lines.vtp" "d['cells'] == 10 and d['points'] >= 20"

# fluidsim: a closed box of 8x6x5 interior nodes for 2 frames, written as VTK image
# data with its boundary nodes (fluidsim(1): "dims" counts interior nodes), 10x8x7.
printf '{"dims": [8, 6, 5], "bc": "closed", "frame_dt": 0.04, "frames": 2, "scalars": [{"name": "density", "sources": [{"shape": "box", "min": [2, 2, 1], "max": [4, 4, 2], "rate": 5.0}]}]}' >"$WORK/box.json"
"$FEST_BIN/fluidsim" run "$WORK/box.json" -o "$WORK/f%03d.vti" >/dev/null 2>"$err"
last=$(ls "$WORK"/f*.vti 2>/dev/null | tail -1)
case_ "VTK reads fluidsim's frames (.vti)"
check "frames written" test -n "$last"
[ -n "$last" ] && vtk_check "$last" "d['dims'] == [10, 8, 7] and 'point:density' in d['arrays']"

finish_interop
