#!/usr/bin/env bash
# volrender end-to-end: the analytic compositing cases of docs/volrender.md (exact answers
# from the emission-absorption integral), stereo disparity and the mirror camera checked by
# projecting a bright blob independently (Python), determinism, a golden image, bad input.
source "$(dirname "$0")/lib.sh"
FX="python3 $(dirname "$0")/isovol/fixtures.py"
W="$WORK"
for k in slab ramp quadratic blob nan flat; do $FX volume $k "$W/$k.nrrd"; done
near() {  # near VALUE EXPECTED TOLERANCE
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'
}
ortho=(--fov 0 --view 0,0 --size 8x8 --ert 1 --to pfm)

case_ "homogeneous slab: A = 1 - 0.9^32 = 0.965663, C = A (1, 0.5, 0.25), for any step"
printf 'value,r,g,b,a\n0,1,0.5,0.25,0.1\n10,1,0.5,0.25,0.1\n' > "$W/slab.csv"
for s in 1 0.5 0.3 0.1; do
  run volrender dvr "$W/slab.nrrd" --tf "$W/slab.csv" "${ortho[@]}" --step $s -o "$W/slab.pfm"
  expect_status 0
  read -r r g b < <($FX pfm "$W/slab.pfm" 4 4)
  check "step $s: r $r" near "$r" 0.9656631618 1e-5
  check "step $s: g $g" near "$g" 0.4828315809 1e-5
  check "step $s: b $b" near "$b" 0.2414157904 1e-5
done

case_ "extinction ramp f = y/32, tau = 0.1 v: A = 1 - e^-1.6 = 0.798103 for any step, also pre-integrated"
printf '0,1,1,1,0\n1,1,1,1,0.1\n' > "$W/ramp.csv"
for s in 1 0.5 0.3 0.1; do
  for p in "" --preint; do
    run volrender dvr "$W/ramp.nrrd" --tf "$W/ramp.csv" --tf-mode extinction "${ortho[@]}" --step $s $p -o "$W/ramp.pfm"
    read -r r _ < <($FX pfm "$W/ramp.pfm" 4 4)
    check "step $s $p: $r" near "$r" 0.7981034 1e-6
  done
done

case_ "quadratic samples: trapezoid integral 0.1 * 10928/1024 -> A = 0.656025"
for s in 0.5 0.25; do
  run volrender dvr "$W/quadratic.nrrd" --tf "$W/ramp.csv" --tf-mode extinction "${ortho[@]}" --step $s -o "$W/q.pfm"
  read -r r _ < <($FX pfm "$W/q.pfm" 4 4)
  check "step $s: $r" near "$r" 0.6560249 1e-6
done
run volrender dvr "$W/quadratic.nrrd" --tf "$W/ramp.csv" --tf-mode extinction "${ortho[@]}" --step 0.3 -o "$W/q.pfm"
read -r r _ < <($FX pfm "$W/q.pfm" 4 4)
check "step 0.3: $r" near "$r" 0.6560249 1e-4

# The blob's centre P = index (24, 17, 20) * 0.01 = (0.24, 0.17, 0.20).
screen='-0.1,-0.1,0.5;0.5,-0.1,0.5;-0.1,0.4,0.5'
case_ "stereo pair: the blob's disparity is ipd z / (D + z) on the screen (prediction by projection)"
run volrender mip "$W/blob.nrrd" --window 0,100 --screen "$screen" --eye 0.2,0.15,1.1 --stereo 0.064 --size 300x250 \
    --to pfm -o "$W/st_%s.pfm"
expect_status 0
read -r lx ly < <($FX centroid "$W/st_L.pfm")
read -r rx ry < <($FX centroid "$W/st_R.pfm")
# line eye -> P meets the screen plane z = 0.5 at eye + t (P - eye), t = (1.1 - 0.5) / (1.1 - 0.2)
pred() { awk -v ex="$1" 'BEGIN { t = 0.6 / 0.9; x = ex + t * (0.24 - ex); y = 0.15 + t * (0.17 - 0.15);
                                 printf "%.6f %.6f\n", (x + 0.1) / 0.6 * 300, 250 - (y + 0.1) / 0.5 * 250 }'; }
