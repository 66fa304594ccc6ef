#!/usr/bin/env bash
# lemtrace end to end: analytic paths on gen grids (the helix x' = -y, y' = x, z' = 0.05
# has the closed form r = r0, angle = t, z = z0 + 0.05 t), golden files, every input
# format, and bad input with clean errors.
. "$(dirname "$0")/lib.sh"
GOLDEN="$(dirname "$0")/lemtrace"

# A CSV of traced points (line,seed,i,x,y,z,t,...) from seeds (r0, 0, z0) on the helix:
# prints the largest distance from the closed form.
helix_error() {
  awk -F, -v z0="$2" 'NR > 1 { r0 = $2; x = r0 * cos($7); y = r0 * sin($7); z = z0 + 0.05 * $7;
    d = sqrt(($4 - x)^2 + ($5 - y)^2 + ($6 - z)^2); if (d > m) m = d } END { printf "%.3g\n", m + 0 }' "$1"
}
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 <= b + 0) }'; }

case_ "gen helix, trace seeds given as CSV with ids = radii: closed form to 1e-10"
run lemtrace gen helix --n 8 --jitter 0.2 --seed 3 -o "$WORK/helix.vtu"
expect_status 0
printf 'x,y,z,id\n0.25,0,-0.9,0.25\n0.4,0,-0.9,0.4\n0.55,0,-0.9,0.55\n0.7,0,-0.9,0.7\n0.85,0,-0.9,0.85\n' >"$WORK/seeds.csv"
run lemtrace "$WORK/helix.vtu" "$WORK/seeds.csv"
expect_status 0
check "header" test "$(head -1 "$out")" = "line,seed,i,x,y,z,t,cell,type,speed"
cp "$out" "$WORK/lines.csv"
err_lem=$(helix_error "$WORK/lines.csv" -0.9)
check "LEM error $err_lem <= 1e-10" below "$err_lem" 1e-10
check "every line reaches z = 1 at t = 38" test "$(awk -F, 'NR > 1 && ($6 - 1)^2 < 1e-24 && ($7 - 38)^2 < 1e-18' "$WORK/lines.csv" | wc -l)" -eq 5

case_ "the same grid as hexahedra (split by lemtrace) and as legacy .vtk on standard input"
run lemtrace gen helix --n 8 --jitter 0.2 --seed 3 --hex --to vtk -o "$WORK/helix_hex.vtk"
expect_status 0
"$FEST_BIN/lemtrace" - --seed-point 0.4,0,-0.9 <"$WORK/helix_hex.vtk" | sed 's/^0,0,/0,0.4,/' >"$WORK/hex.csv"
err_hex=$(helix_error "$WORK/hex.csv" -0.9)
check "hex grid error $err_hex <= 1e-10" below "$err_hex" 1e-10

case_ "RK4 at 0.2 cell lengths is worse than the LEM, Euler worse still"
run lemtrace "$WORK/helix.vtu" "$WORK/seeds.csv" --method rk4
expect_status 0
err_rk4=$(helix_error "$out" -0.9)
run lemtrace "$WORK/helix.vtu" "$WORK/seeds.csv" --method euler
err_euler=$(helix_error "$out" -0.9)
check "lem $err_lem < rk4 $err_rk4 < euler $err_euler" below "$err_lem" "$err_rk4"
check "rk4 < euler" below "$err_rk4" "$err_euler"

case_ "VTK PolyData output with the arrays of vtkStreamTracer"
run lemtrace "$WORK/helix.vtu" "$WORK/seeds.csv" --seed-point 5,5,5 -o "$WORK/lines.vtp"
expect_status 0
expect_stdout_empty
for a in IntegrationTime CellId Speed Velocity SeedId ReasonForTermination NumberOfCells; do
  check "array $a" grep -q "Name=\"$a\"" "$WORK/lines.vtp"
done
run fconv --info "$WORK/lines.vtp"
expect_json '.cells' '5'

