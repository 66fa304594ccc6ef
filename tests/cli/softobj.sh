#!/usr/bin/env bash
# softobj end to end: offset volumes of isolated primitives and of a square whose shared
# edge is corrected by inclusion-exclusion (closed forms: V = 4/3 pi r^3, pi r^2 L +
# 4/3 pi r^3, 2 r A + pi/2 r^2 P + 4/3 pi r^3), the field of one triangle at points in
# all seven Voronoi regions (f = 1/distance), the tongue's points from the formulas of
# App. D, and bad input with clean errors.
. "$(dirname "$0")/lib.sh"

# within GOT EXPECTED RELTOL
within() { awk -v g="$1" -v e="$2" -v t="$3" 'BEGIN { d = g - e; if (d < 0) d = -d; exit !(d <= t * (e < 0 ? -e : e)) }'; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 <= b + 0) }'; }
PI=3.14159265358979

printf '{"vertices": [[1, 2, 3]], "points": [0]}\n' >"$WORK/point.json"
printf '{"vertices": [[0, 0, 0], [20, 0, 0]], "segments": [[0, 1]]}\n' >"$WORK/segment.json"
printf '{"vertices": [[0,0,0],[20,0,0],[20,20,0],[0,20,0]], "triangles": [[0,1,2],[0,2,3]]}\n' >"$WORK/square.json"

case_ "sphere: one point, rho = 10, alpha 7: V = 4/3 pi 10^3 = 4188.79 within 0.5 %, vertices on f = V*"
run softobj polygonize --radius 10 --alpha 7 --report "$WORK/r.json" -o "$WORK/sphere.ply" "$WORK/point.json"
expect_status 0
v=$(jq .volume "$WORK/r.json")
check "volume $v" within "$v" "$(awk -v p=$PI 'BEGIN { print 4 / 3 * p * 1000 }')" 0.005
check "max |f - V*|/V* <= 1e-6" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6
check "closed" test "$(jq .closed "$WORK/r.json")" = true
check "Euler characteristic 2" test "$(jq .euler_characteristic "$WORK/r.json")" = 2
check "max edge <= lmax" below "$(jq .max_edge "$WORK/r.json")" 10.000000001
check "max normal angle <= alpha" below "$(jq .max_normal_angle_deg "$WORK/r.json")" 7.000000001
check "binary PLY written" grep -aq "format binary_little_endian" "$WORK/sphere.ply"

case_ "capsule: segment 20, rho = 5, alpha 10: V = pi 25 20 + 4/3 pi 125 = 2094.40 within 0.5 %"
run_stdin "$WORK/segment.json" softobj polygonize --radius 5 --alpha 10 --report "$WORK/r.json" --to plya
expect_status 0
check "ascii PLY on standard output" grep -q "format ascii" "$out"
v=$(jq .volume "$WORK/r.json")
check "volume $v" within "$v" "$(awk -v p=$PI 'BEGIN { print p * 25 * 20 + 4 / 3 * p * 125 }')" 0.005
check "on the surface" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6

case_ "square slab (2 triangles, shared edge): V = 2 r A + pi/2 r^2 P + 4/3 pi r^3 = 7665.2 within 0.7 %"
run softobj polygonize --radius 5 --alpha 10 --report "$WORK/r.json" -o "$WORK/square.off" "$WORK/square.json"
expect_status 0
v=$(jq .volume "$WORK/r.json")
check "volume $v" within "$v" "$(awk -v p=$PI 'BEGIN { print 2 * 5 * 400 + p / 2 * 25 * 80 + 4 / 3 * p * 125 }')" 0.007
a=$(jq .area "$WORK/r.json")
check "area $a = 2A + pi r P + 4 pi r^2" within "$a" "$(awk -v p=$PI 'BEGIN { print 800 + p * 5 * 80 + 4 * p * 25 }')" 0.007
check "OFF with normals written" test "$(head -1 "$WORK/square.off")" = NOFF