read -r plx ply < <(pred 0.168)
read -r prx pry < <(pred 0.232)
check "left x $lx vs $plx" near "$lx" "$plx" 0.5
check "left y $ly vs $ply" near "$ly" "$ply" 0.5
check "right x $rx vs $prx" near "$rx" "$prx" 0.5
check "disparity $(awk -v a="$rx" -v b="$lx" 'BEGIN{print a-b}') px = 0.064*0.3/0.9 m = 10.67 px" \
      near "$(awk -v a="$rx" -v b="$lx" 'BEGIN{print a-b}')" 10.6667 0.5

case_ "beam-splitter mirror: the blob appears at the pixel whose reflection lies on the line eye -> P"
# A 45-degree mirror n.x = delta, n = (0, 1, 1)/sqrt(2) through (0.2, 0.7, 0.2) between the eye
# (at +y) and the volume; the screen is horizontal at z = 1 where the reflected lines of sight
# go. Prediction: q = line(eye, P) meets R(screen plane); the pixel is at R(q) on the screen.
mirror='0,0.70710678118654752,0.70710678118654752,0.63639610306789277'
run volrender mip "$W/blob.nrrd" --window 0,100 --screen '-0.2,0.3,1.0;0.6,0.3,1.0;-0.2,1.1,1.0' --eye 0.2,1.3,0.2 \
    --mirror "$mirror" --size 200x200 --to pfm -o "$W/mirror.pfm"
expect_status 0
read -r mx my < <($FX centroid "$W/mirror.pfm")
read -r px py < <(python3 - <<'PY'
import math
n = (0, 1 / math.sqrt(2), 1 / math.sqrt(2)); d = 0.63639610306789277
R = lambda x: tuple(x[i] - 2 * (sum(n[k] * x[k] for k in range(3)) - d) * n[i] for i in range(3))
pa, pb, pc = (-0.2, 0.3, 1.0), (0.6, 0.3, 1.0), (-0.2, 1.1, 1.0)
eye, P = (0.2, 1.3, 0.2), (0.24, 0.17, 0.20)
ra, rb, rc = R(pa), R(pb), R(pc)
u = [rb[i] - ra[i] for i in range(3)]; v = [rc[i] - ra[i] for i in range(3)]
nn = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
dd = [P[i] - eye[i] for i in range(3)]
t = sum(nn[i] * (ra[i] - eye[i]) for i in range(3)) / sum(nn[i] * dd[i] for i in range(3))
q = R(tuple(eye[i] + t * dd[i] for i in range(3)))
uu = (q[0] - pa[0]) / 0.8; vv = (q[1] - pa[1]) / 0.8
print("%.6f %.6f" % (uu * 200, 200 - vv * 200))
PY
)
check "mirror x $mx vs $px" near "$mx" "$px" 0.5
check "mirror y $my vs $py" near "$my" "$py" 0.5

case_ "cross-tool: iso depth = depth of isosurf's mesh of the same iso-value (--mesh), within 0.05 voxel"
$FX volume sphere "$W/sphere.nrrd"
run isosurf "$W/sphere.nrrd" --iso 0 -o "$W/sphere.ply"
run volrender dvr "$W/sphere.nrrd" --tf contour-only --mesh "$W/sphere.ply" --fov 0 --size 48x48 --depth-image "$W/dm.pfm" --to pfm -o "$W/m.pfm"
expect_status 0
run volrender iso "$W/sphere.nrrd" --iso 0:1 --fov 0 --size 48x48 --depth-image "$W/di.pfm" --to pfm -o "$W/i.pfm"
expect_status 0
check "depths agree" python3 - "$W/dm.pfm" "$W/di.pfm" <<'PY'
import math, struct, sys
def rd(p):
    d = open(p, "rb").read().split(b"\n", 3)
    w, h = map(int, d[1].split())
    return struct.unpack("<%df" % (w * h), d[3][: 4 * w * h])
a, b = rd(sys.argv[1]), rd(sys.argv[2])
both = [(x, y) for x, y in zip(a, b) if math.isfinite(x) and math.isfinite(y)]
only = sum(math.isfinite(x) != math.isfinite(y) for x, y in zip(a, b))
sys.exit(0 if len(both) > 300 and only <= 12 and max(abs(x - y) for x, y in both) <= 0.05 else 1)
PY
printf 'OFF\n5 1 0\n0 0 0\n1 0 0\n1 1 0\n0.5 1.5 0\n0 1 0\n5 0 1 2 3 4\n' > "$W/penta.off"
run volrender dvr "$W/sphere.nrrd" --mesh "$W/penta.off" -o "$W/x.png"
expect_clean_failure 3 volrender

