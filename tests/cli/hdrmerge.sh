#!/usr/bin/env bash
# hdrmerge end to end: a known radiance image (hdr_check ramp, 4 decades) bracketed by
# the simulated gamma-2.2 camera into 12 exposures, response recovered and merged; the
# errors are measured against the mathematics (docs/hdrmerge.md §6: response within 2 %
# on z 10..245, log-radiance RMS within 2.5 %). Then bad input: one clean line, the
# right status, nothing written.
source "$(dirname "$0")/lib.sh"
check_tool="$FEST_BIN/hdr_check"
T=0.001,0.002,0.004,0.008,0.016,0.032,0.064,0.128,0.256,0.512,1.024,2.048

le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }

case_ "help"
run hdrmerge --help
expect_status 0
check "help names the subcommands" grep -q "calibrate" "$out"

case_ "bracket the known radiance"
"$check_tool" ramp 160 120 "$WORK/E.pfm"
mkdir -p "$WORK/s" "$WORK/clean"
run hdrmerge bracket "$WORK/E.pfm" -t "$T" -o "$WORK/s" --gamma 2.2 --noise 0.5 --seed 3 --response-out "$WORK/true.csv"
expect_status 0
expect_stdout_empty
check "12 exposures written" test -f "$WORK/s/e11.png" -a ! -e "$WORK/s/e12.png"
run hdrmerge bracket "$WORK/E.pfm" -t "$T" -o "$WORK/clean" --noise 0
expect_status 0

case_ "calibrate: response within 2 % of gamma 2.2"
run hdrmerge calibrate "$WORK"/s/e*.png -t "$T"
expect_status 0
check "256 rows and a header" test "$(wc -l <"$out")" -eq 257
check "header z,gR,gG,gB" grep -qx 'z,gR,gG,gB' "$out"
worst=$("$check_tool" curve "$out" 2.2)
le "$worst" 0.02 && pass || fail "response error $worst > 0.02"
truth_worst=$("$check_tool" curve "$WORK/true.csv" 2.2)
le "$truth_worst" 1e-12 && pass || fail "bracket's true curve is not gamma 2.2 ($truth_worst)"

case_ "calibrate --method robertson: response within 2 % too"
run hdrmerge calibrate "$WORK"/s/e*.png -t "$T" --method robertson
expect_status 0
worst=$("$check_tool" curve "$out" 2.2)
le "$worst" 0.02 && pass || fail "Robertson response error $worst > 0.02"

case_ "merge: log-radiance RMS within 2.5 %"
run hdrmerge "$WORK"/s/e*.png -t "$T" -o "$WORK/m.exr" --float --valid "$WORK/valid.exr" --response-out "$WORK/r.csv"
expect_status 0
expect_stdout_empty
read -r rms offset frac < <("$check_tool" logrms "$WORK/m.exr" "$WORK/E.pfm")
le "$rms" 0.025 && pass || fail "log RMS $rms > 0.025"
# g(128) = 0 puts E = 1 at code 128 for dt = 1: merged = E (255/128)^2.2, ln = 1.5161.
near "$offset" 1.5161 0.03 && pass || fail "scale offset $offset, expected 1.5161"
near "$frac" 1 0 && pass || fail "only a fraction $frac of the pixels is positive"
check "the response used is the calibrated one" cmp -s "$WORK/r.csv" <("$FEST_BIN/hdrmerge" calibrate "$WORK"/s/e*.png -t "$T")
run fcompare "$WORK/valid.exr" "$WORK/valid.exr"
expect_status 0

case_ "merge with the true response of a noiseless series: only rounding remains"
run hdrmerge "$WORK"/clean/e*.png -t "$T" --response "$WORK/true.csv" -o "$WORK/exact.pfm"
expect_status 0
read -r rms offset frac < <("$check_tool" logrms "$WORK/exact.pfm" "$WORK/E.pfm")
# +-0.5 DN of rounding: 2.2 * 0.29 / z in ln E, 0.01 at z = 64, averaged over exposures.
le "$rms" 0.01 && pass || fail "log RMS $rms > 0.01"
near "$offset" 1.5161 0.01 && pass || fail "scale offset $offset"

case_ "standard output carries the same EXR as -o"
run hdrmerge "$WORK"/s/e*.png -t "$T" --float
expect_status 0
check "stdout EXR equals the file" cmp -s "$out" "$WORK/m.exr"

case_ "fractions in --times"
run hdrmerge "$WORK"/clean/e0[0-2].png -t 1/1000,1/500,1/250 --response "$WORK/true.csv" --to pfm
expect_status 0
check "PFM on stdout" grep -qa '^PF' <(head -c 2 "$out")

# --- bad input: status 3, one line, nothing written --------------------------------
mkdir -p "$WORK/small"
"$check_tool" ramp 80 60 "$WORK/E_small.pfm"
"$FEST_BIN/hdrmerge" bracket "$WORK/E_small.pfm" -t 0.001 -o "$WORK/small"

bad() {  # bad WHAT STATUS ARGS...: hdrmerge fails cleanly and writes no output file
  local what="$1" status="$2"; shift 2
  case_ "$what"
  rm -f "$WORK/bad.exr"
  run hdrmerge "$@" -o "$WORK/bad.exr"
  expect_clean_failure "$status" hdrmerge
  check "no output file" test ! -e "$WORK/bad.exr"
}
bad "image sizes differ" 3 "$WORK/s/e00.png" "$WORK/small/e00.png" -t 0.001,0.002
expect_stderr_has 'first of the series'
bad "a single exposure" 3 "$WORK/s/e00.png" -t 0.001
expect_stderr_has 'at least 2'
bad "times not increasing" 3 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.002,0.001
expect_stderr_has 'increase'
bad "equal times" 3 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.002,0.002
bad "count mismatch" 3 "$WORK"/s/e0[0-2].png -t 0.001,0.002
expect_stderr_has '3 images but 2'
head -c 300 "$WORK/s/e05.png" >"$WORK/trunc.png"
bad "truncated PNG" 3 "$WORK/s/e04.png" "$WORK/trunc.png" -t 0.001,0.002
expect_stderr_has 'trunc.png'
bad "float image as an exposure" 3 "$WORK/E.pfm" "$WORK/s/e01.png" -t 0.001,0.002
bad "response table with 10 rows" 3 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.001,0.002 --response <(head -11 "$WORK/true.csv")
bad "time is not a number" 2 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.001,abc
bad "zero time" 2 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0,0.001
bad "unknown flag" 2 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.001,0.002 --bogus
bad "unknown method" 2 "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.001,0.002 --method mertens
bad "missing file" 4 "$WORK/s/e00.png" "$WORK/nope.png" -t 0.001,0.002
case_ "radiance as PNG is refused"
run hdrmerge "$WORK/s/e00.png" "$WORK/s/e01.png" -t 0.001,0.002 -o "$WORK/bad.png"
expect_clean_failure 2 hdrmerge
check "no output file" test ! -e "$WORK/bad.png"

finish