case_ "square slab, deviation-driven refinement (--max-deviation 0.04): centroids within 0.04; inscribed, so 0 < V* - V <= A * max deviation"
run softobj polygonize --radius 5 --alpha 40 --lmax 15 --max-deviation 0.04 --report "$WORK/r.json" -o "$WORK/squared.ply" "$WORK/square.json"
expect_status 0
check "closed" test "$(jq .closed "$WORK/r.json")" = true
check "Euler 2" test "$(jq .euler_characteristic "$WORK/r.json")" = 2
check "on the surface" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6
check "centroid deviation <= 0.04" below "$(jq .max_centroid_deviation "$WORK/r.json")" 0.0400001
v=$(jq .volume "$WORK/r.json")
d=$(jq .max_sampled_deviation "$WORK/r.json")
check "volume $v within [V - A d, V] (d = $d)" awk -v v="$v" -v d="$d" -v p=$PI 'BEGIN {
  V = 2 * 5 * 400 + p / 2 * 25 * 80 + 4 / 3 * p * 125; A = 800 + p * 5 * 80 + 4 * p * 25
  exit !(v < V && v >= V - A * d) }'
# An isotropic mesh meeting the sagitta bound r (1 - cos(theta/2)) <= d on the rim needs
# chords <= 2 sqrt(2 r d) = 1.265, so more than A / (0.433 * 1.265^2) = 3420 triangles.
check "anisotropic: fewer triangles than any isotropic mesh within 0.04 (3420)" below "$(jq .triangles "$WORK/r.json")" 3420

case_ "marching-cubes baseline on the capsule: projected vertices, volume within 1 %"
run softobj polygonize --method mc --grid 0.5 --radius 5 --report "$WORK/r.json" -o "$WORK/mc.ply" "$WORK/segment.json"
expect_status 0
v=$(jq .volume "$WORK/r.json")
check "volume $v" within "$v" 2094.395 0.01
check "on the surface" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6

case_ "field of one triangle at points in all seven Voronoi regions: f = 1/d, grad = -(r - R)/d^3"
printf '{"vertices": [[0,0,0],[4,0,0],[0,4,0]], "triangles": [[0,1,2]]}\n' >"$WORK/tri.json"
printf 'x\ty\tz\n-3\t-4\t0\n7\t-4\t0\n-3\t8\t0\n2\t-3\t4\n-3\t2\t4\n4\t4\t0\n1\t1\t2\n' >"$WORK/at.tsv"
run softobj field --at "$WORK/at.tsv" "$WORK/tri.json"
expect_status 0
# distances: 5 (vertex a), 5 (b), 5 (c), 5 (edge ab), 5 (edge ac), 2 sqrt 2 (edge bc), 2 (face)
expected="0.2 0.2 0.2 0.2 0.2 0.353553390593274 0.5"
i=0
for e in $expected; do
  i=$((i + 1))
  got=$(awk -F'\t' -v r=$((i + 1)) 'NR == r { print $4 }' "$out")
  check "point $i: f = $got, expected $e" within "$got" "$e" 1e-12
done
check "face point gradient (0, 0, -1/4)" test "$(awk -F'\t' 'NR == 8 { print ($5 == 0 && $6 == 0 && $7 == -0.25) }' "$out")" = 1

case_ "tongue: the ten points from App. D's formulas (neutral shape), 10 or 9 triangles"
run softobj tongue --neutral
expect_status 0
vl1=$(awk 'BEGIN { d = 3.14159265358979323846 / 180; printf "%.12f %.12f", 15 * sin(15 * d), -15 * cos(15 * d) }')
got=$(jq -r '.vertices[1] | "\(.[0]) \(.[1])"' "$out")
check "vl1 = l1 (sin a1, -cos a1): $got vs $vl1" awk -v g="$got" -v e="$vl1" 'BEGIN { split(g, a, " "); split(e, b, " "); exit !((a[1]-b[1])^2 + (a[2]-b[2])^2 < 1e-20) }'
vl5=$(awk 'BEGIN { d = 3.14159265358979323846 / 180; printf "%.12f", 14 * cos(10 * d) }')
check "vl5.z = l5 cos c2" within "$(jq '.vertices[5][2]' "$out")" "$vl5" 1e-12
expect_json '.triangles | length' 10
expect_json '.iso' 0.16666666666666666
run softobj tongue --neutral --layout paper9 --set l1=20,a1=0
expect_status 0
expect_json '.triangles | length' 9
expect_json '.vertices[1]' '[0,-20,0]'
printf 'time\tx0\ty0\tz0\tl1\tl2\tl3\tl4\tl5\tl6\tl7\tl8\tl9\ta1\ta2\ta3\tc1\tc2\tc3\tc4\tc5\tc6\n0\t0\t0\t0\t10\t10\t10\t5\t5\t5\t5\t5\t5\t90\t180\t0\t0\t0\t0\t0\t0\t0\n' >"$WORK/params.tsv"
run softobj tongue "$WORK/params.tsv"
expect_status 0
expect_json '.vertices[1]' '[10,-6.123233995736766e-16,0]'

