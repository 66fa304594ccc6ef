#!/usr/bin/env bash
# feshape: answers from the mathematics -- the lat-long mesh has V = MN + 2 and
# F = 2V - 4 (docs/feshape.md §2.3) and its vertices lie on the superquadric; points
# sampled exactly from a deformable superquadric give back its parameters (semi-axes
# a*a_i, squareness, tapering, bending, pose) with zero residual; a sphere's points lie
# on the fitted surface; distances to a single triangle are |h|; every level of a
# hierarchy is closed (F = 2V - 4); a golden fit of the seed's squash set-up; bad input.
. "$(dirname "$0")/lib.sh"

# near A B TOL: |A - B| <= TOL
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
# OFF header counts "V F"
off_counts() { awk 'NR == 2 { print $1, $2; exit }' "$1"; }

case_ "init: the seed's grids have V = MN + 2 and F = 2MN (627/1250, 47/90, 66/128)"
for g in "25x25 627 1250" "9x5 47 90" "8x8 66 128"; do
  set -- $g
  run feshape init --grid "$1" --to off
  expect_status 0
  check "$1: counts $2 $3" test "$(off_counts "$out")" = "$2 $3"
done

case_ "init: every vertex of a sphere model lies at distance a from the centre"
run feshape init --grid 7x9 --qs 2,1,1,1,1,1,0,0,0,0,0 --center 1,2,3 --to off
expect_status 0
check "|x - c| = 2 to 1e-12" awk 'NR > 2 && NF == 3 { r = sqrt(($1-1)^2 + ($2-2)^2 + ($3-3)^2); if (r < 2 - 1e-12 || r > 2 + 1e-12) exit 1 }' "$out"

case_ "fit recovers an exactly sampled deformable superquadric (level G)"
run feshape sample --qs 2,0.5,0.7,0.9,0.8,1.2,0.2,-0.1,0.3,0.1,0.5 --center 1,2,3 --quat 0.9,0.1,0.2,0.3 --n 2000 --seed 5 -o "$WORK/sq.xyz"
expect_status 0
check "2000 rows" test "$(wc -l <"$WORK/sq.xyz")" -eq 2000
run feshape fit "$WORK/sq.xyz" --levels 0 --move-tol 1e-13 --report "$WORK/sq.json" -o "$WORK/sq.ply"
expect_status 0
g() { jq -r ".levels[0]$1" "$WORK/sq.json"; }
check "residual < 1e-8" awk -v r="$(g .surface_rms)" 'BEGIN { exit !(r < 1e-8) }'
# a and a_i enter eq. 2 only as the semi-axes a*a_i: 1, 1.4, 1.8
check "a*a1 = 1" near "$(jq '.levels[0].qs | .a * .a1' "$WORK/sq.json")" 1 1e-7
check "a*a2 = 1.4" near "$(jq '.levels[0].qs | .a * .a2' "$WORK/sq.json")" 1.4 1e-7
check "a*a3 = 1.8" near "$(jq '.levels[0].qs | .a * .a3' "$WORK/sq.json")" 1.8 1e-7
for p in "e1 0.8" "e2 1.2" "t1 0.2" "t2 -0.1" "b1 0.3" "b2 0.1" "b3 0.5"; do
  set -- $p
  check "$1 = $2" near "$(g ".qs[\"$1\"]")" "$2" 1e-6
done
check "centre (1,2,3)" near "$(jq '.levels[0].center | (.[0]-1)*(.[0]-1) + (.[1]-2)*(.[1]-2) + (.[2]-3)*(.[2]-3)' "$WORK/sq.json")" 0 1e-14
# the unit quaternion of (0.9,0.1,0.2,0.3): |q . q_true| = 1 (q and -q are one rotation)
check "rotation" near "$(jq '.levels[0].quat | (.[0]*0.9 + .[1]*0.1 + .[2]*0.2 + .[3]*0.3) / 0.9746794344808963 | if . < 0 then -. else . end' "$WORK/sq.json")" 1 1e-12

case_ "a sphere's points: residual 0, semi-axes = radius, squareness 1"
run feshape sample --qs 3,1,1,1,1,1,0,0,0,0,0 --center -1,0.5,2 --n 500 -o "$WORK/sphere.xyz"
run feshape fit "$WORK/sphere.xyz" --levels 0 --move-tol 1e-13 --report "$WORK/sphere.json" -o "$WORK/sphere.ply"
expect_status 0
check "residual < 1e-9" awk -v r="$(jq '.levels[0].surface_rms' "$WORK/sphere.json")" 'BEGIN { exit !(r < 1e-9) }'
for k in a1 a2 a3; do check "a*$k = 3" near "$(jq ".levels[0].qs | .a * .$k" "$WORK/sphere.json")" 3 1e-8; done
check "e1 = e2 = 1" near "$(jq '.levels[0].qs | (.["e1"] - 1) * (.["e1"] - 1) + (.["e2"] - 1) * (.["e2"] - 1)' "$WORK/sphere.json")" 0 1e-14