case_ "reasons: out of domain, out of time, out of steps, not initialized (JSON output)"
run lemtrace "$WORK/helix.vtu" --seed-point 0.5,0,-0.9 --seed-point 0.5,0,-0.9 --seed-point 0.5,0,-0.9 \
  --seed-point 3,0,0 --to json --max-time 100
expect_status 0
expect_json '[.[].reason]' '[1,1,1,2]'
run lemtrace "$WORK/helix.vtu" --seed-point 0.5,0,-0.9 --to json --max-time 2
expect_json '.[0].reason' '8'
expect_json '.[0].points[-1][3]' '2'
run lemtrace "$WORK/helix.vtu" --seed-point 0.5,0,-0.9 --to json --max-steps 7
expect_json '.[0].reason' '5'
expect_json '.[0].cells' '7'

case_ "backward from the end returns to the seed; both directions join at the seed"
run lemtrace "$WORK/helix.vtu" --seed-point 0.5,0,0 --direction both --to json
expect_status 0
expect_json '.[0].points[0][2]' '-1'
expect_json '.[0].points[-1][2]' '1'

case_ "gen rotation in .vtk, spiral and saddle: exact; report counts"
for kind in rotation spiral saddle jordan shear; do
  "$FEST_BIN/lemtrace" gen $kind --n 5 --jitter 0.15 -o "$WORK/$kind.vtu"
  run lemtrace "$WORK/$kind.vtu" --seed-point 0.3,0.2,0.1 --report "$WORK/$kind.json" --max-time 5
  expect_status 0
  check "$kind report" jq -e '.seeds == 1 and .tetrahedra == 750' "$WORK/$kind.json"
done

case_ "image data (.vti) is split 6 tets per voxel"
run lemtrace gen uniform --n 2 -o "$WORK/u.vtu"
cat >"$WORK/img.vtk" <<'VTK'
# vtk DataFile Version 3.0
uniform flow on an image grid
ASCII
DATASET STRUCTURED_POINTS
DIMENSIONS 3 3 3
ORIGIN 0 0 0
SPACING 0.5 0.5 0.5
POINT_DATA 27
VECTORS v double
VTK
for i in $(seq 27); do echo "1 0.5 0.25" >>"$WORK/img.vtk"; done
run fconv "$WORK/img.vtk" -o "$WORK/img.vti"
expect_status 0
run lemtrace "$WORK/img.vti" --seed-point 0,0.1,0.1 --report "$WORK/img.json"
expect_status 0
check "48 tets" jq -e '.tetrahedra == 48 and .split_cells == 8' "$WORK/img.json"
# x = t, y = 0.1 + 0.5 t, z = 0.1 + 0.25 t: x reaches 1 first, at t = 1.
check "leaves at x = 1, t = 1" test "$(tail -1 "$out" | awk -F, '{ printf "%.12f %.12f %.12f %.12f", $4, $5, $6, $7 }')" = "1.000000000000 0.600000000000 0.350000000000 1.000000000000"

case_ "curvilinear structured grid (.vts): hexahedra split, linear field, LEM = RK45(1e-13)"
cat >"$WORK/sg.vtk" <<'VTK'
# vtk DataFile Version 3.0
curvilinear
ASCII
DATASET STRUCTURED_GRID
DIMENSIONS 3 2 2
POINTS 12 double
0 0 0
0.5 0.1 0
1 0 0
0 1 0
0.5 1.1 0
1 1 0
0 0 1
0.5 0.1 1
1 0 1
0 1 1
0.5 1.1 1
1 1 1
POINT_DATA 12
VECTORS v double
VTK
# v = (1.2 - 0.1 y + 0.3 z, 0.1 x + 0.05, 0.2 y + 0.1): linear, so exact in every tet.
awk 'NR >= 7 && NR <= 18 { print 1.2 - 0.1 * $2 + 0.3 * $3, 0.1 * $1 + 0.05, 0.2 * $2 + 0.1 }' "$WORK/sg.vtk" >>"$WORK/sg.vtk"
run fconv "$WORK/sg.vtk" -o "$WORK/sg.vts"
expect_status 0
run lemtrace "$WORK/sg.vts" --seed-point 0.01,0.5,0.5 --max-time 0.5 --to json --report "$WORK/sg.json"
expect_status 0
cp "$out" "$WORK/sg_lem.json"
check "12 tets from 2 hexahedra" jq -e '.tetrahedra == 12 and .split_cells == 2' "$WORK/sg.json"
run lemtrace "$WORK/sg.vts" --seed-point 0.01,0.5,0.5 --max-time 0.5 --to json --method rk45 --tol 1e-14
check "end points agree to 1e-9" jq -e --slurpfile r "$out" \
  '(.[0].points[-1]) as $a | ($r[0][0].points[-1]) as $b | ([0, 1, 2, 3] | map(($a[.] - $b[.]) | fabs) | max) < 1e-9' "$WORK/sg_lem.json"

