#!/usr/bin/env bash
# isosurf end-to-end: analytic surfaces checked by an independent Python program
# (isovol/fixtures.py: crossed-edge count = vertex count, edge-use watertightness, area and
# volume), determinism, stats, and bad input.
source "$(dirname "$0")/lib.sh"
FX="python3 $(dirname "$0")/isovol/fixtures.py"
W="$WORK"
$FX volume sphere "$W/sphere.nrrd"
$FX volume torus "$W/torus.nrrd"
$FX volume nan "$W/nan.nrrd"
$FX volume flat "$W/flat.nrrd"

case_ "sphere: vertices = crossed voxel edges (independent count), closed, area/volume near the sphere's"
run isosurf exact "$W/sphere.nrrd" --iso 0 -o "$W/s.ply" --report "$W/s.json"
expect_status 0
n=$($FX crossings "$W/sphere.nrrd" 0)
check "vertex count $n" test "$(jq .vertices "$W/s.json")" = "$n"
read -r closed v f chi area vol < <($FX plycheck "$W/s.ply")
check "independent check: closed ($closed)" test "$closed" = closed
check "independent check: chi = 2 ($chi)" test "$chi" = 2
check "stats agree: closed" test "$(jq .closed "$W/s.json")" = true
check "stats agree: genus 0" test "$(jq .genus "$W/s.json")" = 0
# R = 9.3: 4 pi R^2 = 1086.865, 4/3 pi R^3 = 3369.283; marching cubes at R/h = 9.3 is within 1 %
check "area $area" awk -v a="$area" 'BEGIN { exit !(a > 1086.865 * 0.99 && a < 1086.865) }'
check "volume $vol" awk -v a="$vol" 'BEGIN { exit !(a > 3369.283 * 0.99 && a < 3369.283) }'
check "triangles = 2 (V - chi)" test "$f" = $((2 * (v - 2)))

case_ "--normals: -grad f is the sphere's outward radial direction (analytic)"
# f = 9.3 - |x - c|: the exact normal at x is (x - c)/|x - c|. Central differences and
# their trilinear interpolation err in direction by O((h/R)^2) = 1/86 rad = 0.66 degree.
run isosurf exact "$W/sphere.nrrd" --iso 0 --normals -o "$W/sn.ply"
expect_status 0
ang=$($FX radial "$W/sn.ply" 11.5,11.5,11.5)
check "largest angle to the radial direction $ang <= 0.66 degree" awk -v a="$ang" 'BEGIN { exit !(a <= 0.66) }'
run isosurf adaptive "$W/sphere.nrrd" --iso 0 --normals --max-error inf --focus 11.5,11.5,21 --focus-radius 3 -o "$W/san.ply"
expect_status 0
ang=$($FX radial "$W/san.ply" 11.5,11.5,11.5)
check "adaptive: largest angle $ang <= 0.66 degree" awk -v a="$ang" 'BEGIN { exit !(a <= 0.66) }'
run isosurf exact "$W/sphere.nrrd" --iso 0 --normals -o "$W/sn.stl"
expect_clean_failure 2 isosurf
expect_stderr_has "normals"

case_ "--smooth K (Taubin lambda|mu): a plane stays the plane, its boundary stays put"
# f = y/32, iso 0.49: the plane y = 32 * 0.49 = 15.68 with boundary on the volume's faces.
# The umbrella Laplacian of coplanar neighbours has no normal component, so every vertex
# keeps y = 15.68; boundary vertices are fixed, so the extent in x and z stays [0, 32].
$FX volume ramp "$W/ramp.nrrd"
run isosurf exact "$W/ramp.nrrd" --iso 0.49 --smooth 5 -o "$W/plane.ply"
expect_status 0
check "y = 15.68 everywhere, x and z span [0, 32]" python3 - "$W/plane.ply" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
nv = [int(l.split()[2]) for l in data[:end].decode().splitlines() if l.startswith("element vertex")][0]
V = [struct.unpack_from("<3f", data, end + 12 * i) for i in range(nv)]
ok = all(abs(v[1] - 15.68) < 1e-4 for v in V)
ok = ok and min(v[0] for v in V) == 0 and max(v[0] for v in V) == 32 and min(v[2] for v in V) == 0 and max(v[2] for v in V) == 32
sys.exit(0 if ok and nv > 1000 else 1)
PY
run isosurf exact "$W/sphere.nrrd" --iso 0 --smooth 10 -o "$W/ss.ply" --report "$W/ss.json"
expect_status 0
read -r closed _ < <($FX plycheck "$W/ss.ply")
check "smoothed sphere still closed (independent)" test "$closed" = closed
run isosurf exact "$W/sphere.nrrd" --iso 0 --smooth -1 -o "$W/x.ply"
expect_clean_failure 2 isosurf

