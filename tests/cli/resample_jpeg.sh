#!/usr/bin/env bash
# JPEG output of resample and fconv, and resize by --width or --height alone (issue 30):
# the round trip of a smooth image against a PSNR bound from the quantisation tables,
# fest's decoder against libjpeg-turbo's djpeg byte for byte, cjpeg's files read, the
# side that --width/--height leave out from the aspect ratio, and what is refused.
. "$(dirname "$0")/lib.sh"

R="$FEST_BIN/resample"
F="$FEST_BIN/fconv"

# size FILE: "W H" of an image, from fconv --info.
size() { "$F" --info "$1" | jq -r '"\(.width) \(.height)"'; }
# pixels FILE W H: the last W*H*3 bytes (the samples of a P6 file).
pixels() { tail -c $(( $2 * $3 * 3 )) "$1"; }

# A smooth 256x192 RGB gradient, as plain PPM: R = x, G = round(255 y / 191),
# B = floor((x + y) / 1.75). The PSNR below recomputes it from the same formula.
W=256 H=192
awk -v w=$W -v h=$H 'BEGIN { printf "P3\n%d %d\n255\n", w, h
  for (y = 0; y < h; y++) for (x = 0; x < w; x++)
    printf "%d %d %d\n", x, int(255 * y / (h - 1) + 0.5), int((x + y) / 1.75) }' >"$WORK/grad.ppm"

# psnr P6FILE: PSNR in dB of a decoded P6 of the gradient against the formula.
psnr() {
  pixels "$1" $W $H | od -An -v -tu1 | tr -s ' ' '\n' | grep -v '^$' |
    awk -v w=$W -v h=$H '{ i = NR - 1; p = int(i / 3); c = i % 3; x = p % w; y = int(p / w)
      want = c == 0 ? x : c == 1 ? int(255 * y / (h - 1) + 0.5) : int((x + y) / 1.75)
      d = $1 - want; se += d * d } END { printf "%.2f\n", 10 * log(255 * 255 / (se / NR)) / log(10) }'
}

have_djpeg=0
command -v djpeg >/dev/null && command -v cjpeg >/dev/null && have_djpeg=1

# --- the round trip ------------------------------------------------------------------
# At quality q libjpeg scales the Annex K tables by s = (200 - 2q) % (q >= 50). A smooth
# gradient puts its energy in the DC and first AC coefficients, whose table entries are
# <= 24 (chroma 17-24, luma 10-16): at q 90 (s = 20 %) their steps are <= 5, an error of
# RMS <= 5 / sqrt(12) = 1.44 per coefficient, with the YCbCr -> RGB rounding (RMS 0.29)
# and 4:2:0 chroma on a linear ramp adding well under 1: RMS < 2.55, PSNR > 40 dB. At q 50
# (s = 100 %) the steps are <= 24: RMS < 7, PSNR > 31 dB.
case_ "fconv: the gradient through JPEG at quality 90 and 50, decoded by djpeg"
run fconv "$WORK/grad.ppm" -o "$WORK/q90.jpg" --quality 90
expect_status 0
run fconv "$WORK/grad.ppm" --to jpg --quality 50 -o "$WORK/q50.jpg"
expect_status 0
check "q90 is JPEG (SOI marker)" test "$(head -c 3 "$WORK/q90.jpg" | od -An -tx1 | tr -d ' ')" = ffd8ff
check "q50 is smaller than q90" test "$(wc -c <"$WORK/q50.jpg")" -lt "$(wc -c <"$WORK/q90.jpg")"
if [ $have_djpeg = 1 ]; then
  djpeg -pnm "$WORK/q90.jpg" >"$WORK/q90.dj.ppm" 2>"$err"; rc=$?
  expect_status 0
  check "djpeg reads it as a 256x192 P6 with nothing on stderr" sh -c "head -c 15 '$WORK/q90.dj.ppm' | grep -q '^P6' && test ! -s '$err'"
  djpeg -pnm "$WORK/q50.jpg" >"$WORK/q50.dj.ppm"
  p90=$(psnr "$WORK/q90.dj.ppm") p50=$(psnr "$WORK/q50.dj.ppm")
  echo "gradient round trip: PSNR q90 $p90 dB, q50 $p50 dB (djpeg decode)"
  check "q90 PSNR $p90 > 40 dB" awk -v p="$p90" 'BEGIN { exit !(p > 40) }'
  check "q50 PSNR $p50 > 31 dB" awk -v p="$p50" 'BEGIN { exit !(p > 31) }'
  check "q90 beats q50" awk -v a="$p90" -v b="$p50" 'BEGIN { exit !(a > b) }'

  case_ "fest's decoder gives djpeg's pixels exactly (ISLOW DCT, fancy upsampling)"
  "$F" "$WORK/q90.jpg" --to ppm -o "$WORK/q90.fest.ppm"
  check "fest == djpeg on fest's file" cmp -s <(pixels "$WORK/q90.fest.ppm" $W $H) <(pixels "$WORK/q90.dj.ppm" $W $H)
  for opts in "-quality 75" "-quality 85 -progressive" "-quality 60 -sample 1x1" "-quality 80 -optimize -restart 2"; do
    # shellcheck disable=SC2086
    cjpeg $opts "$WORK/grad.ppm" >"$WORK/c.jpg"
    djpeg -pnm "$WORK/c.jpg" >"$WORK/c.dj.ppm"
    run fconv "$WORK/c.jpg" --to ppm -o "$WORK/c.fest.ppm"
    expect_status 0
    check "cjpeg $opts: fest == djpeg" cmp -s <(pixels "$WORK/c.fest.ppm" $W $H) <(pixels "$WORK/c.dj.ppm" $W $H)
  done
  cjpeg -grayscale -quality 90 "$WORK/grad.ppm" >"$WORK/g.jpg"
  djpeg -pnm "$WORK/g.jpg" >"$WORK/g.dj.pgm"
  run fconv "$WORK/g.jpg" --to pgm -o "$WORK/g.fest.pgm"
  expect_status 0
  check "cjpeg -grayscale: one channel" test "$("$F" --info "$WORK/g.jpg" | jq .channels)" = 1
  check "cjpeg -grayscale: fest == djpeg" cmp -s <(tail -c $((W * H)) "$WORK/g.fest.pgm") <(tail -c $((W * H)) "$WORK/g.dj.pgm")
