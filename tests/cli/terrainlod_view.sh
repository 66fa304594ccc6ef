#!/usr/bin/env bash
# terrainlod views (issue 30): --clip cuts exactly at the DEM's edges (the same view with
# and without --clip agree wherever both draw; --clip loses only the padding), on a DEM
# whose size is not a multiple of the tile and on Olinda (r-cran-stars) when present.
. "$(dirname "$0")/lib.sh"
PNGCMP="python3 $(dirname "$0")/terrainlod/pngcmp.py"

# 45 x 37 samples (44 x 36 cells; tile 16 -> a 64-cell padded square), 10 m cells, sample
# centres x = 5 .. 445, y = 5 .. 365. Bumps in the west, flat "sea" (0) east of column 28:
# over flat ground the tiles' triangles reach from inside the DEM into the padding.
awk 'BEGIN { print "ncols 45\nnrows 37\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 37; r++) { line = ""; j = 36 - r; for (i = 0; i < 45; i++)
    line = line sprintf("%d ", i < 28 ? (i * 7 + j * 13) % 11 + (i * j) % 5 : 0); print line } }' >"$WORK/odd.asc"

# A view from straight above the DEM's centre (225, 185): a point (x, y, 0) projects to
# column 200 + f (x - 225) / 5000, row 200 - f (y - 185) / 5000, f = 200 / tan(6 deg);
# heights <= 15 move a point by < 0.3 pixel.
top_cam() { printf '{"eye":[%s,%s,5000],"target":[%s,%s,0],"up":[0,1,0],"fovy_deg":12,"width":400,"height":400}\n' "$1" "$2" "$1" "$2"; }
rect() {  # x0 x1 y0 y1 (world) and the camera's centre -> the pixel rectangle
  awk -v x0="$1" -v x1="$2" -v y0="$3" -v y1="$4" -v cx="$5" -v cy="$6" -v d="$7" -v w="$8" -v fov="$9" 'BEGIN {
    f = (w / 2) / (sin(fov * 3.14159265358979 / 360) / cos(fov * 3.14159265358979 / 360));
    printf "%.4f %.4f %.4f %.4f", w / 2 + f * (x0 - cx) / d, w / 2 - f * (y1 - cy) / d, w / 2 + f * (x1 - cx) / d, w / 2 - f * (y0 - cy) / d }'
}

case_ "--clip on a 45 x 37 DEM (tile 16): from above, exactly the DEM rectangle; nothing else changes"
run terrainlod build "$WORK/odd.asc" --tile 16 -o "$WORK/odd.tlp"
expect_status 0
top_cam 225 185 >"$WORK/top.json"
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/top.json" -o "$WORK/full.ply" --png "$WORK/full.png"
expect_status 0
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/top.json" --clip -o "$WORK/clip.ply" --png "$WORK/clip.png"
expect_status 0
check "clip: DEM drawn whole, padding gone, the rest identical" \
  $PNGCMP "$WORK/full.png" "$WORK/clip.png" $(rect 5 445 5 365 225 185 5000 400 12)
check "the padding was in view without --clip" sh -c "$PNGCMP '$WORK/full.png' '$WORK/clip.png' | awk '\$2 > 1000 { ok = 1 } END { exit !ok }'"
# The clipped mesh spans exactly the DEM's sample centres.
check "clipped mesh x in [5, 445], y in [5, 365]" python3 - "$WORK/clip.ply" <<'PY'
import sys
d = open(sys.argv[1], "rb").read()
head, body = d.split(b"end_header\n", 1)
assert b"binary_little_endian" in head, "binary PLY expected"
import struct
n = int([l for l in head.split(b"\n") if l.startswith(b"element vertex")][0].split()[2])
props = [l.split() for l in head.split(b"\n") if l.startswith(b"property") and b"list" not in l]
vprops = props[:next(i for i, p in enumerate(props) if p[1] == b"uchar") if any(p[1] == b"uchar" for p in props) else len(props)]
size = {b"float": 4, b"double": 8}[vprops[0][1]]
fmt = "<" + ("f" if size == 4 else "d") * 3
stride = size * len(vprops)
xs = [struct.unpack_from(fmt, body, k * stride) for k in range(n)]
lo = (min(p[0] for p in xs), min(p[1] for p in xs)); hi = (max(p[0] for p in xs), max(p[1] for p in xs))
assert abs(lo[0] - 5) < 1e-6 and abs(lo[1] - 5) < 1e-6 and abs(hi[0] - 445) < 1e-6 and abs(hi[1] - 365) < 1e-6, (lo, hi)
PY

case_ "--clip in an oblique view looking at the far (north-east) corner: the same wherever both draw"
echo '{"eye":[-150,-150,250],"target":[400,330,0],"up":[0,0,1],"fovy_deg":50,"width":320,"height":200}' >"$WORK/obl.json"
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/obl.json" -o "$WORK/of.ply" --png "$WORK/of.png"
expect_status 0
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/obl.json" --clip -o "$WORK/oc.ply" --png "$WORK/oc.png"
expect_status 0
check "oblique: --clip only loses pixels" $PNGCMP "$WORK/of.png" "$WORK/oc.png"

