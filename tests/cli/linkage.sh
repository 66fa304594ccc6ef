#!/usr/bin/env bash
# Start-up cost: no fest tool lists OpenCV's imgcodecs among its DT_NEEDED entries (it
# alone maps ~140 shared libraries: GDAL, gdcm, poppler, ffmpeg...), and no tool lists
# GDAL or VTK. Issue 21 ("Batch speed: every tool starts in milliseconds") moved GDAL and
# VTK into plugin libraries opened with dlopen when an input needs them
# (formats/dem/gdal_plugin.cpp, formats/dataset/vtk_plugin.cpp); a tool that gains a
# heavy link fails here.
source "$(dirname "$0")/lib.sh"
command -v readelf >/dev/null || { echo "readelf not installed (binutils): skipped"; exit 77; }

# Tools allowed to link GDAL or VTK directly: none.
KNOWN_HEAVY=" "

TOOLS_DIR="$(cd "$(dirname "$0")/../../tools" && pwd)"
checked=0
for dir in "$TOOLS_DIR"/*/; do
  tool=$(basename "$dir")
  exe="$FEST_BIN/$tool"
  [ -x "$exe" ] || continue  # not built in this tree
  checked=$((checked + 1))
  needed=$(readelf -d "$exe" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  case_ "$tool: no libopencv_imgcodecs in DT_NEEDED"
  if grep -q '^libopencv_imgcodecs' <<<"$needed"; then fail "$tool needs libopencv_imgcodecs"; else pass; fi
  case_ "$tool: GDAL/VTK only where known"
  heavy=$(grep -E '^lib(gdal|vtk)' <<<"$needed" | tr '\n' ' ')
  if [ -n "$heavy" ] && [[ "$KNOWN_HEAVY" != *" $tool "* ]]; then
    fail "$tool needs $heavy (load it from a plugin with dlopen instead)"
  elif [ -z "$heavy" ] && [[ "$KNOWN_HEAVY" == *" $tool "* ]]; then
    fail "$tool no longer needs GDAL or VTK: remove it from KNOWN_HEAVY"
  else
    pass
  fi
done
case_ "some tools were checked"
if [ "$checked" -gt 0 ]; then pass; else fail "no fest executables found in $FEST_BIN"; fi
finish
