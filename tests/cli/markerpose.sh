#!/usr/bin/env bash
# markerpose end to end: synthetic markers rendered at known poses by `markerpose gen`
# (the truth is the camera model's projection of the square, cv::projectPoints) are found
# with the right id, corners within 0.1 px and poses within 1 degree / 1 % of the
# distance; a frame stream and a list give one JSON line per frame; the overlay of a unit
# cube lands on the cube's projection; bad input gets one clean line, the right status,
# and nothing written.
source "$(dirname "$0")/lib.sh"

le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }
cat >"$WORK/camera.json" <<'JSON'
{"K":[600,0,319.5,0,600,239.5,0,0,1],"dist":[-0.1,0.04,0.0005,-0.0005,0],"R":[1,0,0,0,1,0,0,0,1],
 "t":[0,0,0],"width":640,"height":480,"rms":0.2,"board":"9x6x25mm","views":[],"left_out":[]}
JSON
cam="$WORK/camera.json"

case_ "help and version"
run markerpose --help
expect_status 0
check "help names the subcommands" grep -q "gen" "$out"
run markerpose --version
expect_status 0

case_ "analytic: a marker at a known pose"
run markerpose gen --camera "$cam" --dict 6x6_250 --id 123 --size 0.05 --distance 0.3 --u 380 --v 200 \
  --tilt 40 --axis 30 --roll 20 --blur 0.8 --noise 2 --black 60 --white 200 -o "$WORK/a.png" --truth "$WORK/a_truth.json"
expect_status 0
run markerpose "$WORK/a.png" --camera "$cam" --size 0.05 --dict 6x6_250
expect_status 0
expect_json 'length' 1
expect_json '.[0].id' 123
cp "$out" "$WORK/a.json"
# Corner error (px), rotation error (deg, from trace(R_a^T R_b)), translation error (% of distance).
corner=$(jq -n --slurpfile d "$WORK/a.json" --slurpfile t "$WORK/a_truth.json" \
  '[range(4) as $k | (($d[0][0].corners[$k][0] - $t[0].corners[$k][0]) | fabs), (($d[0][0].corners[$k][1] - $t[0].corners[$k][1]) | fabs)] | max')
le "$corner" 0.1 && pass || fail "corner error $corner px > 0.1"
rot=$(jq -n --slurpfile d "$WORK/a.json" --slurpfile t "$WORK/a_truth.json" \
  '([range(9)] | map($d[0][0].R[.] * $t[0].R[.]) | add) as $tr | ((($tr - 1) / 2) | if . > 1 then 1 else . end | acos * 180 / 3.141592653589793)')
le "$rot" 1 && pass || fail "rotation error $rot deg > 1"
trans=$(jq -n --slurpfile d "$WORK/a.json" --slurpfile t "$WORK/a_truth.json" \
  '([range(3)] | map(($d[0][0].tvec[.] - $t[0].tvec[.]) | . * .) | add | sqrt) / ([range(3)] | map($t[0].tvec[.] * $t[0].tvec[.]) | add | sqrt) * 100')
le "$trans" 1 && pass || fail "translation error $trans % > 1"
check "reprojection below 0.2 px" le "$(jq '.[0].reproj_rms_px' "$WORK/a.json")" 0.2

case_ "golden: the same detection as when correctness was shown (1e-3 px, 1e-5)"
gold="$FEST_FIXTURES/markerpose/a.json"
if [ -f "$gold" ]; then
  worst=$(jq -n --slurpfile d "$WORK/a.json" --slurpfile g "$gold" \
    '[($d[0][0].corners | flatten) as $a | ($g[0][0].corners | flatten) as $b | range($a | length) | ($a[.] - $b[.]) | fabs] + [($d[0][0].R) as $a | ($g[0][0].R) as $b | range(9) | ($a[.] - $b[.]) * 100 | fabs] | max')
  le "$worst" 0.001 && pass || fail "differs from the golden detection by $worst"
else
  fail "golden file $gold missing"
fi

case_ "deterministic output, any thread count"
run markerpose "$WORK/a.png" --camera "$cam" --size 0.05 --dict 6x6_250 --threads 1
cp "$out" "$WORK/t1.json"
run markerpose "$WORK/a.png" --camera "$cam" --size 0.05 --dict 6x6_250 --threads 3
check "byte-identical" cmp -s "$out" "$WORK/t1.json"

case_ "tvec comes in the unit of --size"
run markerpose "$WORK/a.png" --camera "$cam" --size 50 --dict 6x6_250
z_mm=$(jq '.[0].tvec[2]' "$out"); z_m=$(jq '.[0].tvec[2]' "$WORK/a.json")
check "50 mm marker: z in mm = 1000 z in m" awk -v a="$z_mm" -v b="$z_m" 'BEGIN { d = a - 1000 * b; exit !(d < 1e-3 && d > -1e-3) }'

case_ "a frame stream on standard input: one JSON line per frame, ids right"
run markerpose gen --camera "$cam" --dict 4x4_50 --id 9 --size 0.04 --distance 0.25 --tilt 25 --roll-step 12 \
  --u-step 6 --u 260 --frames 8 --to pgm -o "$WORK/stream.pgm" --truth "$WORK/stream_truth.jsonl"
expect_status 0
run_stdin "$WORK/stream.pgm" markerpose - --camera "$cam" --size 0.04 --dict 4x4_50
expect_status 0
check "8 lines" test "$(wc -l <"$out")" -eq 8
check "every frame has marker 9" test "$(jq -c '[.markers[].id]' "$out" | sort -u)" = "[9]"
check "frame numbers 0..7" test "$(jq -s -c 'map(.frame)' "$out")" = "[0,1,2,3,4,5,6,7]"