case_ "the default tongue polygonises closed, every vertex on the surface, every chord acceptable"
softobj_tongue_json="$WORK/tongue.json"
"$FEST_BIN/softobj" tongue --neutral -o "$softobj_tongue_json"
run softobj polygonize --report "$WORK/r.json" -o "$WORK/tongue.ply" "$softobj_tongue_json"
expect_status 0
check "closed" test "$(jq .closed "$WORK/r.json")" = true
check "Euler 2" test "$(jq .euler_characteristic "$WORK/r.json")" = 2
check "on surface" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6
check "max edge <= 6" below "$(jq .max_edge "$WORK/r.json")" 6.000000001
check "max normal angle <= 15" below "$(jq .max_normal_angle_deg "$WORK/r.json")" 15.000000001

case_ "bad input: malformed JSON"
printf '{"vertices": [[0,0,0]' >"$WORK/bad.json"
run softobj polygonize "$WORK/bad.json"
expect_clean_failure 3 softobj
case_ "bad input: index out of range"
printf '{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,5]]}\n' >"$WORK/bad.json"
run softobj polygonize "$WORK/bad.json"
expect_clean_failure 3 softobj
expect_stderr_has "triangle 0 references vertex 5 \(only 3 vertices\)"
case_ "bad input: NaN coordinate"
printf '{"vertices": [[0,NaN,0]], "points": [0]}\n' >"$WORK/bad.json"
run softobj polygonize "$WORK/bad.json"
expect_clean_failure 3 softobj
case_ "bad input: empty skeleton"
printf '{"vertices": []}\n' >"$WORK/bad.json"
run softobj polygonize "$WORK/bad.json"
expect_clean_failure 3 softobj
expect_stderr_has "empty skeleton"
case_ "bad input: unknown member"
printf '{"vertices": [[0,0,0]], "points": [0], "colour": 1}\n' >"$WORK/bad.json"
run softobj polygonize "$WORK/bad.json"
expect_clean_failure 3 softobj
expect_stderr_has 'unknown member "colour"'
case_ "usage: --iso 0, --iso with --radius, unknown tongue parameter"
run softobj polygonize --iso 0 "$WORK/point.json"
expect_clean_failure 2 softobj
run softobj polygonize --iso 1 --radius 2 "$WORK/point.json"
expect_clean_failure 2 softobj
run softobj tongue --neutral --set q7=3
expect_clean_failure 2 softobj
case_ "annulus skeleton (chi = 0, no far-field sphere): refused with the marching-cubes hint"
printf '{"vertices": [[0,0,0],[10,0,0],[10,10,0],[0,10,0],[3,3,0],[7,3,0],[7,7,0],[3,7,0]], "triangles": [[0,1,5],[0,5,4],[1,2,6],[1,6,5],[2,3,7],[2,7,6],[3,0,4],[3,4,7]]}\n' >"$WORK/annulus.json"
run softobj polygonize --radius 1 "$WORK/annulus.json"
expect_clean_failure 3 softobj
expect_stderr_has "marching cubes"
case_ "two skeletons far apart with shrink-wrap: exit 1 with the --method mc hint"
printf '{"vertices": [[0,0,0],[100,0,0]], "points": [0, 1]}\n' >"$WORK/two.json"
run softobj polygonize --radius 5 --max-verts 20000 "$WORK/two.json"
expect_clean_failure 1 softobj
expect_stderr_has "not genus 0.*use --method mc"
run softobj polygonize --radius 5 --method mc --report "$WORK/r.json" -o "$WORK/two.ply" "$WORK/two.json"
expect_status 0
check "mc gives two spheres (Euler 4)" test "$(jq .euler_characteristic "$WORK/r.json")" = 4
case_ "--max-verts 100 on the tongue: exit 1"
run softobj polygonize --max-verts 100 "$softobj_tongue_json"
expect_clean_failure 1 softobj
case_ "nothing written on failure"
run softobj polygonize --max-verts 100 -o "$WORK/never.ply" "$softobj_tongue_json"
check "no file" test ! -e "$WORK/never.ply"