case_ "--roi: a box holding the whole surface gives the same surface; a cut one, capped, is closed"
# The sphere (R 9.3 about 11.5) lies within samples 2..21: the ROI 1..22 keeps every cell
# the surface crosses, and world positions stay (origin moved to the ROI's first sample),
# so the meshes agree up to float rounding (fcompare, an independent program).
run isosurf exact "$W/sphere.nrrd" --iso 0 --roi 1,22,1,22,1,22 -o "$W/roi.ply" --report "$W/roi.json"
expect_status 0
check "same counts" test "$(jq -c '[.vertices, .triangles]' "$W/roi.json")" = "$(jq -c '[.vertices, .triangles]' "$W/s.json")"
check "same surface within 1e-5 (fcompare)" "$FEST_BIN/fcompare" -q "$W/s.ply" "$W/roi.ply" --tol 1e-5
run isosurf exact "$W/sphere.nrrd" --iso 0 --roi 12,23,0,23,0,23 --cap -o "$W/half.ply"
expect_status 0
read -r closed _ < <($FX plycheck "$W/half.ply")
check "half sphere capped: closed (independent)" test "$closed" = closed
check "nothing left of x = 11 (the cap layer)" python3 - "$W/half.ply" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
nv = [int(l.split()[2]) for l in data[:end].decode().splitlines() if l.startswith("element vertex")][0]
sys.exit(0 if nv > 100 and min(struct.unpack_from("<f", data, end + 12 * i)[0] for i in range(nv)) >= 11 else 1)
PY
run isosurf exact "$W/sphere.nrrd" --iso 0 --roi 0,30,0,23,0,23 -o "$W/x.ply"
expect_clean_failure 2 isosurf
expect_stderr_has "not inside"
check "no output on bad --roi" test ! -e "$W/x.ply"
run isosurf exact "$W/sphere.nrrd" --iso 0 --roi 1,2,3 -o "$W/x.ply"
expect_clean_failure 2 isosurf

case_ "torus: genus 1 (chi 0), closed"
run isosurf "$W/torus.nrrd" --iso 0 --to ply -o "$W/t.ply"
expect_status 0
read -r closed v f chi area vol < <($FX plycheck "$W/t.ply")
check "closed torus" test "$closed" = closed
check "chi 0 ($chi)" test "$chi" = 0

case_ "golden: sphere counts and measures (tests/data/isosurf/sphere.json, fcompare-free: exact integers, 1e-6 relative)"
gold="$FEST_FIXTURES/isosurf/sphere.json"
check "vertices" test "$(jq .vertices "$W/s.json")" = "$(jq .vertices "$gold")"
check "triangles" test "$(jq .triangles "$W/s.json")" = "$(jq .triangles "$gold")"
check "area" awk -v a="$(jq .area "$W/s.json")" -v b="$(jq .area "$gold")" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * b) }'

case_ "determinism: threads 1 = threads 2 = brute-force scan, byte for byte"
run isosurf "$W/sphere.nrrd" --iso 0.25 --threads 1 -o "$W/a.ply"
run isosurf "$W/sphere.nrrd" --iso 0.25 --threads 2 -o "$W/b.ply"
run isosurf "$W/sphere.nrrd" --iso 0.25 --no-octree -o "$W/c.ply"
check "threads" cmp "$W/a.ply" "$W/b.ply"
check "octree vs scan" cmp "$W/a.ply" "$W/c.ply"

case_ "--cap closes a surface cut by the volume boundary"
run isosurf "$W/sphere.nrrd" --iso -5 -o "$W/open.ply" --report "$W/open.json"
check "open without --cap" test "$(jq .boundary_edges "$W/open.json")" -gt 0
run isosurf "$W/sphere.nrrd" --iso -5 --cap -o "$W/capped.ply" --report "$W/capped.json"
check "closed with --cap" test "$(jq .closed "$W/capped.json")" = true
read -r closed _ < <($FX plycheck "$W/capped.ply")
check "independently closed" test "$closed" = closed

