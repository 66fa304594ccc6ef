#!/usr/bin/env bash
# ffd: every expected position comes from the mathematics of docs/ffd.md, computed here
# with awk: a zero lattice is the identity, a lattice whose control points are an affine
# image of the rest points maps X to A X + b, a joint lands on its target, PyGeM's .prm
# box and weights give hand-computed points, a rigid object keeps its distances, and an
# animation reproduces its keys; bad input fails cleanly.
. "$(dirname "$0")/lib.sh"

printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' >"$WORK/octa.off"
# Vertex i of an OFF file ("x y z").
vertex() { awk -v i="$2" 'NR == 2 { next } NR == 3 + i { print $1, $2, $3; exit }' "$1"; }
# close A B TOL: two "x y z" triples within TOL.
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { split(a, p); split(b, q); d = 0
  for (i = 1; i <= 3; i++) d += (p[i] - q[i])^2; exit !(sqrt(d) <= t) }'; }

case_ "init + apply with zero displacements is the identity (bit-exact)"
run ffd init "$WORK/octa.off" --dims 4,4,4 -o "$WORK/lat.json"
expect_status 0
run ffd apply --lattice "$WORK/lat.json" "$WORK/octa.off" --to off
expect_status 0
check "identical text" cmp "$out" "$WORK/octa.off"

case_ "affine control points map X to A X + b (2x2x2 Bernstein, the box [-2,2]^3)"
# A = [[1.5,0.2,0],[0,0.8,0.1],[0.3,0,1.2]], b = (0.5,-1,2); points = A P0 + b, i fastest.
awk 'BEGIN { printf "{\"origin\":[-2,-2,-2],\"axes\":[[4,0,0],[0,4,0],[0,0,4]],\"dims\":[2,2,2],\"points\":["
  n = 0
  for (k = 0; k < 2; k++) for (j = 0; j < 2; j++) for (i = 0; i < 2; i++) {
    x = -2 + 4 * i; y = -2 + 4 * j; z = -2 + 4 * k
    printf "%s[%.17g,%.17g,%.17g]", (n++ ? "," : ""), 1.5*x + 0.2*y + 0.5, 0.8*y + 0.1*z - 1, 0.3*x + 1.2*z + 2 }
  print "]}" }' >"$WORK/affine.json"
run ffd apply --lattice "$WORK/affine.json" "$WORK/octa.off" -o "$WORK/affine.off"
expect_status 0
awk 'NR <= 2 { print; next } NR <= 8 { printf "%.17g %.17g %.17g\n", 1.5*$1 + 0.2*$2 + 0.5, 0.8*$2 + 0.1*$3 - 1, 0.3*$1 + 1.2*$3 + 2; next } { print }' \
  "$WORK/octa.off" >"$WORK/affine_expected.off"
run fcompare "$WORK/affine.off" "$WORK/affine_expected.off" --tol 1e-12
expect_status 0

case_ "jacobian: det J = det A = 1.5*0.8*1.2 - ... everywhere"
run ffd jacobian --lattice "$WORK/affine.json" "$WORK/octa.off"
expect_status 0
# det [[1.5,0.2,0],[0,0.8,0.1],[0.3,0,1.2]] = 1.5*(0.96) - 0.2*(0 - 0.03) + 0 = 1.446
check "all det J = 1.446" awk 'NR > 1 { if ($2 < 1.446 - 1e-12 || $2 > 1.446 + 1e-12) exit 1 }' "$out"

case_ "a joint (vertex 4, the apex) lands exactly on its target under a bent lattice"
printf '{"origin":[-2,-2,-2],"axes":[[4,0,0],[0,4,0],[0,0,4]],"dims":[4,4,4],"displacements":[[1,1,3,0.8,0,0],[2,2,3,0.5,0.3,0]]}\n' >"$WORK/bend.json"
printf 'name x y z tx ty tz\napex 0 0 1 0.1 0.2 1.05\n' >"$WORK/joints.tsv"
run ffd apply --lattice "$WORK/bend.json" --joints "$WORK/joints.tsv" "$WORK/octa.off" --to off --report "$WORK/j.json"
expect_status 0
check "apex at (0.1, 0.2, 1.05) within 1e-9" close "$(vertex "$out" 4)" "0.1 0.2 1.05" 1e-9
check "report: residual <= 1e-9" awk -v e="$(jq .joints.max_error_after "$WORK/j.json")" 'BEGIN { exit !(e <= 1e-9) }'

case_ "PyGeM .prm: box rotated 90 deg about z, weight 0.5 on x of point (1,1,1)"
cat >"$WORK/box.prm" <<'PRM'
[Box info]
n control points x: 2
n control points y: 2
n control points z: 2
box length x: 1.0
box length y: 1.0
box length z: 1.0
box origin x: 0.0
box origin y: 0.0
box origin z: 0.0
rotation angle x: 0.0
rotation angle y: 0.0
rotation angle z: 90.0