case_ "golden: helix n=6 jitter 0.2 seed 1, ten seeds (numeric comparison, 1e-9)"
run lemtrace gen helix --n 6 --jitter 0.2 --seed 1 -o "$WORK/h6.vtu"
run lemtrace "$WORK/h6.vtu" --seed-line 0.2,0,-0.9:0.8,0.1,-0.8:10
expect_status 0
cp "$out" "$WORK/h6.csv"
run fcompare --tol 1e-9 "$WORK/h6.csv" "$GOLDEN/helix6_lines.csv"
expect_status 0
run lemtrace classify "$WORK/h6.vtu"
expect_status 0
check "classify table byte-exact" cmp -s "$out" "$GOLDEN/helix6_classify.csv"

case_ "classify: a smooth field on a jittered grid has few extraordinary cells; the sweep grows monotonically"
run lemtrace gen sphere-potential --n 10 --jitter 0.2 -o "$WORK/sp.vtu"
run lemtrace classify "$WORK/sp.vtu"
expect_status 0
check "extraordinary < 0.5 %" awk -F, '$1 == "extraordinary" { exit !($3 < 0.5) }' "$out"
run lemtrace classify "$WORK/sp.vtu" --sweep-parallel 1e-7:1e-1 --eps-mode abs
expect_status 0
check "7 rows" test "$(wc -l <"$out")" -eq 8
check "non-decreasing" awk -F, 'NR > 2 && $2 < prev { exit 1 } NR > 1 { prev = $2 }' "$out"
run lemtrace classify "$WORK/sp.vtu" -o "$WORK/cells.vtu"
check "cell arrays" grep -q 'Name="LemType"' "$WORK/cells.vtu"

case_ "bench: the table of methods"
run lemtrace bench "$WORK/helix.vtu" "$WORK/seeds.csv"
expect_status 0
check "eleven rows" test "$(wc -l <"$out")" -eq 12
check "LEM error <= 1e-10" awk -F, '$1 == "lem_precomputed" { exit !($5 <= 1e-10) }' "$out"

# Table 9.4 on the chapter's sphere data, checked on counts, not on wall time (the
# machine is shared): the comparison is at equal step count (no line short), the
# precomputed LEM needs about one closed-form evaluation and no point location per cell,
# and each RK method exactly its number of stages in field evaluations per step, each
# with at least one point-location test. Seeds at radius 0.55-0.8 keep Euler's outward
# drift inside the box [-1,1]^3 for one revolution (2 pi).
case_ "bench: Table 9.4 at equal step count (sphere-rotation)"
run lemtrace gen sphere-rotation --n 20 -o "$WORK/sphere.vtu"
expect_status 0
run lemtrace bench "$WORK/sphere.vtu" --seed-line 0.55,0,0.13:0.8,0,0.13:8 --max-time 6.283185307
expect_status 0
check "equal step count" awk -F, 'NR > 1 && $9 != 0 { exit 1 }' "$out"
check "same steps for all" awk -F, 'NR == 2 { s = $3 } NR > 2 && $3 != s { exit 1 }' "$out"
check "precomputed LEM <= 1.25 evaluations per cell" \
  awk -F, '$1 == "lem_precomputed" { exit !($8 <= 1.25) }' "$out"
