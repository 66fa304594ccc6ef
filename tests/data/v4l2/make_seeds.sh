#!/usr/bin/env bash
# Seeds for tests/fuzz/fuzz_v4l2_frame: 4 bytes (format index, width-1, height-1, row
# padding + 2; see the target) then a buffer. Run once with a built fconv:
#   tests/data/v4l2/make_seeds.sh build/bin/fconv
set -euo pipefail
fconv="${1:?usage: make_seeds.sh FCONV}"
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A 16 x 16 colour gradient as PPM, then baseline JPEG at quality 90.
python3 - "$tmp/grad.ppm" <<'PY'
import sys
w = h = 16
px = bytes(v for y in range(h) for x in range(w) for v in (16 * x, 16 * y, 128))
open(sys.argv[1], "wb").write(b"P6 16 16 255\n" + px)
PY
"$fconv" "$tmp/grad.ppm" -o "$tmp/grad.jpg" --quality 90
{ printf '\001\017\017\002'; cat "$tmp/grad.jpg"; } > mjpeg_16x16.bin
# YUYV 4 x 2: black/white pair, red pair; blue pair, grey pair (BT.601 limited range).
printf '\000\003\001\002\020\200\353\200\121\132\121\360\051\360\051\156\176\200\176\200' > yuyv_4x2.bin
# Y16 2 x 2, little-endian.
printf '\004\001\001\002\064\022\377\377\000\000\001\000' > y16_2x2.bin
