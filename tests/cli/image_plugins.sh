#!/usr/bin/env bash
# TIFF and OpenEXR are plugin modules (formats/image/codec_plugins.hpp): a PNG or PPM
# needs neither, a TIFF or EXR without its module is one line naming the Debian package
# and exit 4, and with the modules the pixels survive the trip through them.
source "$(dirname "$0")/lib.sh"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
NONE="$WORK/no-plugins"
mkdir -p "$NONE"

# A 2x2 RGB PPM whose samples are known by construction.
printf 'P6\n2 2\n255\n' >"$WORK/in.ppm"
printf '\000\001\002\100\101\102\200\201\202\375\376\377' >>"$WORK/in.ppm"

case_ "PPM -> PNG needs no plugin"
FEST_PLUGIN_DIR="$NONE" run fconv "$WORK/in.ppm" -o "$WORK/a.png"
expect_status 0

case_ "PPM -> TIFF -> PPM through the TIFF module: the same 12 samples"
run fconv "$WORK/in.ppm" -o "$WORK/a.tiff"
expect_status 0
run fconv "$WORK/a.tiff" -o "$WORK/back.ppm"
expect_status 0
if cmp -s "$WORK/in.ppm" "$WORK/back.ppm"; then pass; else fail "TIFF round trip changed the samples"; fi

case_ "float PFM -> EXR -> PFM through the EXR module: the same bytes"
printf 'Pf\n2 1\n-1\n' >"$WORK/in.pfm"  # fest writes the scale as -1
printf '\000\000\200\077\000\000\000\300' >>"$WORK/in.pfm"   # 1.0, -2.0 (little-endian)
run fconv "$WORK/in.pfm" -o "$WORK/a.exr"
expect_status 0
run fconv "$WORK/a.exr" -o "$WORK/back.pfm"
expect_status 0
if cmp -s "$WORK/in.pfm" "$WORK/back.pfm"; then pass; else fail "EXR round trip changed the samples"; fi

case_ "reading a TIFF without the module: exit 4 naming libtiff6, nothing written"
FEST_PLUGIN_DIR="$NONE" run fconv "$WORK/a.tiff" -o "$WORK/none.png"
expect_clean_failure 4 fconv
expect_stderr_has "libtiff6"
[ ! -e "$WORK/none.png" ] && pass || fail "an output was written"

case_ "writing an EXR without the module: exit 4 naming libopenexr"
FEST_PLUGIN_DIR="$NONE" run fconv "$WORK/in.pfm" -o "$WORK/none.exr"
expect_clean_failure 4 fconv
expect_stderr_has "libopenexr"
[ ! -e "$WORK/none.exr" ] && pass || fail "an output was written"

case_ "a module that is not a shared object: exit 4, one line"
printf 'not an ELF file' >"$NONE/libfest_tiff_plugin.so"
FEST_PLUGIN_DIR="$NONE" run fconv "$WORK/a.tiff" -o "$WORK/none.png"
expect_clean_failure 4 fconv
expect_stderr_has "TIFF support is not available"

case_ "fconv --version maps neither libtiff nor OpenEXR"
if command -v ldd >/dev/null; then
  if LD_DEBUG=libs "$FEST_BIN/fconv" --version 2>&1 >/dev/null | grep -qE 'libtiff|OpenEXR'; then
    fail "fconv --version loads libtiff or OpenEXR"
  else pass; fi
else pass; fi

finish
