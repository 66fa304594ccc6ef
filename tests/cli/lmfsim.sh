#!/usr/bin/env bash
# lmfsim end to end: generated scenes, analytic answers (pendulum half period, reduced
# references), topology reports, export to ParaView files, and bad input.
. "$(dirname "$0")/lib.sh"

L="$FEST_BIN/lmfsim"
near() {  # near VALUE EXPECTED TOL
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'
}

case_ "--help lists the subcommands"
run lmfsim --help
expect_status 0
if grep -q "reduced" "$out" && grep -q "export" "$out"; then pass; else fail "help lacks subcommands"; fi

case_ "check: double particle pendulum has 4 DOF (two spherical joints)"
"$L" gen chain --n 2 --type particle > "$WORK/dp.json"
run_stdin "$WORK/dp.json" lmfsim check
expect_status 0
expect_json '.dof' '4'
expect_json '.rank_deficiency' '0'
expect_json '.auxiliary_rows' '0'

case_ "check: planar four-bar of hinges has one DOF and three redundant rows"
"$L" gen fourbar --omega0 2 > "$WORK/fb.json"
run_stdin "$WORK/fb.json" lmfsim check
expect_status 0
expect_json '.dof' '1'
expect_json '.rank_deficiency' '3'
expect_json '.auxiliary_rows' '5'

case_ "run: a 90-degree pendulum is at the far side after half its period (T = 2.367842 s)"
"$L" gen chain --n 1 --type particle --angle 90 > "$WORK/p.json"
# Half period 1.183921 s; the 1184th step lands 7.9e-5 s later (displacement ~3e-8 m).
run_stdin "$WORK/p.json" lmfsim run --t-end 1.184 --every 1184
expect_status 0
px=$(awk -F, '$1==1 {print $4}' "$out"); pz=$(awk -F, '$1==1 {print $6}' "$out")
if near "$px" -1 1e-5 && near "$pz" 0 1e-5; then pass; else fail "tip at ($px, $pz), expected (-1, 0)"; fi

case_ "run agrees with the reduced-coordinate double pendulum (chaotic start, 3 s)"
"$L" gen chain --n 2 --type particle --planar > "$WORK/dpp.json"
"$L" run --t-end 3 < "$WORK/dpp.json" > "$WORK/lmf.csv"
"$L" reduced --chain --dt 1e-4 --t-end 3 < "$WORK/dpp.json" > "$WORK/ref.csv"
run lmfsim diff "$WORK/lmf.csv" "$WORK/ref.csv" --at 3
expect_status 0
d=$(jq '.max_pos' "$out")
if near "$d" 0 1e-6; then pass; else fail "max position difference $d m"; fi

# Every integrator and stabilisation against the reduced reference (tolerances from their
# orders at h = 1e-3: rk45 adaptive to 1e-8, rk4 ~1e-8, first-order Euler variants ~1e-2).
for spec in "--integrator rk45:1e-7" "--stab force:1e-7" "--stab project:1e-7" "--stab none:1e-7" \
            "--solver dense:1e-7" "--integrator symplectic:0.1" "--integrator euler --max-violation 1:0.2"; do
  opts="${spec%%:*}"; tol="${spec##*:}"
  case_ "run $opts agrees with the reduced double pendulum at t = 3 s within $tol m"
  # shellcheck disable=SC2086
  "$L" run --t-end 3 $opts < "$WORK/dpp.json" > "$WORK/opt.csv"
  run lmfsim diff "$WORK/opt.csv" "$WORK/ref.csv" --at 3
  d=$(jq '.at.max_pos' "$out")
  if near "$d" 0 "$tol"; then pass; else fail "difference $d m"; fi
done

case_ "run agrees with the reduced four-bar (loop through auxiliary rows, 2 s)"
# RK4 error at h = 1e-3 is 1.9e-6 m here (fourth order: 1.3e-7 at 5e-4), so half the step.
"$L" run --t-end 2 --dt 5e-4 --every 20 < "$WORK/fb.json" > "$WORK/fb_lmf.csv"
"$L" reduced --fourbar --dt 1e-4 --t-end 2 < "$WORK/fb.json" > "$WORK/fb_ref.csv"
run lmfsim diff "$WORK/fb_lmf.csv" "$WORK/fb_ref.csv"
expect_status 0
d=$(jq '.max_pos' "$out")
if near "$d" 0 1e-6; then pass; else fail "max position difference $d m"; fi