[Parameters weights]
parameter x: 1 1 1 0.5
PRM
printf 'OFF\n2 0 0\n-0.5 0.5 0.5\n-1 1 1\n' >"$WORK/pts.off"
# Rz(90): S = (0,1,0), T = (-1,0,0), U = (0,0,1); (-0.5,0.5,0.5) has s = t = u = 0.5, so it
# moves by 0.5 S * (1/2)^3 = (0, 0.0625, 0); the corner (-1,1,1) by 0.5 S.
run ffd apply --lattice "$WORK/box.prm" "$WORK/pts.off" --to off
expect_status 0
check "centre moved by (0, 0.0625, 0)" close "$(vertex "$out" 0)" "-0.5 0.5625 0.5" 1e-12
check "corner moved by (0, 0.5, 0)" close "$(vertex "$out" 1)" "-1 1.5 1" 1e-12

case_ "convert .prm -> JSON -> .prm keeps the lattice"
run ffd convert "$WORK/box.prm" --to json
expect_status 0
cp "$out" "$WORK/box.json"
run ffd apply --lattice "$WORK/box.json" "$WORK/pts.off" --to off
check "same result through JSON" close "$(vertex "$out" 0)" "-0.5 0.5625 0.5" 1e-12

case_ "rigid object: distances kept while the other object deforms"
printf 'OFF\n2 0 0\n-0.5 -0.5 0\n0.5 0.5 0.5\n' >"$WORK/bone.off"
run ffd apply --lattice "$WORK/bend.json" --in skin="$WORK/octa.off" --in bone="$WORK/bone.off" --object bone=rigid \
  -o "$WORK/out_%s.off" --report "$WORK/rg.json"
expect_status 0
d_before=$(awk 'BEGIN { n = 0 } NR > 2 { x[n] = $1; y[n] = $2; z[n++] = $3 } END { printf "%.15g", sqrt((x[0]-x[1])^2 + (y[0]-y[1])^2 + (z[0]-z[1])^2) }' "$WORK/bone.off")
d_after=$(awk 'BEGIN { n = 0 } NR > 2 { x[n] = $1; y[n] = $2; z[n++] = $3 } END { printf "%.15g", sqrt((x[0]-x[1])^2 + (y[0]-y[1])^2 + (z[0]-z[1])^2) }' "$WORK/out_bone.off")
check "bone length kept to 1e-12" awk -v a="$d_before" -v b="$d_after" 'BEGIN { exit !((a - b)^2 < 1e-24) }'
check "skin deformed" bash -c "! cmp -s '$WORK/out_skin.off' '$WORK/octa.off'"

case_ "animation: 2 keys 1 s apart at 30 fps = 31 frames; ends equal the keys"
printf '{"origin":[-2,-2,-2],"axes":[[4,0,0],[0,4,0],[0,0,4]],"dims":[4,4,4]}\n' >"$WORK/zero.json"
printf 'time lattice\n0 %s\n1 %s\n' "$WORK/zero.json" "$WORK/bend.json" >"$WORK/keys.tsv"
mkdir -p "$WORK/frames"
run ffd animate --keys "$WORK/keys.tsv" "$WORK/octa.off" -o "$WORK/frames/f%04d.off"
expect_status 0
check "31 frames in the manifest" test "$(tail -n +2 "$out" | wc -l)" = 31
check "frame 0 is the rest mesh" cmp "$WORK/frames/f0000.off" "$WORK/octa.off"
run ffd apply --lattice "$WORK/bend.json" "$WORK/octa.off" --to off
check "frame 30 is the last key" cmp "$WORK/frames/f0030.off" "$out"

case_ "bad input: degenerate box"
printf '{"origin":[0,0,0],"axes":[[1,0,0],[2,0,0],[0,0,1]],"dims":[2,2,2]}\n' >"$WORK/flat.json"
run ffd apply --lattice "$WORK/flat.json" "$WORK/octa.off"
expect_clean_failure 3 ffd
expect_stderr_has "degenerate"

case_ "bad input: dims 1"
printf '{"origin":[0,0,0],"axes":[[1,0,0],[0,1,0],[0,0,1]],"dims":[1,2,2]}\n' >"$WORK/d1.json"
run ffd apply --lattice "$WORK/d1.json" "$WORK/octa.off"
expect_clean_failure 3 ffd

case_ "bad input: NaN in a .prm weight"
sed 's/1 1 1 0.5/1 1 1 nan/' "$WORK/box.prm" >"$WORK/nan.prm"
run ffd apply --lattice "$WORK/nan.prm" "$WORK/pts.off"
expect_clean_failure 3 ffd

case_ "bad input: a joint outside the box"
printf 'far 10 10 10 0 0 0\n' >"$WORK/far.tsv"
run ffd apply --lattice "$WORK/bend.json" --joints "$WORK/far.tsv" "$WORK/octa.off"
expect_clean_failure 3 ffd
expect_stderr_has "far"

case_ "usage: unknown object, dims 1 at init"
run ffd apply --lattice "$WORK/bend.json" "$WORK/octa.off" --object nobody=rigid
expect_clean_failure 2 ffd
run ffd init "$WORK/octa.off" --dims 1,4,4
expect_clean_failure 2 ffd

case_ "I/O: missing mesh file"
run ffd apply --lattice "$WORK/bend.json" "$WORK/does-not-exist.off"
expect_clean_failure 4 ffd

case_ "ffd --help, --version, unknown flag"
run ffd --help
expect_status 0
check "usage printed" grep -q "Usage" "$out"
run ffd --version
expect_status 0
check "version names fest" grep -q "(fest)" "$out"
run ffd --no-such-flag
expect_clean_failure 2 ffd

finish