case_ "automatic camera (no --camera): every vertex of the clipped terrain projects inside the image"
run terrainlod extract "$WORK/odd.tlp" --clip -o "$WORK/auto.obj" --png "$WORK/auto.png" --report "$WORK/auto.json"
expect_status 0
cp "$WORK/auto.json" "$out"
expect_json '[.camera.automatic, .camera.width, .camera.height]' '[true,1280,800]'
# Pinhole projection of every OBJ vertex with the reported camera (docs/terrainlod.md §5).
project() {  # report obj -> "inside_all fill_x fill_y"
  python3 "$(dirname "$0")/terrainlod/project.py" "$1" "$2"
}
for preset in overview oblique north south east west top; do
  run terrainlod extract "$WORK/odd.tlp" --clip --camera-preset $preset -o "$WORK/p.obj" --report "$WORK/p.json"
  expect_status 0
  read -r ok fx fy < <(project "$WORK/p.json" "$WORK/p.obj")
  check "$preset: every vertex inside the image" test "$ok" = 1
  # The terrain's box touches the 4 % margin in one direction; the surface inside it spans
  # most of that (less where the box's top corners stand above the terrain).
  check "$preset: the terrain fills the view ($fx x $fy)" awk -v a="$fx" -v b="$fy" 'BEGIN { exit !(a > 0.6 || b > 0.6) }'
done
run terrainlod extract "$WORK/odd.tlp" --camera-preset north -o "$WORK/pn.obj" --report "$WORK/pn.json"
expect_status 0
read -r ok fx fy < <(project "$WORK/pn.json" "$WORK/pn.obj")
check "without --clip the padding is framed too" test "$ok" = 1

case_ "--z-exaggeration K: every vertex height multiplied by K, x and y unchanged"
# --tau 0.001: every leaf is drawn for both, whatever the scaled culling boxes.
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/top.json" --tau 0.001 -o "$WORK/z1.obj"
expect_status 0
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/top.json" --tau 0.001 --z-exaggeration 2.5 -o "$WORK/z25.obj"
expect_status 0
check "z x 2.5, same x, y" python3 - "$WORK/z1.obj" "$WORK/z25.obj" <<'PY'
import sys
v = [[list(map(float, l.split()[1:4])) for l in open(p) if l.startswith("v ")] for p in sys.argv[1:3]]
assert len(v[0]) == len(v[1]) > 0
for a, b in zip(*v):
    assert a[0] == b[0] and a[1] == b[1] and abs(b[2] - 2.5 * a[2]) <= 1e-4 * (1 + abs(a[2])), (a, b)
assert max(abs(a[2]) for a in v[0]) > 0
PY

case_ "bad automatic-camera and exaggeration flags"
run terrainlod extract "$WORK/odd.tlp" --z-exaggeration 0 -o "$WORK/x.ply"
expect_status 2
expect_stderr_has 'z-exaggeration'
run terrainlod extract "$WORK/odd.tlp" --camera-preset sideways -o "$WORK/x.ply"
expect_status 2
expect_stderr_has 'sideways'
run terrainlod extract "$WORK/odd.tlp" --camera "$WORK/top.json" --camera-preset top -o "$WORK/x.ply"
expect_status 2
check "nothing written" test ! -e "$WORK/x.ply"

if olinda=$(need_testdata dem/olinda_dem_utm25s.tif); then
  case_ "Olinda (110 x 110 cells, padded to 128): --clip keeps the DEM whole, from above and at the far corner"
  run terrainlod build "$olinda" -o "$WORK/olinda.tlp"
  expect_status 0
  # Sample centres: x0 = 288821.247, 110 cells of 89.994 m (r-cran-stars' olinda_dem_utm25s.tif).
  read -r x0 y0 <<<"$(jq -r '.manifest.origin | "\(.[0]) \(.[1])"' <("$FEST_BIN/terrainlod" stats "$WORK/olinda.tlp"))"
  x1=$(awk -v a="$x0" 'BEGIN { printf "%.6f", a + 110 * 89.99406734945116 }')
  y1=$(awk -v a="$y0" 'BEGIN { printf "%.6f", a + 110 * 89.99406734945116 }')
  cx=294600; cy=9116600
  printf '{"eye":[%s,%s,30000],"target":[%s,%s,0],"up":[0,1,0],"fovy_deg":30,"width":250,"height":250}\n' $cx $cy $cx $cy >"$WORK/ot.json"
  run terrainlod extract "$WORK/olinda.tlp" --camera "$WORK/ot.json" -o "$WORK/otf.ply" --png "$WORK/otf.png"
  expect_status 0
  run terrainlod extract "$WORK/olinda.tlp" --camera "$WORK/ot.json" --clip -o "$WORK/otc.ply" --png "$WORK/otc.png"
  expect_status 0
  # Heights -1 .. 88 m at 30 km: < 0.3 pixel of parallax.
  check "Olinda from above: the DEM rectangle exactly" $PNGCMP "$WORK/otf.png" "$WORK/otc.png" $(rect "$x0" "$x1" "$y0" "$y1" $cx $cy 30000 250 30)
  echo '{"eye":[287000,9109000,4000],"target":[293800,9115800,0],"up":[0,0,1],"fovy_deg":50,"width":320,"height":200}' >"$WORK/oo.json"
  run terrainlod extract "$WORK/olinda.tlp" --camera "$WORK/oo.json" -o "$WORK/oof.ply" --png "$WORK/oof.png"
  run terrainlod extract "$WORK/olinda.tlp" --camera "$WORK/oo.json" --clip -o "$WORK/ooc.ply" --png "$WORK/ooc.png"
  expect_status 0
  check "Olinda oblique: --clip only loses pixels" $PNGCMP "$WORK/oof.png" "$WORK/ooc.png"
fi

finish
