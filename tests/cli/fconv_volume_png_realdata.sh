#!/usr/bin/env bash
# The volume quick look (fconv VOLUME --to png, segbrain slices) on the real heads fetched
# by scripts/fetch-test-data.sh: the T1 MRI head (NIfTI with an sform) and InVesalius'
# Cranium CT (a NRRD with spacings only, no orientation).
. "$(dirname "$0")/lib.sh"
head=$(need_testdata mri/t1_head.nii.gz) || exit 77
ct=$(need_testdata volumes/cranium.nrrd) || exit 77

case_ "T1 head, ortho: panel sizes and letters from the file's geometry (fconv --info)"
"$FEST_BIN/fconv" --info "$head" >"$WORK/info.json"
run fconv "$head" --to png -v -o "$WORK/ortho.png"
expect_status 0
cp "$err" "$WORK/ortho.log"
# Expected: each world axis (R, A, S) is shown along the voxel axis whose direction is
# closest to it; a panel is (extent of its horizontal axis) x (extent of its vertical
# axis) in mm, extent = voxels x spacing.
check "panel sizes and letters match the geometry" python3 - "$WORK/info.json" "$WORK/ortho.log" <<'PY'
import json, re, sys
info = json.load(open(sys.argv[1])); log = open(sys.argv[2]).read()
d, n, s = info['direction'], info['dimensions'], info['spacing']
extent = []
for world in range(3):
    col = max(range(3), key=lambda c: abs(d[3 * world + c]))
    extent.append(n[col] * s[col])
mm = float(re.search(r"panels, ([0-9.e+-]+) mm per pixel", log).group(1))
want = {'AXIAL': (0, 1, 'L', 'R', 'A', 'P'), 'CORONAL': (0, 2, 'L', 'R', 'S', 'I'), 'SAGITTAL': (1, 2, 'P', 'A', 'S', 'I')}
ok = 0
for m in re.finditer(r"panel '(\w+)[^']*' at \d+,\d+ size (\d+)x(\d+) left '(\w*)' right '(\w*)' top '(\w*)' bottom '(\w*)'", log):
    h, v, *letters = want[m.group(1)]
    assert abs(int(m.group(2)) * mm - extent[h]) <= mm, m.group(0)
    assert abs(int(m.group(3)) * mm - extent[v]) <= mm, m.group(0)
    assert list(m.groups()[3:]) == letters, m.group(0)
    ok += 1
sys.exit(ok != 3)
PY
check "scale bar plausible for a head (20 to 100 mm)" grep -Eq "scale bar (20|50|100) mm" "$WORK/ortho.log"
check "neurological by default" grep -q "neurological" "$WORK/ortho.log"
check "PNG 3 channels" test "$("$FEST_BIN/fconv" --info "$WORK/ortho.png" | jq .channels)" = 3

case_ "T1 head: montage of 12 axial slices and MIPs"
run fconv "$head" --to png --view montage -v -o "$WORK/montage.png"
expect_status 0
check "12 panels" grep -q ": 12 panels" "$err"
run fconv "$head" --to png --view mip -v -o "$WORK/mip.png"
expect_status 0
check "3 projections" grep -q "panel 'MIP SAGITTAL'" "$err"

case_ "Cranium CT: a NRRD without space directions says 'orientation unknown'"
run fconv "$ct" --to png -v -o "$WORK/ct.png"
expect_status 0
expect_stderr_has "orientation unknown"
check "no letters" grep -q "left '' right '' top '' bottom ''" "$err"

case_ "segbrain slices of the T1 head without --labels"
run segbrain slices "$head" -o "$WORK/slices.png"
expect_status 0
check "PNG written" test -s "$WORK/slices.png"

finish