check "bracket alone needs more" \
  awk -F, '$1 == "lem_precomputed" { p = $8 } $1 == "lem_bracket" { b = $8 } END { exit !(b > 2 * p) }' "$out"
check "LEM locates once per line" awk -F, '$1 ~ /^lem/ && $4 != 8 { exit 1 }' "$out"
check "RK stages per step" awk -F, '
  $1 == "euler" { e = ($8 > 1 && $8 < 1.1) } $1 == "heun" { h = ($8 > 2 && $8 < 2.1) }
  $1 == "rk3" { r3 = ($8 > 3 && $8 < 3.1) } $1 == "rk4" { r4 = ($8 > 4 && $8 < 4.1) }
  END { exit !(e && h && r3 && r4) }' "$out"
check "RK locates at least once per evaluation" \
  awk -F, '$1 ~ /^(euler|heun|rk3|rk4)$/ && $4 < $3 * $8 { exit 1 }' "$out"
check "the chapter's loop: one cell search per evaluation" \
  awk -F, '$1 ~ /_cell_search$/ { n++; if ($4 < $3 * $8 || $4 > $3 * $8 + 16) exit 1 } END { exit !(n == 4) }' "$out"
check "LEM exact, RK4 not (analytic circle)" \
  awk -F, '$1 == "lem_precomputed" { l = $5 } $1 == "rk4" { r = $5 } END { exit !(l <= 1e-12 && r > 1e-9) }' "$out"

case_ "empty seed file: header only"
: >"$WORK/empty.csv"
run lemtrace "$WORK/helix.vtu" "$WORK/empty.csv"
expect_status 0
check "header only" test "$(cat "$out")" = "line,seed,i,x,y,z,t,cell,type,speed"

case_ "streamed output: the same bytes for any thread count (CSV and JSON), atomic -o"
for to in csv json; do
  "$FEST_BIN/lemtrace" "$WORK/h6.vtu" --seed-line 0.1,0,-0.9:0.9,0.1,-0.8:300 --seed-point 5,5,5 --to $to --threads 1 >"$WORK/t1.$to"
  for th in 2 3 4; do
    run lemtrace "$WORK/h6.vtu" --seed-line 0.1,0,-0.9:0.9,0.1,-0.8:300 --seed-point 5,5,5 --to $to --threads $th \
      -o "$WORK/t$th.$to"
    expect_status 0
    check "$to, $th threads = 1 thread" cmp -s "$WORK/t1.$to" "$WORK/t$th.$to"
  done
done
check "JSON parses, 301 lines" test "$(jq length "$WORK/t1.json")" -eq 301
printf 'x,y,z\n0.1,0.1,0.1\n0.2,abc,0.1\n' >"$WORK/badseeds.csv"
echo old >"$WORK/keep.csv"
run lemtrace "$WORK/h6.vtu" "$WORK/badseeds.csv" -o "$WORK/keep.csv"
expect_clean_failure 3 lemtrace
check "bad input leaves the old file and no temporary" test "$(cat "$WORK/keep.csv")" = old
check "no temporary" test -z "$(ls "$WORK" | grep 'keep.csv.tmp')"

case_ "streamed VTP: the same file for --threads 1 and 2, and the file VTK's writer makes (fconv reads it back)"
for th in 1 2; do
  "$FEST_BIN/lemtrace" "$WORK/h6.vtu" --seed-line 0.1,0,-0.9:0.9,0.1,-0.8:300 --seed-point 5,5,5 --to vtp \
    --threads $th >"$WORK/v$th.vtp"
  # The file records the command line (field data LemtraceOptions): same length, one digit apart.
  LC_ALL=C sed "s/--threads $th/--threads N/" "$WORK/v$th.vtp" >"$WORK/v$th.n.vtp"
