#!/usr/bin/env bash
# Draco's own encoder reads the PLY files fconv writes: it accepts only float32 or int32
# x, y, z, so fconv must write float positions whenever the input's precision allows
# (decimal text of up to 7 significant digits always does).
. "$(dirname "$0")/lib.sh"
if ! command -v draco_encoder >/dev/null; then
  echo "skipped: draco_encoder (package draco) is not installed" >&2
  exit 77
fi

# decimal text that is not exactly float (0.1) but fits a float32
printf 'OFF\n4 2 0\n0.1 0.2 0.3\n1.5 0.25 -0.7\n0.333333 1 0\n-2.5 1e-3 4\n3 0 1 2\n3 0 2 3\n' >"$WORK/tri.off"

for ascii in "" --ascii; do
  case_ "OFF with 0.1 -> PLY $ascii: float positions, and draco_encoder encodes it"
  run fconv $ascii "$WORK/tri.off" -o "$WORK/tri.ply"
  expect_status 0
  check "declares float x" grep -aqx "property float x" "$WORK/tri.ply"
  check "draco_encoder accepts fconv's PLY" draco_encoder -i "$WORK/tri.ply" -o "$WORK/tri.drc"
  check "draco_decoder gives 2 faces back" draco_decoder -i "$WORK/tri.drc" -o "$WORK/back.ply"
  run fconv --info "$WORK/back.ply"
  expect_json '.faces' '2'
done

case_ "--precision double: double positions, which Draco's encoder refuses (it says why)"
run fconv --precision double "$WORK/tri.off" -o "$WORK/tri_double.ply"
expect_status 0
check "declares double x" grep -aqx "property double x" "$WORK/tri_double.ply"
check "draco_encoder refuses double x y z" sh -c "! draco_encoder -i '$WORK/tri_double.ply' -o '$WORK/d.drc'"

case_ "a committed fixture converted to PLY encodes too"
"$FEST_BIN/fconv" "$FEST_FIXTURES/mesh/cube_quads.off" -o "$WORK/cube.ply"
check "draco_encoder accepts the cube" draco_encoder -i "$WORK/cube.ply" -o "$WORK/cube.drc"

case_ "--precision takes float or double only"
run fconv --precision half "$WORK/tri.off" --to ply
expect_status 2

finish
