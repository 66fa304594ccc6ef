#!/usr/bin/env bash
# fconv VOLUME --to png (the quick look, docs/fconv.md "Volume quick look") and
# segbrain slices without --labels. Synthetic NRRD volumes with a bright block at the
# patient's left, anterior, superior side: each panel must show the block on the sides
# its letters name, wherever the voxel axes point; the expected sides and sizes come from
# the geometry written into the files, the pixels from the PNG read back by fconv itself.
. "$(dirname "$0")/lib.sh"

# make_nrrd OUT NX,NY,NZ SPACE_DIRECTIONS|none: int16 volume, background 100, and 1000
# in the voxels whose world position is in the left, anterior, superior fifth of the box
# (NRRD space LPS: left = +x, anterior = -y, superior = +z). Prints the marker's voxel
# centroid as I,J,K.
make_nrrd() {
  python3 - "$@" <<'PY'
import struct, sys
out, dims, dirs = sys.argv[1], [int(x) for x in sys.argv[2].split(',')], sys.argv[3]
if dirs == 'none':
    cols = [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
else:
    cols = [tuple(float(x) for x in c.strip('()').split(',')) for c in dirs.split()]
def world(i, j, k):
    return [i * cols[0][r] + j * cols[1][r] + k * cols[2][r] for r in range(3)]
corners = [world(i, j, k) for i in (0, dims[0] - 1) for j in (0, dims[1] - 1) for k in (0, dims[2] - 1)]
lo = [min(c[r] for c in corners) for r in range(3)]
hi = [max(c[r] for c in corners) for r in range(3)]
data, sel = bytearray(), []
for k in range(dims[2]):
    for j in range(dims[1]):
        for i in range(dims[0]):
            p = world(i, j, k)
            f = [(p[r] - lo[r]) / (hi[r] - lo[r]) for r in range(3)]
            inside = f[0] > 0.7 and f[1] < 0.3 and f[2] > 0.7  # LPS: left, anterior, superior
            data += struct.pack('<h', 1000 if inside else 100)
            if inside: sel.append((i, j, k))
head = 'NRRD0004\ntype: int16\ndimension: 3\nsizes: %d %d %d\n' % tuple(dims)
if dirs == 'none':
    head += 'spacings: 1 1 1\n'
else:
    head += 'space: left-posterior-superior\nspace directions: %s\n' % dirs
head += 'encoding: raw\nendian: little\n\n'
open(out, 'wb').write(head.encode() + bytes(data))
print(','.join(str(round(sum(s[a] for s in sel) / len(sel))) for a in range(3)))
PY
}

# check_sides PNG STDERR: for every panel named on standard error by -v, the pixels of
# value 255 (the block, windowed 0..1000) lie on the sides whose letters are L, A or S.
cat >"$WORK/sides.py" <<'PY'
import re, sys
ppm, log = sys.argv[1], sys.argv[2]
tok = open(ppm).read().split()
assert tok[0] == 'P3'
w, h = int(tok[1]), int(tok[2])
px = [int(t) for t in tok[4:]]
def white(x, y):
    i = 3 * (y * w + x)
    return px[i] == 255 and px[i + 1] == 255 and px[i + 2] == 255
bad, panels = [], 0
for m in re.finditer(r"panel '([^']*)' at (\d+),(\d+) size (\d+)x(\d+) left '(\w*)' right '(\w*)' top '(\w*)' bottom '(\w*)'", open(log).read()):
    title, x0, y0, pw, ph = m.group(1), *map(int, m.groups()[1:5])
    left, right, top, bottom = m.groups()[5:]
    pts = [(x, y) for y in range(y0, y0 + ph) for x in range(x0, x0 + pw) if white(x, y)]
    panels += 1
    if not pts:
        bad.append('%s: block not seen' % title); continue
    cx = sum(p[0] for p in pts) / len(pts) - x0
    cy = sum(p[1] for p in pts) / len(pts) - y0
    want = set('LAS')
    if (left in want) == (right in want): bad.append('%s: letters %s/%s' % (title, left, right))
    if (top in want) == (bottom in want): bad.append('%s: letters %s/%s' % (title, top, bottom))
    if (left in want) != (cx < pw / 2): bad.append('%s: block at x %.0f of %d, letters %s|%s' % (title, cx, pw, left, right))
    if (top in want) != (cy < ph / 2): bad.append('%s: block at y %.0f of %d, letters %s/%s' % (title, cy, ph, top, bottom))
print('\n'.join(bad) if bad else 'ok %d panels' % panels)
sys.exit(1 if bad or panels == 0 else 0)
PY
check_sides() {
  "$FEST_BIN/fconv" "$1" --to ppm --ascii -o "$WORK/sides.ppm" && python3 "$WORK/sides.py" "$WORK/sides.ppm" "$2"
}

for conv in neurological radiological; do
  for geometry in "40,30,20|(1,0,0) (0,1,0) (0,0,1)" "24,36,30|(0,0,-1.5) (-1,0,0) (0,2,0)"; do
    case_ "block at L/A/S: $conv, space directions $geometry"
    at=$(make_nrrd "$WORK/block.nrrd" "${geometry%%|*}" "${geometry#*|}")
    for view in "ortho --slice $at" mip; do
      # shellcheck disable=SC2086
      run fconv "$WORK/block.nrrd" --to png --window 0,1000 --convention $conv --view $view -v -o "$WORK/block.png"
      expect_status 0
      cp "$err" "$WORK/block.log"
      check "$view: the block lies where the letters say (see $WORK/block.log)" check_sides "$WORK/block.png" "$WORK/block.log"
      if [ "$conv" = neurological ]; then
        check "$view: neurological: patient's left on the image's left" grep -q "left 'L' right 'R' top 'A'" "$WORK/block.log"
      else
        check "$view: radiological: patient's right on the image's left" grep -q "left 'R' right 'L' top 'A'" "$WORK/block.log"
      fi
    done
  done
done

case_ "the same volume through NIfTI, MHA and MGH keeps the letters"
make_nrrd "$WORK/block.nrrd" 24,36,30 "(0,0,-1.5) (-1,0,0) (0,2,0)" >/dev/null
for to in nii mha mgh; do
  "$FEST_BIN/fconv" "$WORK/block.nrrd" -o "$WORK/block.$to"
  run fconv "$WORK/block.$to" --to png --window 0,1000 --view mip -v -o "$WORK/block.png"
  expect_status 0
  cp "$err" "$WORK/block.log"
  check "$to: block where the letters say" check_sides "$WORK/block.png" "$WORK/block.log"
done

case_ "anisotropic voxels keep their physical aspect"
# 40 x 40 x 20 voxels of 1 x 1 x 3 mm: the coronal panel is 40 mm wide and 60 mm high.
python3 -c "
import sys
sys.stdout.buffer.write(b'NRRD0004\ntype: uint8\ndimension: 3\nsizes: 40 40 20\nspace: RAS\nspace directions: (1,0,0) (0,1,0) (0,0,3)\nencoding: raw\n\n' + bytes([100]) * 32000)" >"$WORK/aniso.nrrd"
run fconv "$WORK/aniso.nrrd" --to png -v -o "$WORK/aniso.png"
expect_status 0
size=$(sed -n "s/.*panel 'CORONAL[^']*' at [0-9]*,[0-9]* size \([0-9]*x[0-9]*\).*/\1/p" "$err")
w=${size%x*} h=${size#*x}
check "coronal panel ${size}: height/width = 60/40" python3 -c "import sys; sys.exit(abs($h / $w - 1.5) > 2 / $w)"
check "axial panel is square" grep -Eq "panel 'AXIAL[^']*' at [0-9]+,[0-9]+ size ([0-9]+)x\1 " "$err"
# The pixels: the white (constant volume, window 0..100) rows and columns of the coronal panel.
"$FEST_BIN/fconv" "$WORK/aniso.png" --to ppm --ascii -o "$WORK/aniso.ppm"
check "white area of the coronal panel is 40 x 60 mm" python3 - "$WORK/aniso.ppm" "$err" <<'PY'
import re, sys
tok = open(sys.argv[1]).read().split(); w = int(tok[1]); px = tok[4:]
m = re.search(r"panel 'CORONAL[^']*' at (\d+),(\d+) size (\d+)x(\d+)", open(sys.argv[2]).read())
x0, y0, pw, ph = map(int, m.groups())
mm = float(re.search(r"panels, ([0-9.e+-]+) mm per pixel", open(sys.argv[2]).read()).group(1))
xs, ys = set(), set()
for y in range(y0 - 2, y0 + ph + 2):
    for x in range(x0 - 2, x0 + pw + 2):
        if px[3 * (y * w + x)] == '255' and px[3 * (y * w + x) + 2] == '255': xs.add(x); ys.add(y)
sys.exit(not (abs(len(xs) * mm - 40) <= mm and abs(len(ys) * mm - 60) <= mm))
PY

case_ "a file without orientation: 'orientation unknown', no letters"
make_nrrd "$WORK/plain.nrrd" 20,20,20 none >/dev/null
run fconv "$WORK/plain.nrrd" --to png -v -o "$WORK/plain.png"
expect_status 0
expect_stderr_has "orientation unknown"
check "no letters" grep -q "left '' right '' top '' bottom ''" "$err"
check "PNG written" test -s "$WORK/plain.png"

case_ "VTK image data (no anatomical orientation): drawn in voxel order, aspect from its spacing"
python3 - "$WORK/grid.vti" <<'PY'
import sys
n = (10, 8, 6)
vals = ' '.join(str(float(i % 7)) for i in range(n[0] * n[1] * n[2]))
ext = '0 9 0 7 0 5'
open(sys.argv[1], 'w').write('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">\n'
    '<ImageData WholeExtent="%s" Origin="0 0 0" Spacing="1 1 2"><Piece Extent="%s"><PointData Scalars="s">'
    '<DataArray type="Float32" Name="s" format="ascii">%s</DataArray></PointData></Piece></ImageData></VTKFile>\n' % (ext, ext, vals))
PY
run fconv "$WORK/grid.vti" --to png -v -o "$WORK/grid.png"
expect_status 0
expect_stderr_has "orientation unknown"
# The I-K panel: 10 voxels of 1 across, 6 of 2 up -> 10 x 12 mm.
check "J slice 10 x 12 mm" python3 - "$err" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
mm = float(re.search(r"panels, ([0-9.e+-]+) mm per pixel", log).group(1))
w, h = map(int, re.search(r"panel 'J=\d+' at \d+,\d+ size (\d+)x(\d+)", log).groups())
sys.exit(not (abs(w * mm - 10) <= mm and abs(h * mm - 12) <= mm))
PY

case_ "a 4-D series: frame 0 with a warning naming the count, --frame K picks another"
python3 - "$WORK/series.nrrd" <<'PY'
import sys
data = bytes(range(1, 4)) * 0 + b''.join(bytes([10 * (t + 1)]) * 1000 for t in range(3))
open(sys.argv[1], 'wb').write(b'NRRD0004\ntype: uint8\ndimension: 4\nsizes: 10 10 10 3\nkinds: domain domain domain list\n'
                             b'space: RAS\nspace directions: (1,0,0) (0,1,0) (0,0,1) none\nencoding: raw\n\n' + data)
PY
run fconv "$WORK/series.nrrd" --to png -v -o "$WORK/series.png"
expect_status 0
expect_stderr_has "warning: .*3 frames: drawing frame 0"
expect_stderr_has "window 0 to 10,"
run fconv "$WORK/series.nrrd" --to png --frame 2 -v -o "$WORK/series2.png"
expect_status 0
expect_stderr_has "window 0 to 30,"
run fconv "$WORK/series.nrrd" --to png --frame 3 -o "$WORK/series3.png"
check "--frame beyond the last: refused" test "$rc" -ne 0

case_ "montage: 12 axial slices over the slices with content; fewer slices, fewer panels"
make_nrrd "$WORK/thin.nrrd" 30,30,4 "(1,0,0) (0,1,0) (0,0,1)" >/dev/null
run fconv "$WORK/thin.nrrd" --to png --view montage --window 0,500 -v -o "$WORK/thin.png"
expect_status 0
check "4 panels" grep -q ": 4 panels" "$err"
# 40 x 30 x 20 voxels, background 100 (the window's low end by default): only the block
# (k > 0.7 * 19, the six top slices 14..19) rises above a tenth of the window.
make_nrrd "$WORK/block.nrrd" 40,30,20 "(1,0,0) (0,1,0) (0,0,1)" >/dev/null
run fconv "$WORK/block.nrrd" --to png --view montage -v -o "$WORK/mont.png"
check "6 panels, K=14 to K=19" test "$(grep -o "panel 'K=[0-9]*'" "$err" | tr -dc '0-9\n' | paste -sd,)" = "14,15,16,17,18,19"
run fconv "$WORK/block.nrrd" --to png --view montage --window 0,500 -v -o "$WORK/mont.png"
check "background above a tenth of 0..500: 12 panels over all 20 slices" grep -q ": 12 panels" "$err"

case_ "scale bar: a round length (1, 2, 5 x 10^n mm) at most 0.3 of the narrowest panel"
check "scale bar of the montage" python3 - "$err" <<'PY'
import math, re, sys
log = open(sys.argv[1]).read()
mm = float(re.search(r"panels, ([0-9.e+-]+) mm per pixel", log).group(1))
widths = [int(w) * mm for w in re.findall(r"size (\d+)x\d+", log)]
limit = 0.3 * min(widths)
want = max(m * 10 ** e for m in (1, 2, 5) for e in range(-3, 5) if m * 10 ** e <= limit * (1 + 1e-9))
bar = re.search(r"scale bar ([0-9.e+-]+) mm = (\d+) px", log)
sys.exit(not (abs(float(bar.group(1)) - want) < 1e-9 and abs(int(bar.group(2)) * mm - want) <= mm))
PY

case_ "bad --view, --window, --slice: exit 2 naming the flag"
for bad in "--view sideways:--view" "--window 5,1:--window" "--window a,b:--window" "--window 1:--window" \
            "--slice 1,2:--slice" "--slice -1,0,0:--slice" "--slice 1.5,0,0:--slice" "--slice 40,0,0:outside the volume" \
            "--convention upside:--convention"; do
  run fconv "$WORK/block.nrrd" --to png ${bad%%:*} -o "$WORK/bad.png"
  expect_clean_failure 2 fconv
  expect_stderr_has "${bad#*:}"
  check "nothing written for ${bad%%:*}" test ! -e "$WORK/bad.png"
done
run fconv "$WORK/block.nrrd" --to png --view mip --slice 1,1,1 -o "$WORK/bad.png"
expect_clean_failure 2 fconv
expect_stderr_has "--slice"

case_ "a 2-D image or a volume-to-volume conversion with --view: exit 2"
run fconv "$WORK/plain.png" --to png --view ortho -o "$WORK/bad.png"
expect_clean_failure 2 fconv
expect_stderr_has "the input is an image"
run fconv "$WORK/block.nrrd" --to mha --view mip -o "$WORK/bad.mha"
expect_clean_failure 2 fconv
expect_stderr_has "--view"

case_ "segbrain slices without --labels: plain grey slices with letters"
run segbrain slices "$WORK/block.nrrd" -o "$WORK/sb.png"
expect_status 0
run fconv --info "$WORK/sb.png"
expect_json '.channels' '3'

finish