case_ "adaptive: closed, fewer triangles, every vertex where exact mode puts it (independent check)"
run isosurf adaptive "$W/sphere.nrrd" --iso 0 --cap --max-error 0.2 -o "$W/ad.ply" --report "$W/ad.json"
expect_status 0
read -r closed v f chi _ < <($FX plycheck "$W/ad.ply")
check "closed ($closed)" test "$closed" = closed
check "chi 2" test "$chi" = 2
run isosurf exact "$W/sphere.nrrd" --iso 0 --cap -o "$W/ex.ply"
check "fewer triangles ($f)" test "$f" -lt "$(jq .triangles "$W/s.json")"
check "vertices are exact-mode vertices" $FX subset "$W/ad.ply" "$W/ex.ply"
run isosurf adaptive "$W/torus.nrrd" --iso 0 --cap --focus 20,13.5,7.5 --focus-radius 2 --max-error inf -o "$W/adt.ply"
read -r closed _ _ chi _ < <($FX plycheck "$W/adt.ply")
check "focus: closed torus" test "$closed" = closed
check "focus: chi 0" test "$chi" = 0
run isosurf exact "$W/sphere.nrrd" --iso 0 --focus 1,2,3
expect_clean_failure 2 isosurf
run isosurf adaptive "$W/sphere.nrrd" --iso 0 --max-error -1
expect_clean_failure 2 isosurf

case_ "progressive: closed levels coarse to fine, the last (tolerance 0) identical to exact; focus path; Draco"
run isosurf progressive "$W/sphere.nrrd" --iso 0 --cap --errors 0.4,0.1,0 -o "$W/prog"
expect_status 0
check "three levels" test "$(jq '.levels | length' "$W/prog/manifest.json")" = 3
check "all closed" test "$(jq '[.levels[].closed] | all' "$W/prog/manifest.json")" = true
check "coarse first" test "$(jq '.levels[0].triangles < .levels[2].triangles' "$W/prog/manifest.json")" = true
run isosurf exact "$W/sphere.nrrd" --iso 0 --cap -o "$W/capped0.ply"
check "last = exact" cmp "$W/prog/level_02.ply" "$W/capped0.ply"
printf 'x,y,z\n11.5,11.5,20\n3,11.5,11.5\n' > "$W/path.csv"
run isosurf progressive "$W/sphere.nrrd" --iso 0 --cap --focus-path "$W/path.csv" --focus-radius 2 --to drc -o "$W/prog2"
expect_status 0
check "two Draco frames" test -s "$W/prog2/frame_01.drc"
run isosurf progressive "$W/sphere.nrrd" --iso 0 --errors 0.1,0.2 -o "$W/prog3"
expect_clean_failure 2 isosurf
run isosurf progressive "$W/sphere.nrrd" --iso 0 --errors 0.1,0 -o /proc/nope/dir
expect_clean_failure 4 isosurf

case_ "stats of any mesh: an open triangle"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$W/tri.off"
run isosurf stats "$W/tri.off"
expect_status 0
expect_json .boundary_edges 3
expect_json .closed false
expect_json .area 0.5

case_ "stdin and other formats"
run_stdin "$W/sphere.nrrd" isosurf --iso 0 --to off
expect_status 0
check "OFF on stdout" grep -q '^OFF' "$out"

case_ "iso outside the range: empty mesh, warning, exit 0"
run isosurf "$W/sphere.nrrd" --iso 1000 -o "$W/e.ply"
expect_status 0
expect_stderr_has "^isosurf: warning: no surface"