case_ "a list of images"
run markerpose gen --dict 4x4_50 --id 3 --size 0.05 --tilt 20 -o "$WORK/l%d.png" --frames 3 --roll-step 30
expect_status 0
printf '%s\n' "$WORK/l0.png" "$WORK/l1.png" "# a comment" "$WORK/l2.png" >"$WORK/list.txt"
printf '{"K":[600,0,319.5,0,600,239.5,0,0,1],"width":640,"height":480}' >"$WORK/ideal.json"
run markerpose --list "$WORK/list.txt" --camera "$WORK/ideal.json" --size 0.05
expect_status 0
check "3 lines, marker 3 in each" test "$(jq -c '[.markers[].id]' "$out" | tr -d '\n')" = "[3][3][3]"

case_ "ARToolKit pattern marker"
"$FEST_BIN/markerpose" draw --dict 7x7_50 --id 5 --cell 8 --quiet-zone 0 -o "$WORK/picture.png"
"$FEST_BIN/markerpose" draw --dict 5x5_50 --id 1 --cell 8 --quiet-zone 0 -o "$WORK/other.png"
run markerpose gen --pattern "$WORK/picture.png" --size 0.08 --distance 0.4 --tilt 30 --roll 100 -o "$WORK/p.png" --truth "$WORK/p_truth.json"
expect_status 0
run markerpose "$WORK/p.png" --camera "$WORK/ideal.json" --size 0.08 --pattern "$WORK/other.png" --pattern "$WORK/picture.png"
expect_status 0
expect_json '[.[].id]' '[1]'
corner=$(jq -n --slurpfile d "$out" --slurpfile t "$WORK/p_truth.json" \
  '[range(4) as $k | (($d[0][0].corners[$k][0] - $t[0].corners[$k][0]) | fabs)] | max')
le "$corner" 0.2 && pass || fail "pattern corner error $corner px > 0.2 (rotation found wrongly?)"

case_ "overlay of a unit cube"
printf 'OFF\n8 6 0\n-0.5 -0.5 0\n0.5 -0.5 0\n-0.5 0.5 0\n0.5 0.5 0\n-0.5 -0.5 1\n0.5 -0.5 1\n-0.5 0.5 1\n0.5 0.5 1\n4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n' >"$WORK/cube.off"
run markerpose "$WORK/a.png" --camera "$cam" --size 0.05 --dict 6x6_250 --overlay "$WORK/cube.off" --overlay-scale 0.05 \
  --overlay-out "$WORK/ar.png" -o "$WORK/ar.json"
expect_status 0
check "overlay written" test -s "$WORK/ar.png"
check "JSON written" test -s "$WORK/ar.json"

case_ "no marker: an empty list, a warning, status 0"
run markerpose gen --dict 4x4_50 --id 0 --size 0.05 --distance 0.3 --u 2000 -o "$WORK/none.png"
run markerpose "$WORK/none.png" --camera "$WORK/ideal.json" --size 0.05
expect_status 0
expect_json '.' '[]'
expect_stderr_has "markerpose: warning: no marker found"

case_ "bad input: no --camera"
run markerpose "$WORK/a.png" --size 0.05
expect_clean_failure 2 markerpose
case_ "bad input: camera file missing"
run markerpose "$WORK/a.png" --camera "$WORK/nope.json" --size 0.05
expect_clean_failure 4 markerpose
case_ "bad input: camera file of another resolution"
printf '{"K":[600,0,399.5,0,600,299.5,0,0,1],"width":800,"height":600}' >"$WORK/cam800.json"
run markerpose "$WORK/a.png" --camera "$WORK/cam800.json" --size 0.05 -o "$WORK/never.json"
expect_clean_failure 3 markerpose
expect_stderr_has "image is 640x480 but the camera .* was calibrated at 800x600"
check "nothing written" test ! -e "$WORK/never.json"
case_ "bad input: images of mixed sizes"
run markerpose gen --width 320 --height 240 --focal 300 --dict 4x4_50 -o "$WORK/small.png"
run markerpose "$WORK/a.png" "$WORK/small.png" --camera "$cam" --size 0.05 --overlay "$WORK/cube.off" --overlay-out "$WORK/never%d.png"
expect_clean_failure 3 markerpose
expect_stderr_has "1 of 2 frames differ"
check "no overlay written" test ! -e "$WORK/never0.png"
case_ "bad input: marker size 0 and negative"
run markerpose "$WORK/a.png" --camera "$cam" --size 0
expect_clean_failure 2 markerpose
run markerpose "$WORK/a.png" --camera "$cam" --size -0.05
expect_clean_failure 2 markerpose
case_ "bad input: malformed camera.json"
printf '{"K":[600,0,319.5],"width":640,"height":480}' >"$WORK/badcam.json"
run markerpose "$WORK/a.png" --camera "$WORK/badcam.json" --size 0.05
expect_clean_failure 3 markerpose
expect_stderr_has "camera: 'K' must hold 9 numbers"
case_ "bad input: unknown dictionary"
run markerpose "$WORK/a.png" --camera "$cam" --size 0.05 --dict 9x9_50
expect_clean_failure 2 markerpose
case_ "bad input: truncated image, empty input"
head -c 2000 "$WORK/a.png" >"$WORK/trunc.png"
run markerpose "$WORK/trunc.png" --camera "$cam" --size 0.05
expect_clean_failure 3 markerpose
: >"$WORK/empty"
run_stdin "$WORK/empty" markerpose - --camera "$cam" --size 0.05
expect_clean_failure 3 markerpose
case_ "bad input: truncated stream"
head -c 400000 "$WORK/stream.pgm" >"$WORK/trunc.pgm"
run_stdin "$WORK/trunc.pgm" markerpose - --camera "$cam" --size 0.04
expect_clean_failure 3 markerpose

finish
