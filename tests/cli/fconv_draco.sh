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

# fconv's Draco settings mean what draco_encoder's do (--draco-bits = -qp, default 11;
# --draco-normal-bits = -qn 8; --draco-texcoord-bits = -qt 10; --draco-speed = 10 - -cl,
# default -cl 7): on the same PLY, fconv's file is no larger than draco_encoder's, and
# draco_decoder (an independent program) gives positions within half a quantization step
# per coordinate: step = largest bbox extent / (2^bits - 1), so every vertex, and hence the
# surface, lies within sqrt(3) step / 2 (1 % for float rounding) of the input. Counts and
# topology are not compared: Draco merges vertices equal in every attribute (as
# draco_encoder does) and its Edgebreaker coder splits non-manifold vertices.
meshes=()
for m in meshes/bunny00.off meshes/cow.off meshes/assimp/Wuson.ply; do
  f=$(need_testdata "$m" 2>/dev/null) && meshes+=("$f")
done
for f in "${meshes[@]}"; do
  name=$(basename "${f%.*}")
  "$FEST_BIN/fconv" "$f" -o "$WORK/$name.ply"
  # draco_encoder's PLY reader leaves texture coordinates (s/t) out; its OBJ reader takes
  # vt. A mesh with them goes to draco_encoder as OBJ, so that both files hold the same
  # attributes (Wuson: docs/fconv.md §6).
  ref="$WORK/$name.ply"
  if [ "$(jq -r '.attributes | index("vertex_texcoords") != null' <("$FEST_BIN/fconv" --info "$WORK/$name.ply"))" = true ]; then
    "$FEST_BIN/fconv" "$WORK/$name.ply" -o "$WORK/$name.obj"
    ref="$WORK/$name.obj"
  fi
  extent=$("$FEST_BIN/fconv" --info "$WORK/$name.ply" | jq '[.bbox.max, .bbox.min] | transpose | map(.[0] - .[1]) | max')
  for qp in 11 14; do
    case_ "$name at $qp bits: no larger than draco_encoder -qp $qp, within the quantization bound"
    draco_encoder -i "$ref" -o "$WORK/$name.ref$qp.drc" -qp "$qp" >/dev/null
    if [ "$qp" = 11 ]; then run fconv "$WORK/$name.ply" -o "$WORK/$name.$qp.drc"  # the defaults
    else run fconv --draco-bits "$qp" "$WORK/$name.ply" -o "$WORK/$name.$qp.drc"; fi
    expect_status 0
    ours=$(stat -c %s "$WORK/$name.$qp.drc"); theirs=$(stat -c %s "$WORK/$name.ref$qp.drc")
    check "fconv $ours <= draco_encoder $theirs bytes" test "$ours" -le "$theirs"
    check "both files hold the same attributes" test \
      "$("$FEST_BIN/fconv" --info "$WORK/$name.$qp.drc" | jq -c .attributes)" = \
      "$("$FEST_BIN/fconv" --info "$WORK/$name.ref$qp.drc" | jq -c .attributes)"
    check "draco_decoder reads fconv's file" draco_decoder -i "$WORK/$name.$qp.drc" -o "$WORK/$name.$qp.back.ply"
    tol=$(awk -v e="$extent" -v b="$qp" 'BEGIN { printf "%.9g", e / (2^b - 1) / 2 * sqrt(3) * 1.01 }')
    run fcompare --samples 0 --ignore-counts --ignore-topology --tol "$tol" "$WORK/$name.ply" "$WORK/$name.$qp.back.ply"
    expect_status 0
  done
  case_ "$name at -cl 10 (--draco-speed 0): no larger than draco_encoder's"
  draco_encoder -i "$ref" -o "$WORK/$name.ref_cl10.drc" -qp 14 -cl 10 >/dev/null
  run fconv --draco-bits 14 --draco-speed 0 "$WORK/$name.ply" -o "$WORK/$name.cl10.drc"
  expect_status 0
  check "fconv <= draco_encoder at -cl 10" test "$(stat -c %s "$WORK/$name.cl10.drc")" -le "$(stat -c %s "$WORK/$name.ref_cl10.drc")"
done

case_ "--help shows the Draco defaults"
run fconv --help
expect_status 0
check "--draco-bits default 11" grep -Eq -- '--draco-bits .*=11$' "$out"
check "--draco-speed default 3" grep -Eq -- '--draco-speed .*=3$' "$out"

case_ "--draco-normal-bits out of range: usage error naming the flag"
run fconv --draco-normal-bits 31 "$WORK/tri.off" --to drc
expect_status 2
expect_stderr_has "draco-normal-bits"

case_ "--precision takes float or double only"
run fconv --precision half "$WORK/tri.off" --to ply
expect_status 2

finish
