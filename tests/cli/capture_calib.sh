#!/usr/bin/env bash
# capture calib-camera / calib-turntable / calib-lights end to end on images rendered
# with known geometry (tests/tools/calib_render, scenes of tests/unit/calib_scenes.hpp):
# the targets of docs/capture.md §6 -- turntable axis within 0.05 degrees and centre
# within 0.1 mm, light position within 1 mm at about 500 mm -- and a known camera
# recovered. Then bad input: one clean line, the right status, nothing on stdout.
source "$(dirname "$0")/lib.sh"
render="$FEST_BIN/calib_render"
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }
# angle_deg '[x,y,z]' '[x,y,z]': angle between two vectors in degrees
angle_deg() {
  jq -n --argjson a "$1" --argjson b "$2" \
    '[($a[0]*$b[0]+$a[1]*$b[1]+$a[2]*$b[2]) / ((($a|map(.*.)|add)|sqrt) * (($b|map(.*.)|add)|sqrt))] | .[0]' |
    awk '{ c = $1; if (c > 1) c = 1; if (c < -1) c = -1; printf "%.8f\n", atan2(sqrt(1 - c * c), c) * 45 / atan2(1, 1) }'
}
# distance '[x,y,z]' '[x,y,z]'
distance() { jq -n --argjson a "$1" --argjson b "$2" '[range(3) as $i | ($a[$i]-$b[$i]) * ($a[$i]-$b[$i])] | add | sqrt'; }

case_ "help"
run capture --help
expect_status 0
for c in calib-camera calib-turntable calib-lights; do check "help lists $c" grep -q "$c" "$out"; done
run capture calib-turntable --help
expect_status 0
check "calib-turntable --help names --angles" grep -q -- "--angles" "$out"

mkdir -p "$WORK/c" "$WORK/t" "$WORK/s"
check "render the camera views" "$render" camera "$WORK/c"
check "render the turntable views" "$render" turntable "$WORK/t"
check "render the chrome spheres" "$render" spheres "$WORK/s"

case_ "calib-camera: the rendering camera recovered"
run capture calib-camera --board 9x6x25mm --fix-k3 "$WORK"/c/c*.png
expect_status 0
expect_json '.K | length' 9
expect_json '.dist | length' 5
expect_json '[.width, .height]' '[640,480]'
expect_json '.views | length' 10
cp "$out" "$WORK/camera.json"
# Truth (calib_scenes.hpp): fx 700, fy 696.5, cx 323.5, cy 237.5, k1 -0.15, k2 0.08.
# Corners found to ~0.05 px bound fx, fy to 0.3 % and the centre to 1.5 px.
read -r fx fy cx cy k1 rms < <(jq -r '[.K[0], .K[4], .K[2], .K[5], .dist[0], .rms] | @tsv' "$WORK/camera.json")
le "$(jq -n "($fx - 700) | fabs / 700")" 0.003 && pass || fail "fx $fx, expected 700 within 0.3 %"
le "$(jq -n "($fy - 696.5) | fabs / 696.5")" 0.003 && pass || fail "fy $fy, expected 696.5 within 0.3 %"
le "$(jq -n "($cx - 323.5) | fabs")" 1.5 && pass || fail "cx $cx, expected 323.5 within 1.5 px"
le "$(jq -n "($cy - 237.5) | fabs")" 1.5 && pass || fail "cy $cy, expected 237.5 within 1.5 px"
le "$(jq -n "($k1 + 0.15) | fabs")" 0.01 && pass || fail "k1 $k1, expected -0.15 within 0.01"
le "$rms" 0.1 && pass || fail "RMS reprojection error $rms px > 0.1"

case_ "calib-camera: an image without the board is left out, with a warning unless -q"
{ printf 'P5\n640 480\n255\n'; head -c 307200 /dev/zero; } >"$WORK/blank.pgm"
run capture calib-camera --board 9x6x25mm --fix-k3 "$WORK/blank.pgm" "$WORK"/c/c*.png
expect_status 0
expect_json '.left_out | length' 1
expect_json '.views | length' 10
expect_stderr_has "^capture: warning: no 9x6 board found; image left out \\(.*blank.pgm\\)$"
check "the same calibration" cmp -s <(jq -c '{K, dist, rms}' "$out") <(jq -c '{K, dist, rms}' "$WORK/camera.json")
run capture calib-camera --board 9x6x25mm --fix-k3 -q "$WORK/blank.pgm" "$WORK"/c/c*.png
expect_status 0
check "-q: nothing on standard error" test ! -s "$err"

case_ "calib-turntable: axis within 0.05 degrees, centre within 0.1 mm"
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x6x25mm --angles 12 "$WORK"/t/t*.png
expect_status 0
cp "$out" "$WORK/tt.json"
axis_err=$(angle_deg "$(jq -c .axis "$WORK/tt.json")" "$(jq -c .axis "$WORK/t/truth.json")")
centre_err=$(distance "$(jq -c .t_T0 "$WORK/tt.json")" "$(jq -c .t_T0 "$WORK/t/truth.json")")
le "$axis_err" 0.05 && pass || fail "axis error $axis_err degrees > 0.05"
le "$centre_err" 0.1 && pass || fail "centre error $centre_err mm > 0.1"
le "$(jq .angle_rms_deg "$WORK/tt.json")" 0.05 && pass || fail "angle RMS $(jq .angle_rms_deg "$WORK/tt.json") > 0.05 degrees"
expect_json '.views | length' 12
expect_json '.R_T0 | length' 9
# R_T0's third column is the axis.
check "R_T0 z column = axis" test "$(angle_deg "$(jq -c '[.R_T0[2], .R_T0[5], .R_T0[8]]' "$WORK/tt.json")" "$(jq -c .axis "$WORK/tt.json")")" = "0.00000000"
echo "turntable: axis error $axis_err deg, centre error $centre_err mm"