done
check "vtp, 2 threads = 1 thread (but for the recorded --threads)" cmp -s "$WORK/v1.n.vtp" "$WORK/v2.n.vtp"
check "vtp, the recorded command lines differ in one byte" test "$(cmp -l "$WORK/v1.vtp" "$WORK/v2.vtp" | wc -l)" -eq 1
# VTK (fconv converts through the VTK plugin) rewrites the streamed file to the same bytes.
(cd "$WORK" && "$FEST_BIN/fconv" v1.vtp --to vtp -o v1.vtk-written.vtp) 2>"$err"
check "fconv's VTK reads the streamed file" test -s "$WORK/v1.vtk-written.vtp"
check "VTK writes back the same bytes" cmp -s "$WORK/v1.vtp" "$WORK/v1.vtk-written.vtp"
run fconv --info "$WORK/v1.vtp"
expect_json '[.points, .cells]' "[$(awk -F, 'NR > 1' "$WORK/t1.csv" | wc -l),$(awk -F, 'NR > 1 { print $1 }' "$WORK/t1.csv" | sort -u | wc -l)]"

case_ "a closed pipe, a full device, a file size limit: exit 4, one line, no half-written file"
for to in csv vtp; do
  "$FEST_BIN/lemtrace" "$WORK/h6.vtu" --seed-line 0.1,0,-0.9:0.9,0.1,-0.8:300 --to $to 2>"$err" | head -c 100 >/dev/null
  rc=${PIPESTATUS[0]}
  expect_status 4
  check "$to: one line on a closed pipe" test "$(wc -l <"$err")" -eq 1
  expect_stderr_has "^lemtrace: error: cannot write: .*(standard output)"
  run lemtrace "$WORK/h6.vtu" --seed-line 0.1,0,-0.9:0.9,0.1,-0.8:300 --to $to -o /dev/full
  expect_clean_failure 4 lemtrace
  echo old >"$WORK/limited.$to"
  (ulimit -f 200 && "$FEST_BIN/lemtrace" "$WORK/h6.vtu" --seed-line 0.1,0,-0.9:0.9,0.1,-0.8:300 \
    -o "$WORK/limited.$to" >"$out" 2>"$err")
  rc=$?
  expect_clean_failure 4 lemtrace
  check "$to: the old file is left as it was" test "$(cat "$WORK/limited.$to")" = old
  check "$to: no temporary left" test -z "$(ls -A "$WORK" | grep 'limited\.'"$to"'\..')"
done

# ---- bad input -------------------------------------------------------------------------
tet_grid() {  # $1 = point data section
  cat <<VTK
# vtk DataFile Version 3.0
two tets
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 5 double
0 0 0
1 0 0
0 1 0
0 0 1
1 1 1
CELLS 2 10
4 0 1 2 3
4 1 2 3 4
CELL_TYPES 2
10
10
$1
VTK
}
tet_grid "CELL_DATA 2
VECTORS u double
1 0 0
1 0 0" >"$WORK/celldata.vtk"
case_ "cell-data vectors"
run lemtrace "$WORK/celldata.vtk" --seed-point 0.1,0.1,0.1
expect_clean_failure 3 lemtrace
expect_stderr_has "cell data; lemtrace needs point vectors"

tet_grid "POINT_DATA 5
FIELD f 2
a 3 5 double
1 0 0 1 0 0 1 0 0 1 0 0 1 0 0
b 3 5 double
0 1 0 0 1 0 0 1 0 0 1 0 0 1 0" >"$WORK/ambiguous.vtk"
case_ "ambiguous vector arrays"
run lemtrace "$WORK/ambiguous.vtk" --seed-point 0.1,0.1,0.1
expect_clean_failure 3 lemtrace
expect_stderr_has "several 3-component point arrays \(a, b\)"
case_ "missing array named by --vectors; then the right one"
run lemtrace "$WORK/ambiguous.vtk" --seed-point 0.1,0.1,0.1 --vectors U
expect_clean_failure 3 lemtrace
expect_stderr_has "no point array named 'U'"
run lemtrace "$WORK/ambiguous.vtk" --seed-point 0.1,0.1,0.1 --vectors b
expect_status 0