case_ "dense and baraff solvers give the same trajectory"
"$L" gen chain --n 5 --angle 60 > "$WORK/c5.json"
"$L" run --t-end 0.5 --solver dense < "$WORK/c5.json" > "$WORK/dense.csv"
"$L" run --t-end 0.5 --solver baraff < "$WORK/c5.json" > "$WORK/baraff.csv"
run lmfsim diff "$WORK/dense.csv" "$WORK/baraff.csv"
d=$(jq '.max_pos' "$out")
if near "$d" 0 1e-8; then pass; else fail "dense vs baraff $d m"; fi

case_ "diag, forces and report side files"
run_stdin "$WORK/p.json" lmfsim run --t-end 0.5 --diag "$WORK/diag.csv" --forces "$WORK/forces.csv" --report "$WORK/rep.json"
expect_status 0
if [ "$(head -1 "$WORK/diag.csv")" = "frame,t,T,U,E,drift_rel,C_max,Cdot_max,Cv_max,rows,rank_def,solve_us" ]; then pass; else fail "diag header"; fi
if [ "$(jq '.steps' "$WORK/rep.json")" = "500" ]; then pass; else fail "report steps $(jq '.steps' "$WORK/rep.json")"; fi
# Rod tension at the start (horizontal, at rest) is m (g cos 90 + L w^2) = 0.
lam=$(awk -F, '$1==0 && $3=="constraint" {print $6}' "$WORK/forces.csv")
if near "$lam" 0 1e-9; then pass; else fail "initial tension $lam"; fi

case_ "export writes a ParaView series: one .vtp per frame with every body's triangles"
"$L" run --t-end 0.1 --every 50 < "$WORK/fb.json" | "$L" export --scene "$WORK/fb.json" --vtk "$WORK/vtk"
rc=$?; expect_status 0
if [ -f "$WORK/vtk/scene.pvd" ] && [ "$(ls "$WORK/vtk"/frame_*.vtp | wc -l)" = 3 ]; then pass; else fail "missing export files"; fi
run fconv --info "$WORK/vtk/frame_000002.vtp"
expect_json '.cells' '36'
"$L" run --t-end 0.1 --every 50 < "$WORK/fb.json" | "$L" export --scene "$WORK/fb.json" --obj "$WORK/obj"
run fconv --info "$WORK/obj/frame_000001.obj"
expect_json '.faces' '36'

case_ "assemble closes a perturbed loop"
jq '.bodies[1].pos[2] += 0.01' "$WORK/fb.json" > "$WORK/fb_bad.json"
"$L" assemble < "$WORK/fb_bad.json" > "$WORK/fb_fixed.json"
run_stdin "$WORK/fb_fixed.json" lmfsim check
c=$(jq '.initial_C_max' "$out")
if near "$c" 0 1e-9; then pass; else fail "C after assemble $c"; fi

case_ "gen sleigh: the knife edge keeps the COM on a circle of radius v/omega = 2 m"
"$L" gen sleigh --omega0 0.5 > "$WORK/sleigh.json"
run_stdin "$WORK/sleigh.json" lmfsim run --t-end 5 --every 500
expect_status 0
r=$(awk -F, '$1==10 {print sqrt($4*$4 + ($5-2)*($5-2) + $6*$6)}' "$out")
if near "$r" 2 1e-7; then pass; else fail "distance from the centre $r"; fi

case_ "gen ring: an 8-link closed ring swings with its loop closed (auxiliary rows, rank deficiency 3)"
"$L" gen ring --n 8 > "$WORK/ring.json"
run_stdin "$WORK/ring.json" lmfsim check
expect_json '.rank_deficiency' '3'
run_stdin "$WORK/ring.json" lmfsim run --t-end 1 --report "$WORK/ring_rep.json"
expect_status 0
c=$(jq '.max_C' "$WORK/ring_rep.json")
if near "$c" 0 1e-6; then pass; else fail "ring max |C| $c"; fi

case_ "deterministic: two runs give byte-identical output"
"$L" run --t-end 0.3 < "$WORK/fb.json" > "$WORK/r1.csv"
"$L" run --t-end 0.3 < "$WORK/fb.json" > "$WORK/r2.csv"
if cmp -s "$WORK/r1.csv" "$WORK/r2.csv"; then pass; else fail "outputs differ"; fi