case_ "animate /b i b/ at 10 fps: rule 2 gives /i/'s target from t = 0 on (keys at 0, 0.2, 0.3)"
printf '{"phonemes": {"i": {"class": "vowel", "tongue": {"a1": 40}}, "b": {"class": "consonant", "tongue": null}}, "lag_s": {"tip": 0, "middle": 0, "back": 0}}\n' >"$WORK/table.json"
printf 'b 0 0.1\ni 0.1 0.3\nb 0.3 0.4\n' >"$WORK/bib.tsv"
run softobj animate --table "$WORK/table.json" --fps 10 "$WORK/bib.tsv"
expect_status 0
check "5 frames (t = 0 .. 0.4) and a header" test "$(wc -l <"$out")" -eq 6
check "a1 = 40 in every frame" test "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "a1") c = i; next } $c != 40 { bad++ } END { print bad + 0 }' "$out")" = 0
cp "$out" "$WORK/bib.params.tsv"
run softobj tongue --frame 4 "$WORK/bib.params.tsv"
expect_status 0
check "frame 4 -> skeleton with vl1.x = 15 sin 40 deg" within "$(jq '.vertices[1][0]' "$out")" "$(awk 'BEGIN { printf "%.15g", 15 * sin(40 * 3.14159265358979323846 / 180) }')" 1e-12
case_ "animate bad input: unknown phoneme, overlapping phonemes"
printf 'i 0 0.1\nx 0.1 0.2\n' >"$WORK/bad.tsv"
run softobj animate --table "$WORK/table.json" "$WORK/bad.tsv"
expect_clean_failure 3 softobj
expect_stderr_has 'line 2: phoneme "x" is not in the table'
printf 'i 0 0.3\nb 0.2 0.4\n' >"$WORK/bad.tsv"
run softobj animate --table "$WORK/table.json" "$WORK/bad.tsv"
expect_clean_failure 3 softobj

case_ "palate pass 1: the tip 4 mm beyond the virtual plane x = 14 - 6 steps onto it"
cp "$(dirname "$0")/../../examples/tongue/palate.json" "$WORK/palate.json"
run softobj tongue --neutral --set x0=12 --palate "$WORK/palate.json"
expect_status 0
check "vl0.x = 8" within "$(jq '.vertices[0][0]' "$out")" 8 1e-12
cp "$out" "$WORK/tip.json"
case_ "palate pass 2: no vertex beyond the true plane x = 14 in the strip, none outside the sphere"
run softobj polygonize -o "$WORK/tip.ply" "$WORK/tip.json"
expect_status 0
run softobj palate --palate "$WORK/palate.json" --to off "$WORK/tip.ply"
expect_status 0
check "inside" awk 'NR == 2 { n = $1 } NR > 2 && NR <= n + 2 { x = $1; y = $2; z = $3;
  if (y >= -8 && y <= 6 && (z < 0 ? -z : z) <= 20 && x > 14 + 1e-9) bad++;
  if (x > -10 && (x + 10)^2 + (y + 24)^2 + z^2 > 1600 + 1e-6) bad++ } END { exit bad > 0 }' "$out"
case_ "palate bad input"
printf '{"sphere": {"center": [0, 0], "radius": 4}, "strip": {}}\n' >"$WORK/badpal.json"
run softobj palate --palate "$WORK/badpal.json" "$WORK/tip.ply"
expect_clean_failure 3 softobj