else
  echo "djpeg/cjpeg not installed (libjpeg-turbo-progs): independent decoder checks skipped"
fi

# --- resample writes JPEG -----------------------------------------------------------
case_ "the issue's command: resample resize x.jpg --width 128 -o y.jpg"
run resample resize "$WORK/q90.jpg" --width 128 -o "$WORK/small.jpg"
expect_status 0
check "128x96 (192 * 128 / 256)" test "$(size "$WORK/small.jpg")" = "128 96"
check "written as JPEG" test "$(head -c 3 "$WORK/small.jpg" | od -An -tx1 | tr -d ' ')" = ffd8ff
run resample resize "$WORK/q90.jpg" --height 48 -o "$WORK/small.jpeg"
expect_status 0
check ".jpeg is JPEG too, 64x48" test "$(head -c 3 "$WORK/small.jpeg" | od -An -tx1 | tr -d ' ') $(size "$WORK/small.jpeg")" = "ffd8ff 64 48"
run resample resize "$WORK/q90.jpg" --width 128 -o "$WORK/small.png"
if [ $have_djpeg = 1 ]; then
  # The JPEG of the resized image against the same resize written losslessly: the PSNR
  # bound of quality 95 (steps <= 2.4: RMS < 1.3 with the rounding, > 45 dB; ask 40).
  djpeg -pnm "$WORK/small.jpg" >"$WORK/small.dj.ppm"
  "$F" "$WORK/small.png" --to ppm -o "$WORK/small.ppm"
  check "resized JPEG (djpeg) vs the lossless resize: fcompare psnr >= 40" \
    "$FEST_BIN/fcompare" -q -t 'psnr>=40' --report "$WORK/small.json" "$WORK/small.dj.ppm" "$WORK/small.ppm"
  echo "resized 128x96 at quality 95 vs lossless: PSNR $(jq '[.. | .psnr? // empty][0]' "$WORK/small.json") dB"
fi
run resample resize "$WORK/grad.ppm" --width 128 --to jpg --quality 30
expect_status 0
check "--to jpg on standard output" test "$(head -c 3 "$out" | od -An -tx1 | tr -d ' ')" = ffd8ff
low=$(wc -c <"$out")
run resample resize "$WORK/grad.ppm" --width 128 --to jpg
check "--quality 30 ($low bytes) is smaller than the default 95 ($(wc -c <"$out"))" test "$low" -lt "$(wc -c <"$out")"

case_ "16-bit and float images become 8-bit JPEG by default; --depth 16 is refused"
printf 'P5\n4 2\n65535\n' >"$WORK/deep.pgm"
printf '\000\000\100\000\200\000\377\377\377\377\200\000\100\000\000\000' >>"$WORK/deep.pgm"
run resample resize "$WORK/deep.pgm" --width 8 -o "$WORK/deep.jpg"
expect_status 0
check "8x4 grey JPEG" test "$("$F" --info "$WORK/deep.jpg" | jq -c '[.width,.height,.channels]')" = "[8,4,1]"
run resample resize "$WORK/deep.pgm" --width 8 --depth 16 -o "$WORK/deep16.jpg"
expect_clean_failure 2 resample
expect_stderr_has "JPEG holds 8-bit samples"
check "no output" test ! -e "$WORK/deep16.jpg"
run fconv "$WORK/deep.pgm" -o "$WORK/deep_f.jpg"
expect_clean_failure 3 fconv
expect_stderr_has "16-bit .*JPEG holds 8-bit"