case_ "eval: points at heights 1..10 above a triangle: mean 5.5, max 10, var 8.25"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$WORK/tri.off"
for h in 1 2 3 4 5 6 7 8 9 10; do echo "0.2 0.2 $h"; done >"$WORK/heights.xyz"
run feshape eval "$WORK/tri.off" --points "$WORK/heights.xyz"
expect_status 0
check "mean 5.5" near "$(jq .mean "$out")" 5.5 1e-12
check "max 10" near "$(jq .max "$out")" 10 1e-12
check "var 8.25" near "$(jq .var "$out")" 8.25 1e-12

case_ "eval: a mesh's own vertices are at distance 0"
feshape_off() { "$FEST_BIN/feshape" init --grid 6x7 --qs 2,0.5,0.8,1,0.7,1.3,0.2,0,0.1,0,0.5 --to off; }
feshape_off >"$WORK/m.off"
run feshape eval "$WORK/m.off" --points "$WORK/m.off"
expect_status 0
check "max 0" near "$(jq .max "$out")" 0 1e-15

case_ "a hierarchy: every level closed with F = 2V - 4, error falling, files per level"
run feshape sample --qs 2,0.6,0.8,1,1,1,0.2,0,0.2,0,0.5 --bumps 2,0.08 --n 800 --seed 3 -o "$WORK/bump.xyz"
run feshape fit "$WORK/bump.xyz" --grid 6x6 --levels 3 --tau 0.01 --levels-out "$WORK/L%s.off" --report "$WORK/h.json" -o "$WORK/h.ply"
expect_status 0
check "5 levels (G, 0..3)" test "$(jq '.levels | length' "$WORK/h.json")" -eq 5
check "F = 2V - 4 in the report" jq -e 'all(.levels[]; .elements == 2 * .nodes - 4)' "$WORK/h.json"
check "mean error falls from level 0 on" jq -e '[.levels[1:][] | .mean] | . == (sort | reverse)' "$WORK/h.json"
for n in G 0 1 2 3; do
  check "L$n.off: F = 2V - 4" awk 'NR == 2 { exit !($2 == 2 * $1 - 4) }' "$WORK/L$n.off"
done
check "final output = last level" test "$(jq '.levels[-1].nodes' "$WORK/h.json")" = "$(awk '/^element vertex/ { print $3; exit }' "$WORK/h.ply")"

case_ "deterministic: 1 and 2 threads give identical bytes"
run feshape fit "$WORK/bump.xyz" --grid 6x6 --levels 2 --tau 0.01 --threads 1 -o "$WORK/t1.ply"
run feshape fit "$WORK/bump.xyz" --grid 6x6 --levels 2 --tau 0.01 --threads 2 -o "$WORK/t2.ply"
check "cmp" cmp "$WORK/t1.ply" "$WORK/t2.ply"

case_ "golden: the seed's squash set-up (5x5 grid, beta 100, 3 levels) on 123 points"
run feshape fit "$FEST_FIXTURES/feshape/squash123.xyz" --grid 5x5 --qs 2.6,0.35,0.35,0.9,1,1,0,0,0,0,0 --beta 100 --levels 3 --tau 0.02 -o "$WORK/squash.ply"
expect_status 0
run fcompare "$WORK/squash.ply" "$FEST_FIXTURES/feshape/squash_fit.ply" --tol 1e-6
expect_status 0

case_ "the seed's explicit Euler (dt 1e-5, D = I) runs the same schedule"
run feshape fit "$FEST_FIXTURES/feshape/squash123.xyz" --grid 5x5 --qs 2.6,0.35,0.35,0.9,1,1,0,0,0,0,0 --beta 100 --levels 2 --solver explicit --report "$WORK/e.json" -o "$WORK/e.ply"
expect_status 0
check "F = 2V - 4" jq -e 'all(.levels[]; .elements == 2 * .nodes - 4)' "$WORK/e.json"
check "local levels lower the error" jq -e '.levels[1].mean < .levels[0].mean' "$WORK/e.json"

