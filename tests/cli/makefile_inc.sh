#!/usr/bin/env bash
# Makefile.inc over a folder that holds the same names in several formats: make must
# never rewrite an input (checksums before and after), never report a circular
# dependency, and the converted files must hold what their inputs held.
. "$(dirname "$0")/lib.sh"

inc="$(cd "$(dirname "$0")/../.." && pwd)/Makefile.inc"
command -v make >/dev/null || { echo "makefile_inc: make not installed: skipped"; exit 77; }

scans="$WORK/scans"
mkdir -p "$scans/sub"
# Wuson.ply and Wuson.off are two different meshes under one name, as in the report
# that led to this test: converting the OFFs to PLY must not touch the PLY.
cp "$FEST_FIXTURES/mesh/tetra_colors_normals.ply" "$scans/Wuson.ply"
cp "$FEST_FIXTURES/mesh/cube_quads.off" "$scans/Wuson.off"
cp "$FEST_FIXTURES/mesh/cube_quads.off" "$scans/sub/box.off"
cp "$FEST_FIXTURES/mesh/square_uv.obj" "$scans/square.obj"
cp "$FEST_FIXTURES/mesh/triangle.stl" "$scans/triangle.stl"
cp "$FEST_FIXTURES/image/pattern_raw.ppm" "$scans/pattern.ppm"
printf 'P2\n4 2\n255\n0 64 128 255\n255 128 64 0\n' >"$scans/ramp.pgm"
"$FEST_BIN/fconv" "$scans/ramp.pgm" -o "$scans/ramp.png"

cat >"$WORK/Makefile" <<EOF
FEST_BIN := $FEST_BIN
include $inc
OFF := \$(shell find scans -name '*.off')
PLY := \$(wildcard scans/*.ply)
all: \$(OFF:%.off=\$(FEST_OUT)/%.ply) \$(PLY:%.ply=\$(FEST_OUT)/%.off) \\
     \$(FEST_OUT)/scans/square.ply \$(FEST_OUT)/scans/triangle.ply \\
     \$(FEST_OUT)/scans/pattern.png \$(FEST_OUT)/resized/scans/ramp.png \\
     scans/Wuson.ply.info.json
EOF

sums() { (cd "$scans" && find . -type f ! -name '*.info.json' | sort | xargs sha256sum); }
before=$(sums)

case_ "make -j2 over PLY, OFF, OBJ, STL, PPM and PNG inputs"
(cd "$WORK" && make -j2 RESIZE_FLAGS='--size 2x1 --filter box' >"$out" 2>"$err")
rc=$?
expect_status 0
check "no input changed" test "$before" = "$(sums)"
check "no circular dependency" bash -c "! grep -qi circular '$out' '$err'"
for f in scans/Wuson.ply scans/sub/box.ply scans/Wuson.off scans/square.ply scans/triangle.ply \
         scans/pattern.png resized/scans/ramp.png; do
  check "fest-out/$f made" test -s "$WORK/fest-out/$f"
done
check "info beside its input" test -s "$scans/Wuson.ply.info.json"

case_ "the converted files hold what their inputs held"
check "OFF -> PLY" "$FEST_BIN/fcompare" -q "$scans/Wuson.off" "$WORK/fest-out/scans/Wuson.ply"
check "PLY -> OFF" "$FEST_BIN/fcompare" -q --ignore-counts --tol 1e-6 "$scans/Wuson.ply" "$WORK/fest-out/scans/Wuson.off"
check "PPM -> PNG" "$FEST_BIN/fcompare" -q "$scans/pattern.ppm" "$WORK/fest-out/scans/pattern.png"
# A box filter halving 4x2 to 2x1 averages pixel pairs in linear light; the size is the
# check here, the filter's values are resample's own tests.
check "resized to 2x1" test "$("$FEST_BIN/fconv" --info "$WORK/fest-out/resized/scans/ramp.png" | jq -c '[.width,.height]')" = "[2,1]"

case_ "a second make has nothing to do"
(cd "$WORK" && make -j2 RESIZE_FLAGS='--size 2x1 --filter box' >"$out" 2>"$err")
rc=$?
expect_status 0
check "nothing rebuilt" grep -q "Nothing to be done" "$out"
check "still no input changed" test "$before" = "$(sums)"

case_ "asking make for an input in place finds no rule that could overwrite it"
touch "$scans/Wuson.off"   # newer than Wuson.ply: an in-place %.ply: %.off rule would fire
(cd "$WORK" && make scans/Wuson.ply >"$out" 2>"$err")
rc=$?
expect_status 0
check "Wuson.ply untouched" test "$(sha256sum <"$scans/Wuson.ply")" = "$(sha256sum <"$FEST_FIXTURES/mesh/tetra_colors_normals.ply")"

# The default RESIZE_FLAGS (--width 256): the 4x2 ramp becomes 256 x round(2 * 256 / 4)
# = 256x128; RESAMPLE_FLAGS reaches the command (a lower --quality, a smaller file).
case_ "the resize rule: --width 256 keeps the aspect ratio, JPEG output, RESAMPLE_FLAGS"
(cd "$WORK" && make fest-out/resized/scans/ramp.jpg >"$out" 2>"$err")
rc=$?
expect_status 0
check "256x128 JPEG" test "$("$FEST_BIN/fconv" --info "$WORK/fest-out/resized/scans/ramp.jpg" | jq -c '[.width,.height,.format]')" = '[256,128,"jpeg"]'
big=$(wc -c <"$WORK/fest-out/resized/scans/ramp.jpg")
rm "$WORK/fest-out/resized/scans/ramp.jpg"
(cd "$WORK" && make fest-out/resized/scans/ramp.jpg RESAMPLE_FLAGS='--quality 20' >"$out" 2>"$err")
rc=$?
expect_status 0
check "--quality 20 from RESAMPLE_FLAGS gives a smaller file" test "$(wc -c <"$WORK/fest-out/resized/scans/ramp.jpg")" -lt "$big"

finish
