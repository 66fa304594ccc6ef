#!/usr/bin/env bash
# Images fest writes (PNG, PGM/PPM, PAM, TIFF, JPEG, PFM, EXR), read by OpenImageIO, ImageMagick,
# GDAL and OpenEXR's exrheader. The reference is always the source file as the same
# independent program reads it, so fest's readers are not involved on either side.
. "$(dirname "$0")/../cli/lib.sh"
. "$(dirname "$0")/interop_lib.sh"

rgb="$FEST_FIXTURES/image/pattern_raw.ppm"
grey="$WORK/ramp.pgm"
printf 'P2\n4 3\n255\n0 64 128 255\n255 128 64 0\n1 2 3 4\n' >"$grey"
hdr="$FEST_FIXTURES/image/colour_little_endian.pfm"

have_oiio=0; reader oiiotool openimageio-tools && have_oiio=1
have_im=0; if [ -x /usr/bin/convert ] && /usr/bin/convert -version 2>/dev/null | grep -q ImageMagick; then have_im=1
           else echo "interop: skip: ImageMagick convert not installed (Debian package imagemagick)"; skipped_readers+=(convert); fi
have_gdal=0; reader gdalinfo gdal-bin && have_gdal=1
have_exr=0; reader exrheader openexr && have_exr=1

# same_pixels SRC OUT [FAIL]: OpenImageIO finds the same pixels (to FAIL, default exact).
same_pixels() {
  oiiotool "$1" "$2" --fail "${3:-0}" --diff >"$out" 2>"$err"; rc=$?
  expect_status 0
}

for src in "$rgb" "$grey"; do
  name=$(basename "$src"); name=${name%.*}
  for fmt in png ppm pam tiff; do
    [ "$src" = "$grey" ] && [ $fmt = ppm ] && fmt=pgm
    f="$WORK/$name.$fmt"
    "$FEST_BIN/fconv" "$src" -o "$f"
    case_ "fconv wrote $name.$fmt"
    check "written" test -s "$f"
    if [ $have_oiio = 1 ] && [ $fmt != pam ]; then
      case_ "OpenImageIO reads $name.$fmt with the source's pixels"
      same_pixels "$src" "$f"
    fi
    if [ $have_im = 1 ]; then
      case_ "ImageMagick reads $name.$fmt with the source's pixels"
      check "same samples" cmp -s <(/usr/bin/convert "$src" -depth 8 rgb:-) <(/usr/bin/convert "$f" -depth 8 rgb:-)
    fi
    if [ $have_gdal = 1 ] && [ $fmt = tiff ]; then
      case_ "GDAL reads $name.tiff"
      gdalinfo "$f" >"$out" 2>"$err"; rc=$?
      expect_status 0
      size=$(head -2 "$src" | tail -1); [ "$src" = "$rgb" ] && size=$(/usr/bin/identify -format '%w %h' "$src" 2>/dev/null || echo "$size")
      check "size" grep -q "^Size is ${size// /, }" "$out"
    fi
  done
done

# JPEG is lossy (and subsamples chroma 2x2, so a tiny image of saturated primaries is no
# test): a smooth 48x32 colour ramp must come back from ImageMagick at its size and
# within 30 dB PSNR of the source (fconv writes quality 95 by default).
if [ $have_im = 1 ]; then
  awk 'BEGIN { print "P3\n48 32\n255"; for (y = 0; y < 32; y++) for (x = 0; x < 48; x++)
               print int(255 * x / 47), int(255 * y / 31), int(128 + 60 * sin(x / 7.0)) }' >"$WORK/ramp.ppm"
  "$FEST_BIN/fconv" "$WORK/ramp.ppm" -o "$WORK/ramp.jpg"
  case_ "ImageMagick reads fconv's JPEG"
  check "same size" test "$(/usr/bin/identify -format '%w %h' "$WORK/ramp.jpg")" = "48 32"
  psnr=$(/usr/bin/compare -metric PSNR "$WORK/ramp.ppm" "$WORK/ramp.jpg" null: 2>&1 | awk '{print $1}')
  check "PSNR $psnr >= 30 dB" awk -v p="$psnr" 'BEGIN { exit !(p == "inf" || p + 0 >= 30) }'
fi

case_ "float images: PFM and EXR"
"$FEST_BIN/fconv" "$hdr" -o "$WORK/hdr.exr"
"$FEST_BIN/fconv" "$hdr" -o "$WORK/hdr.pfm"
if [ $have_exr = 1 ]; then
  case_ "exrheader reads fconv's EXR"
  exrheader "$WORK/hdr.exr" >"$out" 2>"$err"; rc=$?
  expect_status 0
  check "2x2 data window" grep -q "dataWindow.*(0 0) - (1 1)" "$out"
fi
if [ $have_oiio = 1 ]; then
  case_ "OpenImageIO reads fconv's EXR and PFM with the source's values"
  same_pixels "$hdr" "$WORK/hdr.exr"
  same_pixels "$hdr" "$WORK/hdr.pfm"
fi

finish_interop