case_ "bad input"
run isosurf "$W/sphere.nrrd" -o "$W/x.ply"
expect_clean_failure 2 isosurf
run isosurf "$W/sphere.nrrd" --iso abc
expect_clean_failure 2 isosurf
: > "$W/empty"
run_stdin "$W/empty" isosurf --iso 0
expect_clean_failure 3 isosurf
head -c 2000 "$W/sphere.nrrd" > "$W/trunc.nrrd"
run isosurf "$W/trunc.nrrd" --iso 0
expect_clean_failure 3 isosurf
run isosurf "$W/nan.nrrd" --iso 0.5
expect_clean_failure 3 isosurf
expect_stderr_has "NaN"
run isosurf "$W/nan.nrrd" --iso -0.5 --nan-outside -o "$W/n.ply"
expect_status 0
run isosurf "$W/flat.nrrd" --iso 3.5
expect_clean_failure 3 isosurf
expect_stderr_has "2-D"
run isosurf "$W/sphere.nrrd" --iso 0 -o "$W/nodir/x.ply"
expect_clean_failure 4 isosurf
check "no partial file" test ! -e "$W/nodir/x.ply"
run isosurf "$W/sphere.nrrd" --iso 0 --to xyz
expect_clean_failure 2 isosurf
run isosurf "$W/sphere.nrrd" --iso 0 --frame 3 --field rho
expect_clean_failure 2 isosurf
run isosurf stats "$W/sphere.nrrd"
expect_clean_failure 3 isosurf

case_ "--raw: a headerless big-endian int16 volume gives the same mesh as the same volume in NRRD, bit for bit"
$FX raw "$W/v.raw" "$W/v.nrrd"
run isosurf exact "$W/v.raw" --raw 20,17,13,int16,big --raw-spacing 0.5,0.5,1.25 --iso 100.5 -o "$W/raw.ply"
expect_status 0
run isosurf exact "$W/v.nrrd" --iso 100.5 -o "$W/nrrd.ply"
check "same bytes" cmp "$W/raw.ply" "$W/nrrd.ply"
read -r closed _ < <($FX plycheck "$W/raw.ply")
check "closed (independent)" test "$closed" = closed
run isosurf adaptive "$W/v.raw" --raw 20,17,13,int16,big,big --iso 100.5 -o "$W/x.ply"
expect_clean_failure 2 isosurf
run isosurf exact "$W/v.raw" --raw 20,17,13,int16,little --iso 100.5 -o "$W/le.ply"
expect_status 0
check "byte order matters" bash -c "! cmp -s '$W/le.ply' '$W/raw.ply'"
run isosurf exact "$W/v.raw" --raw 20,17,13,float32 --iso 100.5 -o "$W/x.ply"
expect_clean_failure 3 isosurf
expect_stderr_has "needs 17680 bytes, got 8840"
run isosurf exact "$W/v.raw" --raw 20,17,13,int16 --frame 1 --iso 100.5 -o "$W/x.ply"
expect_clean_failure 2 isosurf
run isosurf exact "$W/v.raw" --raw 0,17,13,int16 --iso 100.5 -o "$W/x.ply"
expect_clean_failure 2 isosurf
check "nothing written" test ! -e "$W/x.ply"

case_ "--frame K of a 4-D NRRD series = frame K of the same frames as a frame stream; default the last"
$FX stream "$W/stream.nrrd" 4
$FX series "$W/series.nrrd" 4
run isosurf exact "$W/series.nrrd" --frame 1 --iso 50 -o "$W/se1.ply"
expect_status 0
run isosurf exact "$W/stream.nrrd" --frame 1 --iso 50 -o "$W/st1.ply"
check "same bytes" cmp "$W/se1.ply" "$W/st1.ply"
run isosurf exact "$W/series.nrrd" --iso 50 -o "$W/se3.ply"
run isosurf exact "$W/stream.nrrd" --frame 3 --iso 50 -o "$W/st3.ply"
check "default: the last frame" cmp "$W/se3.ply" "$W/st3.ply"
check "frames differ" bash -c "! cmp -s '$W/se1.ply' '$W/se3.ply'"
run isosurf exact "$W/series.nrrd" --frame 4 --iso 50 -o "$W/x.ply"
expect_clean_failure 2 isosurf
expect_stderr_has "4 frames"

case_ "conventions: --help, --version, unknown flag, missing file"
run isosurf --help
expect_status 0
check "usage" grep -q "Usage" "$out"
run isosurf --version
expect_status 0
check "names fest" grep -q "(fest)" "$out"
run isosurf --no-such-flag x
expect_clean_failure 2 isosurf
run isosurf "$W/does-not-exist.nrrd" --iso 1
expect_clean_failure 4 isosurf
expect_stderr_has "does-not-exist"

finish