# --- --width / --height alone ----------------------------------------------------------
# The other side is round(H * W' / W) (or round(W * H' / H)), halves away from zero, at
# least 1: 101x37 --width 50 -> 18.32 -> 18; --height 17 -> 46.41 -> 46; --width 7 ->
# 2.56 -> 3; 10x5 --width 3 -> 1.5 -> 2; --width 1 -> 0.37 -> 1.
case_ "--width or --height alone keeps the aspect ratio, for PPM, PNG and JPEG input"
awk 'BEGIN { printf "P3\n101 37\n255\n"; for (i = 0; i < 101 * 37; i++) printf "%d %d %d\n", i % 256, 50, 200 }' >"$WORK/odd.ppm"
"$F" "$WORK/odd.ppm" --to ppm -o "$WORK/odd_raw.ppm"   # raw P6: resample streams it
"$F" "$WORK/odd.ppm" -o "$WORK/odd.png"
"$F" "$WORK/odd.ppm" -o "$WORK/odd.jpg"
for in in odd.ppm odd_raw.ppm odd.png odd.jpg; do
  for spec in "--width 50:50 18" "--height 17:46 17" "--width 7:7 3" "--width 1:1 1" "--width 202:202 74"; do
    # shellcheck disable=SC2086
    run resample resize "$WORK/$in" ${spec%%:*} -o "$WORK/r.png"
    expect_status 0
    check "$in ${spec%%:*} -> ${spec#*:}" test "$(size "$WORK/r.png")" = "${spec#*:}"
  done
done
awk 'BEGIN { printf "P2\n10 5\n255\n"; for (i = 0; i < 50; i++) printf "%d\n", i }' >"$WORK/ten.pgm"
run resample resize "$WORK/ten.pgm" --width 3 -o "$WORK/r.jpg"
check "10x5 --width 3 -> 3x2 (1.5 rounds up)" test "$(size "$WORK/r.jpg")" = "3 2"
run resample resize "$WORK/ten.pgm" --width 3 --height 3 -o "$WORK/r.png"
check "both given: exactly 3x3" test "$(size "$WORK/r.png")" = "3 3"

# --- real photographs (scripts/fetch-test-data.sh: matplotlib's grace_hopper.jpg, opencv-doc's
# aloeL.jpg); skipped when not fetched -------------------------------------------------
case_ "real JPEG photographs: the issue's command, and fest's decode equals djpeg's"
for rel in faces/grace_hopper.jpg images/aloeL.jpg; do
  photo=$(need_testdata "$rel") || { echo "$rel not fetched: skipped"; continue; }
  read -r pw ph < <(size "$photo")
  want_h=$(awk -v w="$pw" -v h="$ph" 'BEGIN { printf "%d", int(h * 256 / w + 0.5) }')
  run resample resize "$photo" --width 256 -o "$WORK/photo_small.jpg"
  expect_status 0
  check "$rel ${pw}x$ph --width 256 -> 256x$want_h" test "$(size "$WORK/photo_small.jpg")" = "256 $want_h"
  if [ $have_djpeg = 1 ]; then
    check "$rel: djpeg reads fest's output" sh -c "djpeg -pnm '$WORK/photo_small.jpg' | head -c 2 | grep -q P6"
    djpeg -pnm "$photo" >"$WORK/photo.dj.ppm"
    "$F" "$photo" --to ppm -o "$WORK/photo.fest.ppm"
    check "$rel: fest == djpeg" cmp -s <(pixels "$WORK/photo.fest.ppm" "$pw" "$ph") <(pixels "$WORK/photo.dj.ppm" "$pw" "$ph")
  fi
done

# --- refusals ---------------------------------------------------------------------------
case_ "a bad --quality is a usage error"
for q in 0 101 -5 high; do
  run resample resize "$WORK/grad.ppm" --width 8 --quality "$q" -o "$WORK/bad.jpg"
  expect_clean_failure 2 resample
  expect_stderr_has "quality"
  check "no output for --quality $q" test ! -e "$WORK/bad.jpg"
done
run fconv "$WORK/grad.ppm" --quality 0 -o "$WORK/bad.jpg"
expect_clean_failure 2 fconv

case_ "alpha into JPEG: refused with the count unless it is opaque everywhere"
# A 2x2 RGBA PAM, one pixel half transparent.
{ printf 'P7\nWIDTH 2\nHEIGHT 2\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n'
  printf '\377\000\000\377\000\377\000\377\000\000\377\200\377\377\377\377'; } >"$WORK/rgba.pam"
