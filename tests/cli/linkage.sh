#!/usr/bin/env bash
# Start-up cost: no fest tool lists OpenCV's imgcodecs or videoio among its DT_NEEDED
# entries (imgcodecs alone maps ~140 shared libraries: GDAL, gdcm, poppler, ffmpeg...;
# videoio ~240: ffmpeg, GStreamer...; capture talks to V4L2 directly), and no tool lists
# GDAL, VTK, libtiff or OpenEXR. Issue 21 ("Batch speed: every tool starts in
# milliseconds") moved them into plugin modules opened with dlopen when an input needs
# them (formats/plugin_loader.hpp); a tool that gains a heavy link fails here.
source "$(dirname "$0")/lib.sh"
command -v readelf >/dev/null || { echo "readelf not installed (binutils): skipped"; exit 77; }

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
  case_ "$tool: no libopencv_videoio in DT_NEEDED"
  if grep -q '^libopencv_videoio' <<<"$needed"; then fail "$tool needs libopencv_videoio"; else pass; fi
  case_ "$tool: GDAL, VTK, libtiff and OpenEXR only through plugins"
  heavy=$(grep -E '^lib(gdal|vtk|tiff|OpenEXR)' <<<"$needed" | tr '\n' ' ')
  if [ -n "$heavy" ]; then fail "$tool needs $heavy (load it from a plugin module instead)"; else pass; fi
done
case_ "some tools were checked"
if [ "$checked" -gt 0 ]; then pass; else fail "no fest executables found in $FEST_BIN"; fi
finish
