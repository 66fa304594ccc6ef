#!/usr/bin/env bash
# lemtrace on a flow field nobody in this project computed: DOLFIN's Stokes velocity
# (dolfin-doc, fetched by scripts/fetch-test-data.sh), a P2 field on a 2-D triangle mesh,
# turned by tests/tools/dolfin_to_vtk.sh into a slab of wedges (split by lemtrace into
# tetrahedra) and then into .vtu. Checks that need no reference solution: paths stay in
# their plane (the field has no z component), the LEM agrees with RK45 at a tight
# tolerance on the same piecewise-linear field (two independent integrators), every line
# ends for a stated reason, and the no-slip walls show up as critical points.
. "$(dirname "$0")/lib.sh"
mesh=$(need_testdata cfd/dolfin_fine_mesh.xml.gz) || exit 77
velocity=$(need_testdata cfd/dolfin_fine_velocity.xml.gz) || exit 77
TOOLS="$(dirname "$0")/../tools"

case_ "convert the DOLFIN data to .vtu"
check "converter" bash -c 'bash "$1" "$2" "$3" 0.05 >"$4"' _ "$TOOLS/dolfin_to_vtk.sh" "$mesh" "$velocity" "$WORK/dolfin.vtk"
run fconv "$WORK/dolfin.vtk" -o "$WORK/dolfin.vtu"
expect_status 0
run fconv --info "$WORK/dolfin.vtu"
expect_json '.cells' '5400'
expect_json '.bbox.max' '[1,1,0.05]'

case_ "classify: wedges split into 3 tets each; walls carry critical points"
run lemtrace classify "$WORK/dolfin.vtu"
expect_status 0
check "16200 tets" grep -qx "total,16200,100.0000" "$out"
check "some cells hold a critical point (no-slip walls)" awk -F, '$1 == "critical_point_inside" { exit !($2 > 0) }' "$out"

case_ "trace 9 seeds for 0.4 time units: in-plane, out_of_time, LEM = RK45(1e-13) to 1e-6"
seeds="0.98,0.1,0.025:0.98,0.9,0.025:9"
run lemtrace "$WORK/dolfin.vtu" --seed-line "$seeds" --max-time 0.4 --to json --report "$WORK/r.json"
expect_status 0
cp "$out" "$WORK/lem.json"
expect_json '[.[].reason] | unique' '[8]'
check "paths stay at z = 0.025" jq -e '[.[].points[][2] - 0.025 | fabs] | max < 1e-12' "$WORK/lem.json"
check "report: 9 seeds, split wedges" jq -e '.seeds == 9 and .split_cells == 5400 and .tetrahedra == 16200' "$WORK/r.json"
run lemtrace "$WORK/dolfin.vtu" --seed-line "$seeds" --max-time 0.4 --to json --method rk45 --tol 1e-13
expect_status 0
cp "$out" "$WORK/rk45.json"
# The field is only continuous across faces, which bounds RK45's accuracy, not the LEM's.
check "end points agree" jq -e --slurpfile r "$WORK/rk45.json" \
  '[range(length) as $i | (.[$i].points[-1][0:3]) as $a | ($r[0][$i].points[-1][0:3]) as $b |
    ([0, 1, 2] | map(($a[.] - $b[.]) | fabs) | max)] | max < 1e-6' "$WORK/lem.json"

case_ "both directions from the inflow side: every line stops for a reason, nothing non-finite"
run lemtrace "$WORK/dolfin.vtu" --seed-line 0.5,0.02,0.025:0.5,0.98,0.025:40 --direction both -o "$WORK/lines.vtp"
expect_status 0
check "polylines written" grep -q 'Name="ReasonForTermination"' "$WORK/lines.vtp"

finish