"$F" "$WORK/rgba.pam" -o "$WORK/rgba.png"
run fconv "$WORK/rgba.png" -o "$WORK/rgba.jpg"
expect_clean_failure 3 fconv
expect_stderr_has "alpha channel.* 1 of 4 pixels are not opaque"
check "no output" test ! -e "$WORK/rgba.jpg"
run resample resize "$WORK/rgba.png" --width 4 -o "$WORK/rgba.jpg"
expect_clean_failure 3 resample
expect_stderr_has "alpha channel"
check "no output" test ! -e "$WORK/rgba.jpg"
run fconv "$WORK/rgba.png" -o "$WORK/rgba.ppm"
expect_clean_failure 3 fconv
expect_stderr_has "1 of 4 pixels are not opaque"
# The same with alpha 255 everywhere: nothing to lose, written as RGB.
{ printf 'P7\nWIDTH 2\nHEIGHT 2\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n'
  printf '\377\000\000\377\000\377\000\377\000\000\377\377\377\377\377\377'; } >"$WORK/opaque.pam"
run fconv "$WORK/opaque.pam" -o "$WORK/opaque.jpg" --quality 100
expect_status 0
check "3 channels" test "$("$F" --info "$WORK/opaque.jpg" | jq .channels)" = 3
run fconv "$WORK/opaque.pam" -o "$WORK/opaque.ppm"
expect_status 0
check "opaque RGBA -> PPM keeps the colours" test "$(tail -c 12 "$WORK/opaque.ppm" | od -An -v -tu1 | tr -s ' ')" = " 255 0 0 0 255 0 0 0 255 255 255 255"

# --flatten: C' = a C + (1 - a) B in linear light, sRGB-encoded and rounded. The half
# transparent blue pixel (a = 128/255) over white: R = G = srgb(1 - a), B = 255; over
# black (--background 0,0,0): R = G = 0, B = srgb(a).
case_ "--flatten and --background composite alpha in linear light"
srgb() { awk -v l="$1" 'BEGIN { v = l <= 0.0031308 ? 12.92 * l : 1.055 * exp(log(l) / 2.4) - 0.055; printf "%d", int(v * 255 + 0.5) }'; }
a=$(awk 'BEGIN { print 128 / 255 }')
half_white=$(srgb "$(awk -v a="$a" 'BEGIN { print 1 - a }')") half_black=$(srgb "$a")
echo "flatten: over white ($half_white $half_white 255), over black (0 0 $half_black)"
run fconv "$WORK/rgba.png" --flatten -o "$WORK/flat_w.ppm"
expect_status 0
check "over white" test "$(tail -c 12 "$WORK/flat_w.ppm" | od -An -v -tu1 | tr -s ' ')" = " 255 0 0 0 255 0 $half_white $half_white 255 255 255 255"
run fconv "$WORK/rgba.png" --background 0,0,0 -o "$WORK/flat_b.ppm"
expect_status 0
check "over black" test "$(tail -c 12 "$WORK/flat_b.ppm" | od -An -v -tu1 | tr -s ' ')" = " 255 0 0 0 255 0 0 0 $half_black 255 255 255"
run fconv "$WORK/rgba.png" --flatten -o "$WORK/flat.jpg"
expect_status 0
check "JPEG of 3 channels" test "$("$F" --info "$WORK/flat.jpg" | jq .channels)" = 3
run resample resize "$WORK/rgba.png" --width 4 --flatten -o "$WORK/flat4.jpg"
expect_status 0
check "resample --flatten: 4x4 JPEG" test "$(size "$WORK/flat4.jpg")" = "4 4"
for bad in 0,0 1,2,256 a,b,c; do
  run fconv "$WORK/rgba.png" --background "$bad" -o "$WORK/bad.jpg"
  expect_clean_failure 2 fconv
  expect_stderr_has "--background"
done

case_ "CMYK and truncated JPEG: one line, exit 3, no output"
# cjpeg writes no CMYK: a hand-made frame header of 4 components (SOF0, 16x16).
printf '\377\330\377\300\000\024\010\000\020\000\020\004\001\021\000\002\021\000\003\021\000\004\021\000\377\331' >"$WORK/cmyk.jpg"
run fconv "$WORK/cmyk.jpg" -o "$WORK/cmyk.png"
expect_clean_failure 3 fconv
expect_stderr_has "CMYK"
check "no output" test ! -e "$WORK/cmyk.png"
head -c $(( $(wc -c <"$WORK/q90.jpg") / 2 )) "$WORK/q90.jpg" >"$WORK/cut.jpg"
run resample resize "$WORK/cut.jpg" --width 64 -o "$WORK/cut_out.jpg"
expect_clean_failure 3 resample
expect_stderr_has "JPEG"
check "no output" test ! -e "$WORK/cut_out.jpg"

finish