tet_grid "POINT_DATA 5
FIELD f 1
uv 2 5 double
1 0 1 0 1 0 1 0 1 0" >"$WORK/twocomp.vtk"
case_ "2-component vectors"
run lemtrace "$WORK/twocomp.vtk" --seed-point 0.1,0.1,0.1 --vectors uv
expect_clean_failure 3 lemtrace
expect_stderr_has "2 components"

sed 's/^1 1 1$/0.5 0.5 0/' "$WORK/ambiguous.vtk" >"$WORK/flat.vtk"
case_ "zero-volume tetrahedron"
run lemtrace "$WORK/flat.vtk" --seed-point 0.1,0.1,0.1 --vectors a
expect_clean_failure 3 lemtrace
expect_stderr_has "tetrahedron 1 .* zero volume"

sed -e 's/^CELL_TYPES 2$/CELL_TYPES 2/' -e '/^4 1 2 3 4$/s/.*/3 1 2 3/' -e 's/^CELLS 2 10$/CELLS 2 9/' "$WORK/ambiguous.vtk" |
  awk 'BEGIN { n = 0 } /^10$/ { n++; if (n == 2) { print "5"; next } } { print }' >"$WORK/triangle.vtk"
case_ "unsupported cell type"
run lemtrace "$WORK/triangle.vtk" --seed-point 0.1,0.1,0.1 --vectors a
expect_clean_failure 3 lemtrace
expect_stderr_has "triangle \(VTK type 5\)"

case_ "--split none refuses hexahedra, naming the flag"
run lemtrace "$WORK/helix_hex.vtk" --seed-point 0.1,0.1,0.1 --split none
expect_clean_failure 3 lemtrace
expect_stderr_has "cell 0 is a VTK type 12 cell and --split none accepts only tetrahedra"

case_ "non-finite vectors"
run fconv "$WORK/ambiguous.vtk" --ascii -o "$WORK/finite.vtu"
sed '0,/1 0 0 1 0 0/s//1 0 0 nan 0 0/' "$WORK/finite.vtu" >"$WORK/nan.vtu"
run lemtrace "$WORK/nan.vtu" --seed-point 0.1,0.1,0.1 --vectors a
expect_clean_failure 3 lemtrace
expect_stderr_has "non-finite value \(nan\) at point 1"

case_ "truncated .vtu"
head -c 3000 "$WORK/helix.vtu" >"$WORK/cut.vtu"
run lemtrace "$WORK/cut.vtu" --seed-point 0.1,0.1,0.1
expect_clean_failure 3 lemtrace

case_ "seed CSV with text on line 3"
printf 'x,y,z\n0.1,0.1,0.1\n0.2,abc,0.1\n' >"$WORK/badseeds.csv"
run lemtrace "$WORK/helix.vtu" "$WORK/badseeds.csv"
expect_clean_failure 3 lemtrace
expect_stderr_has "line 3"

case_ "seed table without z"
printf 'x,y\n0.1,0.1\n' >"$WORK/noz.csv"
run lemtrace "$WORK/helix.vtu" "$WORK/noz.csv"
expect_clean_failure 3 lemtrace

case_ "usage errors"
run lemtrace "$WORK/helix.vtu" --method rk9
expect_clean_failure 2 lemtrace
run lemtrace "$WORK/helix.vtu" --seed-line 0,0,0:1,1
expect_clean_failure 2 lemtrace
run lemtrace gen vortex
expect_clean_failure 2 lemtrace
run lemtrace "$WORK/helix.vtu" --seed-point 0,0,0 -o "$WORK/out.xyz"
expect_clean_failure 2 lemtrace

case_ "missing file"
run lemtrace "$WORK/nope.vtu" --seed-point 0,0,0
expect_clean_failure 4 lemtrace

case_ "a mesh is not a grid"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$WORK/tri.off"
run lemtrace "$WORK/tri.off" --seed-point 0,0,0
expect_clean_failure 3 lemtrace

finish