case_ "slices (fig. 4.5b): f = x, one plane normal to z, contours 8:8:7 of width 1.01: colour only near x = 8, 16, ..., 56"
$FX volume xramp "$W/xramp.nrrd"
# orthographic, looking down z, 64 pixels over x = 0..64: pixel i has its centre at x = i + 0.5
run volrender slices "$W/xramp.nrrd" --slice-axis z --slices 1 --contours 8:8:7 --contour-width 1.01 --fov 0 --view 0,90 \
    --zoom 1.7320508075688772 --size 64x64 --to pfm -o "$W/sl.pfm"
expect_status 0
check "contour columns" python3 - "$W/sl.pfm" <<'PY'
import struct, sys
d = open(sys.argv[1], "rb").read().split(b"\n", 3)
w, h = map(int, d[1].split())
v = struct.unpack("<%df" % (3 * w * h), d[3][: 12 * w * h])
for row in range(2, h - 2):
    lit = [x for x in range(w) if v[(row * w + x) * 3] > 0]
    near = lambda x: min(abs(x + 0.5 - c) for c in range(8, 57, 8))
    if any(near(x) > 0.5 + 1 for x in lit):  # +-1 pixel
        sys.exit(1)
    if any(not any(abs(x + 0.5 - c) <= 1 for x in lit) for c in range(8, 57, 8)):
        sys.exit(1)
PY
run volrender slices "$W/xramp.nrrd" --slices 4
expect_clean_failure 2 volrender

case_ "slices --contour-width-world W: band W |grad f| in data units (lines of constant world width)"
# f = x has |grad f| = 1 exactly (central differences of a linear field), so W = 1.01 world
# units is the same band as --contour-width 1.01: identical images.
run volrender slices "$W/xramp.nrrd" --slice-axis z --slices 1 --contours 8:8:7 --contour-width-world 1.01 --fov 0 --view 0,90 \
    --zoom 1.7320508075688772 --size 64x64 --to pfm -o "$W/slw.pfm"
expect_status 0
check "same image as --contour-width 1.01" cmp "$W/sl.pfm" "$W/slw.pfm"
# spacing 2: f = i grows by 1/2 per world unit, so W = 4.04 world units is 2.02 data units;
# W = 2.02 lights exactly the pixel columns whose centre x + 0.5 lies within 1.01 of a
# contour at x = 8, 16, ..., 56 (world units; same orthographic camera as above)
$FX volume xramp2 "$W/xramp2.nrrd"
cam=(--slice-axis z --slices 1 --contours 4:4:7 --fov 0 --view 0,90 --zoom 1.7320508075688772 --size 64x64 --to pfm)
run volrender slices "$W/xramp2.nrrd" "${cam[@]}" --contour-width 2.02 -o "$W/s2a.pfm"
run volrender slices "$W/xramp2.nrrd" "${cam[@]}" --contour-width-world 4.04 -o "$W/s2b.pfm"
expect_status 0
check "spacing 2: W = 4.04 world is 2.02 data units" cmp "$W/s2a.pfm" "$W/s2b.pfm"
run volrender slices "$W/xramp2.nrrd" "${cam[@]}" --contour-width-world 2.02 -o "$W/s2c.pfm"
expect_status 0
check "W = 2.02: lit columns = |x + 0.5 - 8m| <= 1.01" python3 - "$W/s2c.pfm" <<'PY'
import struct, sys
d = open(sys.argv[1], "rb").read().split(b"\n", 3)
w, h = map(int, d[1].split())
v = struct.unpack("<%df" % (3 * w * h), d[3][: 12 * w * h])
want = [x for x in range(w) if any(abs(x + 0.5 - c) <= 1.01 for c in range(8, 57, 8))]
for row in range(2, h - 2):
    if [x for x in range(w) if v[(row * w + x) * 3] > 0] != want:
        sys.exit(1)