case_ "bad input: empty, too few points, NaN, garbage, identical points, missing file"
: >"$WORK/empty.xyz"
run feshape fit "$WORK/empty.xyz"; expect_clean_failure 3 feshape
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n' >"$WORK/five.xyz"
run feshape fit "$WORK/five.xyz"; expect_clean_failure 3 feshape
expect_stderr_has "5 points"
{ head -20 "$WORK/sphere.xyz"; echo "1 nan 2"; } >"$WORK/nan.xyz"
run feshape fit "$WORK/nan.xyz"; expect_clean_failure 3 feshape
expect_stderr_has "line 21"
printf 'hello world\nthis is not a point file\n' >"$WORK/text.xyz"
run feshape fit "$WORK/text.xyz"; expect_clean_failure 3 feshape
for i in $(seq 20); do echo "1 2 3"; done >"$WORK/same.xyz"
run feshape fit "$WORK/same.xyz"; expect_clean_failure 1 feshape
expect_stderr_has "coincide"
run feshape fit "$WORK/no-such-file.xyz"; expect_clean_failure 4 feshape
# coordinates near the double range: squared distances overflow -- a failure, not a crash
printf '1e300 0 0\n-1e300 0 0\n0 1e300 0\n0 -1e300 0\n0 0 1e300\n0 0 -1e300\n1 1 1\n2 2 2\n3 3 1\n1 3 2\n' >"$WORK/huge.xyz"
run feshape fit "$WORK/huge.xyz"; expect_clean_failure 1 feshape
run feshape fit "$WORK/huge.xyz" --qs 1,1,1,1,1,1,0,0,0,0,0; expect_clean_failure 1 feshape
# the seed's Euler with a step far beyond its stability limit diverges: a failure
run feshape fit "$FEST_FIXTURES/feshape/squash123.xyz" --solver explicit --dt 10 --max-iter 1000; expect_clean_failure 1 feshape

case_ "bad usage: --grid 2x2, a1 = 0, e1 = 0, tau <= 0, --levels-out without %s"
run feshape fit "$WORK/sphere.xyz" --grid 2x2; expect_clean_failure 2 feshape
run feshape fit "$WORK/sphere.xyz" --qs 1,0,1,1,1,1,0,0,0,0,0; expect_clean_failure 2 feshape
expect_stderr_has "a1"
run feshape fit "$WORK/sphere.xyz" --qs 1,1,1,1,0,1,0,0,0,0,0; expect_clean_failure 2 feshape
run feshape fit "$WORK/sphere.xyz" --tau 0; expect_clean_failure 2 feshape
run feshape fit "$WORK/sphere.xyz" --levels-out "$WORK/x.ply"; expect_clean_failure 2 feshape
run feshape sample --n 10; expect_clean_failure 2 feshape

case_ "node limit: a failure, nothing written"
run feshape fit "$WORK/bump.xyz" --grid 6x6 --levels 3 --tau 0.001 --max-nodes 60 -o "$WORK/limit.ply"
expect_clean_failure 1 feshape
check "no output file" test ! -e "$WORK/limit.ply"
run feshape fit "$WORK/bump.xyz" --grid 6x6 --levels 3 --tau 0.001 --max-nodes 60 -o "$WORK/limit.ply" --partial "$WORK/part.off"
expect_clean_failure 1 feshape
expect_stderr_has "written to"
check "no output file" test ! -e "$WORK/limit.ply"
check "the partial level is closed" awk 'NR == 2 { exit !($2 == 2 * $1 - 4 && $1 <= 60) }' "$WORK/part.off"

case_ "standard input and gzip-compressed rows give the same model as the file"
run feshape fit "$WORK/sphere.xyz" --levels 1 -o "$WORK/file.ply"
run_stdin "$WORK/sphere.xyz" feshape fit --levels 1
expect_status 0
check "stdin = file" cmp "$out" "$WORK/file.ply"
gzip -c "$WORK/sphere.xyz" >"$WORK/sphere.xyz.gz"
run feshape fit "$WORK/sphere.xyz.gz" --levels 1 -o "$WORK/gz.ply"
expect_status 0
check "gzip = file" cmp "$WORK/gz.ply" "$WORK/file.ply"

case_ "--help, --version, unknown flag"
run feshape --help
expect_status 0
check "usage" grep -q "Usage" "$out"
run feshape --version
expect_status 0
check "names fest" grep -q "(fest)" "$out"
run feshape fit --no-such-flag
expect_clean_failure 2 feshape

case_ "Makefile.inc: make NAME.feshape.ply from NAME.xyz"
if command -v make >/dev/null; then
  mkdir -p "$WORK/mk"
  cp "$WORK/sphere.xyz" "$WORK/mk/ball.xyz"
  printf 'FEST_BIN := %s\ninclude %s\nFESHAPE_FLAGS := --levels 1\nall: ball.feshape.ply\n' "$FEST_BIN" \
    "$(cd "$(dirname "$0")/../.." && pwd)/Makefile.inc" >"$WORK/mk/Makefile"
  check "make" make -s -C "$WORK/mk"
  check "report written" jq -e '.levels | length >= 2' "$WORK/mk/ball.feshape.ply.json"
fi

finish