case_ "calib-turntable: --angles as a list is the same as the count"
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x6x25mm --angles 0,30,60,90,120,150,180,210,240,270,300,330 "$WORK"/t/t*.png
expect_status 0
check "same result" cmp -s "$out" "$WORK/tt.json"

case_ "calib-turntable: a view commanded at the wrong angle shows in its residual"
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x6x25mm --angles 0,30,60,92,120,150,180,210,240,270,300,330 "$WORK"/t/t*.png
expect_status 0
# Residuals: -2 for that view, 0 elsewhere, less the common zero (about -2/12).
le "$(jq '.views[3].residual_deg + 2 - 2 / 12 | fabs' "$out")" 0.02 && pass || fail "view 3 residual $(jq '.views[3].residual_deg' "$out")"

case_ "calib-lights: light within 1 mm at about 500 mm"
run capture calib-lights --camera "$WORK/s/cam.json" --ball-radius 25 --id L7 "$WORK/s/s0.png" "$WORK/s/s1.png"
expect_status 0
expect_json '.lights[0].id' '"L7"'
expect_json '.lights[0].rays' 6
expect_json '.spheres | length' 6
light_err=$(distance "$(jq -c '.lights[0].position' "$out")" "$(jq -c .light "$WORK/s/truth.json")")
le "$light_err" 1.0 && pass || fail "light position error $light_err mm > 1"
le "$(jq '.lights[0].residual_mm' "$out")" 1.0 && pass || fail "residual $(jq '.lights[0].residual_mm' "$out") mm > 1"
echo "lights: position error $light_err mm"

case_ "bad input: no board in any image names the files"
run capture calib-camera --board 9x6x25mm "$WORK/s/s0.png" "$WORK/s/s1.png"
expect_clean_failure 3 capture
expect_stderr_has "no 9x6 board found in any image: .*s0.png, .*s1.png"

case_ "bad input: too few views"
run capture calib-camera --board 9x6x25mm "$WORK/c/c00.png" "$WORK/c/c01.png"
expect_clean_failure 3 capture
expect_stderr_has "at least 3"

case_ "bad input: images of different sizes"
run capture calib-camera --board 9x6x25mm "$WORK/c/c00.png" "$WORK/t/t00.png" "$WORK/c/c01.png"
expect_clean_failure 3 capture
expect_stderr_has "800x600"

case_ "bad input: a file that is no image"
printf 'not an image at all\n' >"$WORK/junk.png"
run capture calib-camera --board 9x6x25mm "$WORK/junk.png" "$WORK"/c/c*.png
expect_clean_failure 3 capture
run capture calib-camera --board 9x6x25mm "$WORK/camera.json" "$WORK"/c/c*.png
expect_clean_failure 3 capture
expect_stderr_has "image was expected"

case_ "I/O error: a missing image"
run capture calib-camera --board 9x6x25mm "$WORK/none.png" "$WORK"/c/c*.png
expect_clean_failure 4 capture

case_ "usage: malformed board, square pattern, symmetric board for a turntable"
run capture calib-camera --board 9x6 "$WORK"/c/c*.png
expect_clean_failure 2 capture
run capture calib-camera --board 6x6x25mm "$WORK"/c/c*.png
expect_clean_failure 2 capture
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x7x25mm "$WORK"/t/t*.png
expect_clean_failure 2 capture
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x6x25mm --angles 0,a,60 "$WORK"/t/t*.png
expect_clean_failure 2 capture
run capture calib-lights --camera "$WORK/s/cam.json" --ball-radius -3 "$WORK/s/s0.png"
expect_clean_failure 2 capture

case_ "bad input: angles and images do not pair up"
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x6x25mm --angles 0,30,60 "$WORK"/t/t*.png
expect_clean_failure 3 capture
expect_stderr_has "3 turntable angles for 12 images"

case_ "bad input: views spanning too small a turn"
run capture calib-turntable --camera "$WORK/t/cam.json" --board 9x6x25mm --angles 0,5,10 "$WORK"/t/t0[0-2].png
expect_clean_failure 3 capture
expect_stderr_has "at least 20"

case_ "bad input: images not of the calibrated camera's size"
run capture calib-turntable --camera "$WORK/camera.json" --board 9x6x25mm "$WORK"/t/t*.png
expect_clean_failure 3 capture
expect_stderr_has "calibrated at 640x480"

case_ "bad input: malformed camera.json"
echo '{"K":[1,2,3],"width":640,"height":480}' >"$WORK/bad_cam.json"
run capture calib-lights --camera "$WORK/bad_cam.json" --ball-radius 25 "$WORK/s/s0.png"
expect_clean_failure 3 capture
expect_stderr_has "'K' must hold 9 numbers"
echo '{"K":[1,0,0' >"$WORK/broken.json"
run capture calib-turntable --camera "$WORK/broken.json" --board 9x6x25mm "$WORK"/t/t*.png
expect_clean_failure 3 capture

case_ "bad input: no chrome sphere in board images"
run capture calib-lights --camera "$WORK/t/cam.json" --ball-radius 25 "$WORK/t/t00.png" "$WORK/t/t01.png"
expect_clean_failure 3 capture
expect_stderr_has "no chrome sphere with a highlight found in any image"

finish