case_ "a mesh as skeleton (--skeleton-format mesh): a closed tetrahedron, outer sheet closed and on the surface"
printf 'OFF\n4 4 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >"$WORK/tet.off"
run softobj polygonize --skeleton-format mesh --radius 2 --report "$WORK/r.json" -o "$WORK/tet.ply" "$WORK/tet.off"
expect_status 0
check "closed, Euler 2" test "$(jq '[.closed, .euler_characteristic, .skeleton_euler_characteristic]' -c "$WORK/r.json")" = '[true,2,2]'
check "on the surface" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6
run softobj polygonize "$WORK/tet.off"
expect_clean_failure 3 softobj
expect_stderr_has "skeleton-format mesh"

case_ "tongue --polygonize: every row of the animation, palate passes, a manifest, files in frame order"
mkdir -p "$WORK/frames"
run softobj tongue --polygonize --palate "$WORK/palate.json" --threads 2 -o "$WORK/frames/t%03d.ply" "$WORK/bib.params.tsv"
expect_status 0
check "manifest: header + 5 frames" test "$(wc -l <"$out")" -eq 6
check "5 files" test "$(ls "$WORK/frames" | wc -l)" -eq 5
check "row 3 names t003.ply" test "$(awk -F'\t' 'NR == 5 { print $3 }' "$out")" = "$WORK/frames/t003.ply"
run softobj tongue --polygonize -o "$WORK/frames/no_pattern.ply" "$WORK/bib.params.tsv"
expect_clean_failure 2 softobj
run softobj tongue --polygonize --max-verts 10 -o "$WORK/frames/t%d.ply" "$WORK/bib.params.tsv"
expect_status 2

case_ "golden (regression snapshot, validated by the analytic cases): the default tongue"
GOLDEN="$(dirname "$0")/softobj"
"$FEST_BIN/softobj" tongue --neutral | "$FEST_BIN/softobj" polygonize --report "$WORK/g.json" -o "$WORK/g.ply"
check "triangles within 2 %" within "$(jq .triangles "$WORK/g.json")" "$(jq .triangles "$GOLDEN/tongue_default.json")" 0.02
check "volume within 0.2 %" within "$(jq .volume "$WORK/g.json")" "$(jq .volume "$GOLDEN/tongue_default.json")" 0.002
run fcompare --ignore-counts --samples 20000 --tol 0.06 "$WORK/g.ply" "$GOLDEN/tongue_default.ply"
expect_status 0

case_ "Wyvill kernel with marching cubes: C(R/2) = 1 - 4/9 (1/4)^3 + 17/9 (1/4)^2 - 22/9 (1/4) = 1/2, so iso 0.5 is a sphere of radius 5"
run softobj polygonize --method mc --kernel wyvill:10 --iso 0.5 --grid 0.25 --report "$WORK/r.json" -o "$WORK/w.ply" "$WORK/point.json"
expect_status 0
check "volume 4/3 pi 125 within 0.5 %" within "$(jq .volume "$WORK/r.json")" 523.5988 0.005
check "on the surface" below "$(jq .max_abs_f_err_rel "$WORK/r.json")" 1e-6
run softobj polygonize --kernel wyvill:10 --iso 0.5 "$WORK/point.json"
expect_clean_failure 2 softobj
run softobj polygonize --method mc --kernel wyvill:-1 --iso 0.5 "$WORK/point.json"
expect_clean_failure 2 softobj

case_ "two unit charges at one point: f = 2/d, so radius 5 gives a sphere of radius 10 (beyond rho: the mc box must grow)"
printf '{"vertices": [[0, 0, 0]], "points": [0, 0]}\n' >"$WORK/double.json"
for m in shrinkwrap mc; do
  run softobj polygonize --method $m --grid 0.5 --alpha 7 --radius 5 --report "$WORK/r.json" -o "$WORK/d.ply" "$WORK/double.json"
  expect_status 0
  check "$m: closed" test "$(jq .closed "$WORK/r.json")" = true
  check "$m: volume 4/3 pi 10^3 within 0.5 %" within "$(jq .volume "$WORK/r.json")" 4188.790 0.005
done

finish
