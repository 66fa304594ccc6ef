#!/usr/bin/env bash
# VTK datasets go through fest's VTK plugin (libfest_vtk_plugin.so, opened with dlopen on
# the first dataset): tools map VTK only for dataset inputs and outputs, and when the
# plugin or VTK is missing they say which Debian package to install and exit 4.
. "$(dirname "$0")/lib.sh"

# Five points, a tetrahedron and a triangle; a 64-bit point array whose value 2^60 + 1
# float64 cannot hold, so only a reader and writer that keep the type bring it back.
cat >"$WORK/two.vtk" <<'VTK'
# vtk DataFile Version 3.0
two cells
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 5 float
0 0 0 1 0 0 0 1 0 0 0 1 1 1 1
CELLS 2 9
4 0 1 2 3
3 1 2 4
CELL_TYPES 2
10
5
POINT_DATA 5
SCALARS id vtktypeint64 1
LOOKUP_TABLE default
0 1 2 1152921504606846977 -7
CELL_DATA 2
SCALARS c double 1
LOOKUP_TABLE default
0.5 -2.25
VTK

case_ "legacy .vtk -> .vtu -> legacy ASCII: counts, bounds, ranges and the int64 value kept"
run fconv "$WORK/two.vtk" -o "$WORK/two.vtu"
expect_status 0
run fconv --info "$WORK/two.vtu"
expect_status 0
expect_json '.dataset_type' '"vtkUnstructuredGrid"'
expect_json '[.points, .cells]' '[5,2]'
expect_json '.bbox' '{"max":[1,1,1],"min":[0,0,0]}'
expect_json '.cell_arrays[0].range' '[-2.25,0.5]'
run fconv --ascii "$WORK/two.vtu" -o "$WORK/back.vtk"
expect_status 0
check "2^60 + 1 survives" grep -q '1152921504606846977' "$WORK/back.vtk"
check "cells as written" grep -q '^CELL_TYPES 2' "$WORK/back.vtk"

case_ "a legacy file's own lookup table is carried to the legacy output"
printf '# vtk DataFile Version 3.0\nlut\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS s float 1\nLOOKUP_TABLE mine\n0 0.5 1\nLOOKUP_TABLE mine 2\n0 0.2 0.4 1\n1 1 1 1\n' >"$WORK/lut.vtk"
run fconv --ascii "$WORK/lut.vtk" -o "$WORK/lut_out.vtk"
expect_status 0
check "two table entries" grep -q '^LOOKUP_TABLE lookup_table 2' "$WORK/lut_out.vtk"
check "entry 0 (0.2 = 51/255, 0.4 = 102/255)" grep -q '^0 0.2 0.4 1$' "$WORK/lut_out.vtk"

case_ "fcompare: a dataset equals its own conversion"
run fcompare "$WORK/two.vtk" "$WORK/two.vtu"
expect_status 0

case_ "--version and a PLY conversion do not load VTK (glibc's LD_DEBUG lists what is opened)"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$WORK/t.ply"
LD_DEBUG=files "$FEST_BIN/fconv" --version >/dev/null 2>"$WORK/ld1"
check "no libvtk for --version" bash -c "! grep -q 'libvtk' '$WORK/ld1'"
LD_DEBUG=files "$FEST_BIN/fconv" "$WORK/t.ply" -o "$WORK/t.off" 2>"$WORK/ld2"
check "no libvtk for PLY -> OFF" bash -c "! grep -q 'libvtk' '$WORK/ld2'"
LD_DEBUG=files "$FEST_BIN/fconv" "$WORK/two.vtk" -o "$WORK/t2.vtu" 2>"$WORK/ld3"
check "libvtk for a dataset" grep -q 'libvtkIOLegacy' "$WORK/ld3"

case_ "no plugin in FEST_PLUGIN_DIR: exit 4, one line naming libvtk9.1"
mkdir -p "$WORK/empty"
FEST_PLUGIN_DIR="$WORK/empty" "$FEST_BIN/fconv" "$WORK/two.vtk" -o "$WORK/never.vtu" >"$out" 2>"$err"
rc=$?
expect_clean_failure 4 fconv
expect_stderr_has "install the Debian package libvtk9\.1"
check "nothing written" test ! -e "$WORK/never.vtu"

case_ "a plugin that cannot be loaded (as when libvtk is missing): exit 4 naming libvtk9.1"
mkdir -p "$WORK/broken"
echo "not a shared object" >"$WORK/broken/libfest_vtk_plugin.so"
FEST_PLUGIN_DIR="$WORK/broken" "$FEST_BIN/fconv" --info "$WORK/two.vtk" >"$out" 2>"$err"
rc=$?
expect_clean_failure 4 fconv
expect_stderr_has "libvtk9\.1"

case_ "the executable alone (no plugin beside it or in ../lib/fest): exit 4; other formats still work"
mkdir -p "$WORK/alone/bin"
cp "$FEST_BIN/fconv" "$WORK/alone/bin/"
"$WORK/alone/bin/fconv" "$WORK/two.vtk" -o "$WORK/never.vtu" >"$out" 2>"$err"
rc=$?
expect_clean_failure 4 fconv
expect_stderr_has "libfest_vtk_plugin\.so not found"
"$WORK/alone/bin/fconv" "$WORK/t.ply" -o "$WORK/t2.off" >"$out" 2>"$err"
rc=$?
expect_status 0

finish
