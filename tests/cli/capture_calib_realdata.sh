#!/usr/bin/env bash
# capture calib-camera on real photographs: the 13 chessboard views of OpenCV's sample
# data (opencv-doc, examples/data/left*.jpg, fetched by scripts/fetch-test-data.sh),
# read as they are (JPEG).
# Basis of the check: OpenCV's own calibration of this set, shipped beside the images
# as samples/data/left_intrinsics.yml (OpenCV 4.x; flags: fixed aspect ratio):
# fx = fy = 535.92, cx = 342.28, cy = 235.57, k1 = -0.266, reprojection error 0.393 px.
# Ours (aspect ratio free) must agree within 1.5 % on the focal lengths, 5 px on the
# principal point, and reach a reprojection error no worse than OpenCV's.
source "$(dirname "$0")/lib.sh"
first=$(need_testdata calib/left01.jpg) || exit 77
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }

case_ "calib-camera on the 13 real views"
run capture calib-camera --board 9x6x25mm "$(dirname "$first")"/left*.jpg
expect_status 0
expect_json '.views | length' 13
expect_json '.left_out | length' 0
expect_json '[.width, .height]' '[640,480]'
read -r fx fy cx cy k1 rms < <(jq -r '[.K[0], .K[4], .K[2], .K[5], .dist[0], .rms] | @tsv' "$out")
le "$(jq -n "($fx - 535.92) | fabs / 535.92")" 0.015 && pass || fail "fx $fx vs OpenCV's 535.92"
le "$(jq -n "($fy - 535.92) | fabs / 535.92")" 0.015 && pass || fail "fy $fy vs OpenCV's 535.92"
le "$(jq -n "($cx - 342.28) | fabs")" 5 && pass || fail "cx $cx vs OpenCV's 342.28"
le "$(jq -n "($cy - 235.57) | fabs")" 5 && pass || fail "cy $cy vs OpenCV's 235.57"
le "$(jq -n "($k1 + 0.266) | fabs")" 0.05 && pass || fail "k1 $k1 vs OpenCV's -0.266"
le "$rms" 0.393 && pass || fail "reprojection error $rms px, OpenCV's 0.393"
echo "opencv-doc left*.jpg: fx $fx fy $fy cx $cx cy $cy k1 $k1 rms $rms"

finish
