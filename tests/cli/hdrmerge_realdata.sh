#!/usr/bin/env bash
# hdrmerge on real HDR content: Blender's courtyard environment map (blender-data, via
# scripts/fetch-test-data.sh) bracketed by the simulated gamma-2.2 camera into 12 8-bit
# exposures 1/256 .. 8 s, response recovered and merged. Targets from docs/hdrmerge.md
# §6: response within 2 % on z 10..245 (the map's 4.3 decades cover the codes well),
# log-radiance RMS within 2.5 % where the series saw the pixel (validity >= 0.01).
source "$(dirname "$0")/lib.sh"
map=$(need_testdata hdr/courtyard.exr) || exit 77
check_tool="$FEST_BIN/hdr_check"
T=0.00390625,0.0078125,0.015625,0.03125,0.0625,0.125,0.25,0.5,1,2,4,8
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }
ge() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a >= b) }'; }

case_ "bracket courtyard.exr"
mkdir -p "$WORK/s"
run hdrmerge bracket "$map" -t "$T" -o "$WORK/s" --seed 11
expect_status 0

case_ "merge: response within 2 %, radiance within 2.5 % log-RMS (docs/hdrmerge.md §6)"
run hdrmerge "$WORK"/s/e*.png -t "$T" --float -o "$WORK/m.exr" --valid "$WORK/v.exr" --response-out "$WORK/r.csv"
expect_status 0
worst=$("$check_tool" curve "$WORK/r.csv" 2.2)
le "$worst" 0.02 && pass || fail "response error $worst > 0.02"
read -r rms offset frac < <("$check_tool" logrms "$WORK/m.exr" "$map" "$WORK/v.exr" 0.01)
le "$rms" 0.025 && pass || fail "log RMS $rms > 0.025"
ge "$frac" 0.99 && pass || fail "only $frac of the samples were seen by the series"

finish