case_ "--threads: the integrator is sequential; a count above 1 is said, not silently ignored"
"$L" run --t-end 0.3 --threads 1 < "$WORK/fb.json" > "$WORK/t1.csv" 2> "$WORK/t1.err"
run_stdin "$WORK/fb.json" lmfsim run --t-end 0.3 --threads 2
expect_status 0
expect_stderr_has '^lmfsim: warning: --threads 2: the integrator is sequential and runs one thread$'
check "same trajectory" cmp -s "$WORK/t1.csv" "$out"
check "no warning for one thread" test ! -s "$WORK/t1.err"

# --- bad input: one line, right status, nothing on standard output --------------------
bad() {  # bad STATUS REGEX JSON [args]
  local status="$1" regex="$2" json="$3"; shift 3
  printf '%s' "$json" > "$WORK/bad.json"
  run_stdin "$WORK/bad.json" lmfsim "${@:-run}"
  expect_clean_failure "$status" lmfsim
  expect_stderr_has "$regex"
}
P='{"name":"p","type":"particle","mass":1,"pos":[1,0,0]}'
case_ "empty input"; bad 3 'empty' ''
case_ "JSON syntax error"; bad 3 'line 1' '{"bodies": [}'
case_ "unknown field"; bad 3 "unknown field 'colour'" "{\"bodies\":[$P],\"colour\":1}"
case_ "unknown body in a constraint"; bad 3 "unknown body 'ghost'" "{\"bodies\":[$P],\"constraints\":[{\"type\":\"distance\",\"a\":\"world\",\"b\":\"ghost\",\"length\":1}]}"
case_ "duplicate names"; bad 3 "duplicate name 'p'" "{\"bodies\":[$P,$P]}"
case_ "negative mass"; bad 3 'mass -1 must be positive' '{"bodies":[{"name":"p","type":"particle","mass":-1}]}'
case_ "non-SPD inertia"; bad 3 'not positive definite' '{"bodies":[{"name":"b","mass":1,"inertia":[[1,0,0],[0,-1,0],[0,0,1]]}]}'
case_ "non-unit quaternion"; bad 3 'must be unit' '{"bodies":[{"name":"b","mass":1,"shape":{"sphere":0.1},"quat":[0,0,0,0]}]}'
case_ "zero axis"; bad 3 'zero-length axis' '{"bodies":[{"name":"b","mass":1,"shape":{"sphere":0.1}}],"constraints":[{"type":"hinge","a":"world","b":"b","axis":[0,0,0]}]}'
case_ "distance of length 0"; bad 3 'length 0 must be positive' "{\"bodies\":[$P],\"constraints\":[{\"type\":\"distance\",\"a\":\"world\",\"b\":\"p\",\"length\":0}]}"
case_ "event with an unknown target"; bad 3 "unknown constraint or force 'm'" "{\"bodies\":[$P],\"events\":[{\"t\":1,\"action\":\"activate\",\"target\":\"m\"}]}"
case_ "--dt 0"; bad 2 'dt' "{\"bodies\":[$P]}" run --dt 0
case_ "reduced on a branched scene"; bad 2 'branched' "{\"bodies\":[$P,{\"name\":\"q\",\"type\":\"particle\",\"pos\":[-1,0,0]}],\"constraints\":[{\"type\":\"distance\",\"a\":\"world\",\"b\":\"p\",\"length\":1},{\"type\":\"distance\",\"a\":\"world\",\"b\":\"q\",\"length\":1}]}" reduced --chain
case_ "conflicting constraints report the rank deficiency (exit 1, no partial CSV)"
bad 1 'conflicting constraints.*rank deficiency 3' "{\"bodies\":[$P],\"constraints\":[{\"name\":\"a\",\"type\":\"path\",\"a\":\"p\",\"keys\":[[0,1,0,0]]},{\"name\":\"b\",\"type\":\"path\",\"a\":\"p\",\"keys\":[[0,1,0,0.5]]}]}"
case_ "a state that becomes non-finite (exit 1, no partial CSV)"
bad 1 'non-finite' "{\"bodies\":[$P],\"forces\":[{\"type\":\"constant\",\"body\":\"p\",\"force\":[1e308,1e308,0]}],\"sim\":{\"t_end\":1}}"
case_ "--stream ends a failed run with # ERROR"
printf '%s' "{\"bodies\":[$P],\"forces\":[{\"type\":\"constant\",\"body\":\"p\",\"force\":[1e308,1e308,0]}],\"sim\":{\"t_end\":1}}" > "$WORK/nan.json"
run_stdin "$WORK/nan.json" lmfsim run --stream
expect_status 1
if tail -1 "$out" | grep -q '^# ERROR'; then pass; else fail "stream lacks '# ERROR'"; fi

finish