PY
case_ "composite: over in linear light, the first image on top (analytic)"
# A = sRGB red at alpha 128/255 over opaque blue: linear (a, 0, 1 - a) with a = 128/255,
# opaque, so 8-bit sRGB (round(255 srgb(a)), 0, round(255 srgb(1 - a))) = (188, 0, 187)
$FX png "$W/ca.png" 8 6 255,0,0,128
$FX png "$W/cb.png" 8 6 0,0,255
want=$(python3 -c "
s = lambda v: 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
a = 128 / 255
print(round(255 * s(a)), 0, round(255 * s(1 - a)))")
run volrender composite "$W/ca.png" "$W/cb.png" -o "$W/cab.png"
expect_status 0
check "pixel = $want" test "$($FX pngpixel "$W/cab.png" 3 2)" = "$want"
run volrender composite "$W/cb.png" "$W/ca.png" -o "$W/cba.png"
check "opaque blue on top hides red" test "$($FX pngpixel "$W/cba.png" 5 4)" = "0 0 255"
$FX png "$W/cc.png" 4 6 0,0,255
run volrender composite "$W/ca.png" "$W/cc.png" -o "$W/x.png"
expect_clean_failure 3 volrender
expect_stderr_has "4x6"
run volrender composite "$W/ca.png" -o "$W/x.png"
expect_clean_failure 2 volrender
run volrender composite "$W/ca.png" "$W/xramp.nrrd" -o "$W/x.png"
expect_clean_failure 3 volrender

case_ "slices --slice-frame: the plane's outline, one voxel wide, on the box faces the plane meets"
# plane z = 32 of the 65^3 box seen from above (pixel i centred at x = i + 0.5): the outline
# is the points within 1 voxel of x = 0, x = 64, y = 0 or y = 64, i.e. exactly the border
# pixel rows and columns (no contour is in range: 1000:1:1)
run volrender slices "$W/xramp.nrrd" --slice-axis z --slices 1 --contours 1000:1:1 --slice-frame --fov 0 --view 0,90 \
    --zoom 1.7320508075688772 --size 64x64 --to pfm -o "$W/frame.pfm"
expect_status 0
check "lit pixels = the image border" python3 - "$W/frame.pfm" <<'PY'
import struct, sys
d = open(sys.argv[1], "rb").read().split(b"\n", 3)
w, h = map(int, d[1].split())
v = struct.unpack("<%df" % (3 * w * h), d[3][: 12 * w * h])
lit = {(x, r) for r in range(h) for x in range(w) if v[3 * (r * w + x)] > 0}
want = {(x, r) for r in range(h) for x in range(w) if x in (0, w - 1) or r in (0, h - 1)}
sys.exit(0 if lit == want else 1)
PY
run volrender slices "$W/xramp.nrrd" --contours 8:8:7 --contour-width-world 0 -o "$W/x.png"
expect_clean_failure 2 volrender

case_ "camera --print: off-axis frustum (Kooima) for an on-axis eye is symmetric"
run volrender camera --screen '-0.4,-0.3,0;0.4,-0.3,0;-0.4,0.3,0' --eye 0,0,2 --near 0.5 --size 8x6
expect_status 0
expect_json '.[0].frustum.left' -0.1
expect_json '.[0].frustum.top' 0.075
expect_json '.[0].frustum.eye_screen_distance' 2

case_ "determinism: threads and empty-space skipping do not change bytes"
run volrender dvr "$W/blob.nrrd" --tf rainbow --shade on --view 30,20 --size 64x48 --threads 1 -o "$W/a.png"
run volrender dvr "$W/blob.nrrd" --tf rainbow --shade on --view 30,20 --size 64x48 --threads 2 -o "$W/b.png"
run volrender dvr "$W/blob.nrrd" --tf rainbow --shade on --view 30,20 --size 64x48 --no-skip -o "$W/c.png"
check "threads" cmp "$W/a.png" "$W/b.png"
check "skipping" cmp "$W/a.png" "$W/c.png"

case_ "golden image (tests/data/volrender/blob_dvr.pfm; guard only): max difference 2e-3"
run volrender dvr "$W/blob.nrrd" --tf rainbow --shade on --view 30,20 --size 64x48 --to pfm -o "$W/g.pfm"
check "fcompare-free numeric comparison" python3 - "$W/g.pfm" "$FEST_FIXTURES/volrender/blob_dvr.pfm" <<'PY'
import struct, sys
def rd(p):
    d = open(p, "rb").read().split(b"\n", 3)
    w, h = map(int, d[1].split())
    return struct.unpack("<%df" % (3 * w * h), d[3][: 12 * w * h])
a, b = rd(sys.argv[1]), rd(sys.argv[2])
sys.exit(0 if len(a) == len(b) and max(abs(x - y) for x, y in zip(a, b)) <= 2e-3 else 1)
PY

case_ "bad input"
run volrender dvr "$W/blob.nrrd" -o "$W/x.png" --tf "$W/nope.csv"
expect_clean_failure 4 volrender
printf '1,0,0,0,0\n0,1,1,1,1\n' > "$W/dec.csv"
run volrender dvr "$W/blob.nrrd" --tf "$W/dec.csv" -o "$W/x.png"
expect_clean_failure 3 volrender
expect_stderr_has "increase"
printf '0,0,0,0,0\n1,1,1,1,1.5\n' > "$W/alpha.csv"
run volrender dvr "$W/blob.nrrd" --tf "$W/alpha.csv" -o "$W/x.png"
expect_clean_failure 3 volrender
printf 'this is not a transfer function\n' > "$W/junk.csv"
run volrender dvr "$W/blob.nrrd" --tf "$W/junk.csv" -o "$W/x.png"
expect_clean_failure 3 volrender
run volrender iso "$W/blob.nrrd" -o "$W/x.png"
expect_clean_failure 2 volrender
run volrender warp "$W/blob.nrrd"
expect_clean_failure 2 volrender
run volrender dvr "$W/blob.nrrd" --screen '0,0,0;1,0,0;2,0,0' --eye 0,0,1 -o "$W/x.png"
expect_clean_failure 2 volrender
expect_stderr_has "collinear"
run volrender dvr "$W/blob.nrrd" --screen '0,0,0;1,0,0;0,1,0' --eye 0.5,0.5,0 -o "$W/x.png"
expect_clean_failure 2 volrender
run volrender dvr "$W/blob.nrrd" --screen '0,0,0;1,0,0;0,1,0' --eye 0.5,0.5,1 --mirror 0,0,0,1 -o "$W/x.png"
expect_clean_failure 2 volrender
run volrender dvr "$W/blob.nrrd" --size 0x10 -o "$W/x.png"
expect_clean_failure 2 volrender
run volrender dvr "$W/nan.nrrd" -o "$W/x.png"
expect_clean_failure 3 volrender
run volrender dvr "$W/flat.nrrd" -o "$W/x.png"
expect_clean_failure 3 volrender
: > "$W/empty"
run_stdin "$W/empty" volrender dvr -o "$W/x.png"
expect_clean_failure 3 volrender
run volrender dvr "$W/blob.nrrd" --screen "$screen" --eye 0.2,0.15,1.1 --stereo 0.064 -o "$W/x.png"
expect_clean_failure 2 volrender
run volrender dvr "$W/blob.nrrd" --eye 0.2,0.2,0.2 --look-at 0,0,0 -o "$W/x.png"
expect_clean_failure 2 volrender
expect_stderr_has "inside the volume"
run volrender dvr "$W/blob.nrrd" -o "$W/nodir/x.png"
expect_clean_failure 4 volrender
check "no partial file" test ! -e "$W/nodir/x.png"

case_ "--raw: a headerless big-endian int16 volume renders exactly as the same volume in NRRD"
$FX raw "$W/v.raw" "$W/v.nrrd"
run volrender dvr "$W/v.raw" --raw 20,17,13,int16,big --raw-spacing 0.5,0.5,1.25 --tf rainbow --shade on --view 30,20 --size 40x30 -o "$W/raw.png"
expect_status 0
run volrender dvr "$W/v.nrrd" --tf rainbow --shade on --view 30,20 --size 40x30 -o "$W/nrrd.png"
check "same bytes" cmp "$W/raw.png" "$W/nrrd.png"
run_stdin "$W/v.raw" volrender mip - --raw 20,17,13,int16,big --raw-spacing 0.5,0.5,1.25 --size 40x30 -o "$W/raw_stdin.png"
run volrender mip "$W/v.nrrd" --size 40x30 -o "$W/nrrd_mip.png"
check "from standard input too" cmp "$W/raw_stdin.png" "$W/nrrd_mip.png"
run volrender dvr "$W/v.raw" --raw 20,17,14,int16,big -o "$W/x.png"
expect_clean_failure 3 volrender
expect_stderr_has "needs 9520 bytes, got 8840"
run volrender dvr "$W/v.raw" --raw 20,17,13,int12 -o "$W/x.png"
expect_clean_failure 2 volrender
expect_stderr_has "int12"
run volrender dvr "$W/v.nrrd" --raw-spacing 1,1,1 -o "$W/x.png"
expect_clean_failure 2 volrender
check "nothing written" test ! -e "$W/x.png"

case_ "--screen-mask: marked pixels as without the mask (bit for bit), the others exactly background, never cast"
$FX mask "$W/mask.png" 40 30
mcam=(--tf rainbow --shade on --spp 4 --bg 0.25,0.5,0.75 --view 30,20 --size 40x30 --to pfm)
run volrender dvr "$W/v.nrrd" "${mcam[@]}" -o "$W/full.pfm"
run volrender dvr "$W/v.nrrd" "${mcam[@]}" --screen-mask "$W/mask.png" -o "$W/masked.pfm" --report "$W/masked.json"
expect_status 0
check "pixels" $FX maskcheck "$W/full.pfm" "$W/masked.pfm" 40 30 0.25,0.5,0.75
# marked: x < 20 and y >= 2, i.e. 20 x 28 pixels, 4 rays each
check "rays cast = 4 x 560" test "$(jq .rays "$W/masked.json")" = 2240
run volrender dvr "$W/v.nrrd" --size 40x31 --screen-mask "$W/mask.png" -o "$W/x.png"
expect_clean_failure 3 volrender
expect_stderr_has "screen mask is 40x30, the image 40x31"
run volrender dvr "$W/v.nrrd" --size 40x30 --screen-mask "$W/v.nrrd" -o "$W/x.png"
expect_clean_failure 3 volrender
check "nothing written" test ! -e "$W/x.png"

case_ "--screen-mask polygon: exactly the pixels whose centres lie inside (count from geometry), bit for bit"
# right triangle (0,0), (20,0), (0,20), legs on pixel boundaries: centres (i+1/2, j+1/2)
# strictly inside iff i + j <= 18 -> 19 * 20 / 2 = 190 pixels; the 20 centres on the
# hypotenuse (i + j = 19) are outside by the tie rule (a centre on an edge moves to +x)
run volrender dvr "$W/v.nrrd" "${mcam[@]}" --screen-mask '0,0;20,0;0,20' -o "$W/tri.pfm" --report "$W/tri.json"
expect_status 0
check "pixels inside the triangle = full, others background" test "$($FX trianglecheck "$W/full.pfm" "$W/tri.pfm" 40 30 0.25,0.5,0.75 20)" = 190
check "rays cast = 4 x 190" test "$(jq .rays "$W/tri.json")" = 760
run volrender dvr "$W/v.nrrd" "${mcam[@]}" --screen-mask '0,20;20,0;0,0' -o "$W/tri_cw.pfm"
check "the other orientation: the same pixels" cmp "$W/tri.pfm" "$W/tri_cw.pfm"
# non-convex L: [0,10]x[0,5] and [0,5]x[5,10], vertices on pixel corners -> 50 + 25 pixels
run volrender mip "$W/v.nrrd" --size 40x30 --screen-mask '0,0;10,0;10,5;5,5;5,10;0,10' -o "$W/l.png" --report "$W/l.json"
expect_status 0
check "L-shape: 75 rays" test "$(jq .rays "$W/l.json")" = 75
for bad in '0,0;20,0' '0,0;20,0;nan,20' '0,0;20,x;0,20' '0,0;20,0,1;0,20' '0,0;10,10;20,20'; do
  run volrender dvr "$W/v.nrrd" --size 40x30 --screen-mask "$bad" -o "$W/x.png"
  expect_clean_failure 2 volrender
  expect_stderr_has "screen-mask polygon"
done
check "nothing written" test ! -e "$W/x.png"

case_ "four-mirror pyramid: the composite equals each viewer's part inside its triangle (disjoint masks)"
# the four triangles of a 40 x 30 screen's diagonals (no pixel centre lies on a diagonal),
# each rendered from its own side with --bg none, joined by composite
tris=('0,0;40,0;20,15' '40,0;40,30;20,15' '0,30;40,30;20,15' '0,0;0,30;20,15')
views=(90,20 0,20 270,20 180,20)
rays=0
for k in 0 1 2 3; do
  run volrender dvr "$W/v.nrrd" --tf rainbow --shade on --bg none --size 40x30 --view "${views[$k]}" \
      --screen-mask "${tris[$k]}" -o "$W/part$k.png" --report "$W/part$k.json"
  expect_status 0
  rays=$((rays + $(jq .rays "$W/part$k.json")))
done
check "the four masks cover the 1200 pixels once: $rays rays" test "$rays" = 1200
run volrender composite "$W/part0.png" "$W/part1.png" "$W/part2.png" "$W/part3.png" -o "$W/screen.png"
expect_status 0
check "composite = part inside its triangle" $FX pyramidcheck "$W/screen.png" "$W/part0.png" "$W/part1.png" "$W/part2.png" "$W/part3.png" 40 30

case_ "--frame all: one image per frame (%d pattern); the blob moves 3 voxels = 6 pixels per frame"
$FX stream "$W/stream.nrrd" 4
$FX series "$W/series.nrrd" 4
# orthographic along +y, zoom sqrt(3): the 24^3 box's 23 voxels span the 46 pixels, so the
# blob centre x = 7 + 3k lies at pixel 2x = 14 + 6k, and z = 11.5 at 23
fcam=(--window 0,100 --fov 0 --view 0,0 --zoom 1.7320508075688772 --size 46x46 --to pfm)
mkdir -p "$W/fa" "$W/fb"
run volrender mip "$W/stream.nrrd" --frame all "${fcam[@]}" -o "$W/fa/f%03d.pfm" --report "$W/fa.json"
expect_status 0
check "4 files" test "$(ls "$W/fa" | tr '\n' ' ')" = "f000.pfm f001.pfm f002.pfm f003.pfm "
check "report counts 4 frames" test "$(jq .frames "$W/fa.json")" = 4
for k in 0 1 2 3; do
  read -r cx cy < <($FX centroid "$W/fa/f00$k.pfm")
  check "frame $k: centroid $cx $cy" near "$cx" $((14 + 6 * k)) 0.01
  check "frame $k: row $cy" near "$cy" 23 0.01
done
run volrender mip "$W/stream.nrrd" --frame 2 "${fcam[@]}" -o "$W/f2.pfm"
check "frame 2 of all = --frame 2" cmp "$W/f2.pfm" "$W/fa/f002.pfm"
run volrender mip "$W/series.nrrd" --frame all "${fcam[@]}" -o "$W/fb/f%03d.pfm"
expect_status 0
check "a 4-D NRRD series gives the same frames" cmp "$W/fa/f003.pfm" "$W/fb/f003.pfm"
mkdir -p "$W/fs"
run volrender mip "$W/stream.nrrd" --frame all --window 0,100 --screen '-2,-2,30;26,-2,30;-2,26,30' --eye 11,11,60 --stereo 2 \
    --size 16x16 -o "$W/fs/%02d_%s.png"
expect_status 0
check "stereo pairs per frame: %02d and %s" test "$(ls "$W/fs" | tr '\n' ' ')" = "00_L.png 00_R.png 01_L.png 01_R.png 02_L.png 02_R.png 03_L.png 03_R.png "
run volrender mip "$W/stream.nrrd" --frame all "${fcam[@]}" -o "$W/x.pfm"
expect_clean_failure 2 volrender
expect_stderr_has "%d"
run volrender mip "$W/stream.nrrd" --frame all "${fcam[@]}"
expect_clean_failure 2 volrender
run volrender mip "$W/stream.nrrd" --frame every -o "$W/x%d.pfm"
expect_clean_failure 2 volrender
head -c 150000 "$W/stream.nrrd" > "$W/cut.nrrd"
mkdir -p "$W/fc"
run volrender mip "$W/cut.nrrd" --frame all "${fcam[@]}" -o "$W/fc/f%03d.pfm"
expect_clean_failure 3 volrender
expect_stderr_has "truncated"
check "no frame written" test -z "$(ls "$W/fc")"

case_ "conventions: --help, --version, unknown flag, missing file"
run volrender --help
expect_status 0
check "usage" grep -q "Usage" "$out"
run volrender --version
expect_status 0
check "names fest" grep -q "(fest)" "$out"
run volrender --no-such-flag x
expect_clean_failure 2 volrender
run volrender dvr "$W/does-not-exist.nrrd"
expect_clean_failure 4 volrender
expect_stderr_has "does-not-exist"

finish
