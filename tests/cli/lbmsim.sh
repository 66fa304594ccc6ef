#!/usr/bin/env bash
# lbmsim end to end: Poiseuille's exact TRT profile through the probes, the frame stream
# and VTI series layout, thread/rank determinism, the unit table, golden fields, voxelize,
# and bad input (message and exit status).
. "$(dirname "$0")/lib.sh"
G="$(dirname "$0")/lbmsim"

# Plane Poiseuille flow between halfway walls at y = 0 and y = 8 (TRT, Lambda = 3/16):
# u(y) = g/(2 nu) y (8 - y) at the node centres y = j + 1/2, exactly.
cat >"$WORK/poiseuille.json" <<'JSON'
{ "size": [4, 8], "collision": { "model": "trt", "tau": 0.8 },
  "faces": { "y-": "wall", "y+": "wall" }, "force": [1e-6, 0],
  "probes": [[1, 0.5], [1, 1.5], [1, 2.5], [1, 3.5], [1, 4.5], [1, 5.5], [1, 6.5], [1, 7.5]],
  "check_every": 6000, "steps": 6000 }
JSON
case_ "Poiseuille with TRT: the probes read the closed-form parabola to 1e-9"
run lbmsim run "$WORK/poiseuille.json" -o "$WORK/p.vti" --probes "$WORK/p.csv" --threads 1
expect_status 0
check "probe rows" test "$(grep -c '^6000,' "$WORK/p.csv")" -eq 8
check "parabola" awk -F, 'NR > 1 && $1 == 6000 { y = $5; e = 1e-6 / (2 * 0.1) * y * (8 - y);
    d = ($8 - e) / e; if (d < 0) d = -d; if (d > 1e-9) bad = 1 } END { exit bad }' "$WORK/p.csv"

case_ "Poiseuille with the incompressible equilibrium: the same closed-form parabola to 1e-9"
sed 's/"tau": 0.8 }/"tau": 0.8, "equilibrium": "incompressible" }/' "$WORK/poiseuille.json" >"$WORK/poiseuille_inc.json"
run lbmsim run "$WORK/poiseuille_inc.json" -o "$WORK/p.vti" --probes "$WORK/pi.csv" --threads 1
expect_status 0
check "parabola" awk -F, 'NR > 1 && $1 == 6000 { y = $5; e = 1e-6 / (2 * 0.1) * y * (8 - y);
    d = ($8 - e) / e; if (d < 0) d = -d; if (d > 1e-9) bad = 1; n++ } END { exit bad || n != 8 }' "$WORK/pi.csv"

cat >"$WORK/cav.json" <<'JSON'
{ "size": [32, 32], "re": 100, "u_ref": 0.1,
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0] } } },
  "steps": 2000, "output": { "every": 1000, "fields": ["density", "velocity"], "precision": "float64" } }
JSON
case_ "frame stream: complete NRRD frames with the fest-frame header (man 5 fest-frame)"
run lbmsim run "$WORK/cav.json" --threads 1
expect_status 0
check "3 frames" test "$(grep -ac '^# fest-frame: ' "$out")" -eq 3
check "frame header" grep -aqx '# fest-frame: index=1000 time=1000 fields=density:1,velocity:3' "$out"
check "channel axis first" grep -aqx 'sizes: 4 32 32' "$out"

case_ "VTI series with a ParaView collection"
run lbmsim run "$WORK/cav.json" -o "$WORK/series/f%05d.vti" --threads 1
expect_status 0
check "three files" test -f "$WORK/series/f00000.vti" -a -f "$WORK/series/f01000.vti" -a -f "$WORK/series/f02000.vti"
check "pvd lists them" grep -q 'timestep="2000" group="" part="0" file="f02000.vti"' "$WORK/series/series.pvd"
check "zlib" grep -aq 'compressor="vtkZLibDataCompressor"' "$WORK/series/f02000.vti"

case_ "golden: D2Q9 cavity N = 32, 2000 steps, speed (max abs 1e-12)"
run lbmsim run "$WORK/cav.json" -o "$WORK/g.nrrd" --every 0 --fields speed --set output.precision=float64 --threads 1
expect_status 0
run fcompare --tol 1e-12 "$G/cavity32_speed.nrrd" "$WORK/g_speed.nrrd"
expect_status 0

case_ "restart: 1000 steps, init.file, 1000 more steps is the 2000-step field up to the lost non-equilibrium part"
run lbmsim run "$WORK/cav.json" --steps 1000 --every 0 -o "$WORK/half.vti" --threads 1
expect_status 0
cat >"$WORK/restart.json" <<'JSON'
{ "size": [32, 32], "re": 100, "u_ref": 0.1,
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0] } } },
  "init": { "file": "half.vti" }, "steps": 1000, "output": { "precision": "float64" } }
JSON
run lbmsim run "$WORK/restart.json" --every 0 --fields speed -o "$WORK/r.nrrd" --threads 1
expect_status 0
run fcompare --tol 1e-4 "$G/cavity32_speed.nrrd" "$WORK/r_speed.nrrd"
expect_status 0
case_ "bad input: init.file of another size"
echo '{ "size": [16, 16], "collision": { "tau": 0.6 }, "init": { "file": "half.vti" }, "steps": 1 }' >"$WORK/r2.json"
run lbmsim run "$WORK/r2.json" -o "$WORK/x.vti"
expect_clean_failure 3 lbmsim
expect_stderr_has 'init.file is 32x32x1 but size is 16x16x1'

case_ "determinism: 1 and 2 threads give identical bytes"
cat >"$WORK/c3.json" <<'JSON'
{ "size": [20, 20, 20], "re": 100, "u_ref": 0.1, "collision": { "model": "trt" },
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0, 0] } }, "z-": "wall", "z+": "wall" },
  "geometry": [ { "sphere": { "center": [10, 7, 10], "radius": 3 } } ], "forces": [1],
  "steps": 100, "output": { "fields": ["velocity", "qcriterion"], "precision": "float64" } }
JSON
run lbmsim run "$WORK/c3.json" -o "$WORK/t1.vti" --forces "$WORK/t1.csv" --threads 1
run lbmsim run "$WORK/c3.json" -o "$WORK/t2.vti" --forces "$WORK/t2.csv" --threads 2
expect_status 0
check "same field bytes" cmp "$WORK/t1.vti" "$WORK/t2.vti"
check "same forces" cmp "$WORK/t1.csv" "$WORK/t2.csv"

# The MPI cases (2, 3, 4 ranks) are in lbmsim_mpi.sh, skipped there when the build has no MPI.
if "$FEST_BIN/lbmsim" --version | grep -q "without MPI"; then
  case_ "a build without MPI refuses a launch on several ranks"
  OMPI_COMM_WORLD_SIZE=2 "$FEST_BIN/lbmsim" run "$WORK/cav.json" --steps 1 -o "$WORK/x.vti" >"$out" 2>"$err"
  rc=$?
  expect_clean_failure 2 lbmsim
  expect_stderr_has 'built without MPI; it cannot run on 2 ranks'
fi

case_ "info: the unit table with Re, Ma and tau"
run lbmsim info "$WORK/cav.json"
expect_status 0
check "Re" grep -q '^Re  *100$' "$out"
check "tau" grep -q 'tau 0.596' "$out"
check "Ma" grep -q '^Ma  *0.1732' "$out"
cat >"$WORK/phys.json" <<'JSON'
{ "size": [100, 50], "steps": 10,
  "units": { "dx": 0.001, "u_phys": 0.5, "u_lattice": 0.05, "nu_phys": 1e-6, "rho_phys": 1000 } }
JSON
run lbmsim info "$WORK/phys.json" --json
expect_status 0
# dt = dx u_lat / u_phys = 1e-4 s; nu_lat = 1e-6 * 1e-4 / 1e-6 = 1e-4; tau = 0.5003; Re = 0.05*100/1e-4
expect_json '.dt' '0.0001'
expect_json '(.tau * 1e6 | round)' '500300'
expect_json '(.re | round)' '50000'

case_ "info names the incompressible equilibrium and the curved walls"
sed 's/"re": 100,/"re": 100, "collision": { "equilibrium": "incompressible" }, "curved_walls": "bouzidi",/' "$WORK/cav.json" >"$WORK/cav_inc.json"
run lbmsim info "$WORK/cav_inc.json"
expect_status 0
check "equilibrium" grep -q 'incompressible equilibrium$' "$out"
check "walls" grep -q '^walls .*Bouzidi' "$out"

case_ "voxelize: a closed octahedron"
cat >"$WORK/oct.off" <<'MESH'
OFF
6 8 0
1 0 0
-1 0 0
0 1 0
0 -1 0
0 0 1
0 0 -1
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
MESH
run lbmsim voxelize "$WORK/oct.off" --size 8,8,8 --margin 0 -o "$WORK/oct.nrrd"
expect_status 0
check "uint8 volume" grep -aq '^type: uint8' "$WORK/oct.nrrd"

case_ "bad input: open mesh"
head -n 15 "$WORK/oct.off" | sed 's/^6 8 0/6 7 0/' >"$WORK/open.off"
run lbmsim voxelize "$WORK/open.off" --size 8,8,8
expect_clean_failure 3 lbmsim
expect_stderr_has 'not closed: 3 boundary edges'

case_ "bad input: empty case"
run_stdin /dev/null lbmsim run
expect_clean_failure 3 lbmsim
case_ "bad input: invalid JSON"
echo '{ "size": [8, 8], ' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
case_ "bad input: unknown key with a hint"
echo '{ "size": [8, 8], "colision": { "tau": 0.6 }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'case key "colision" is unknown \(did you mean "collision"\?\)'
case_ "bad input: tau <= 1/2"
echo '{ "size": [8, 8], "collision": { "tau": 0.5 }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'tau = 0.5 gives zero viscosity; need tau > 0.5'
case_ "bad input: Mach number above 0.3"
echo '{ "size": [8, 8], "collision": { "tau": 0.6 }, "faces": { "y-": "wall", "y+": { "moving": { "u": [0.3, 0] } } }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'Mach number 0.52'
case_ "bad input: size with one entry"
echo '{ "size": [8], "collision": { "tau": 0.6 }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
case_ "bad input: inlet on a periodic axis"
echo '{ "size": [8, 8], "collision": { "tau": 0.6 }, "faces": { "x-": { "velocity": { "u": 0.05 } } }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'periodic face needs a periodic opposite face'
case_ "bad input: curved_walls neither halfway nor bouzidi"
echo '{ "size": [8, 8], "collision": { "tau": 0.6 }, "curved_walls": "bouzidy", "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'case key "curved_walls" must be halfway or bouzidi'
case_ "bad input: collision.equilibrium misspelt"
echo '{ "size": [8, 8], "collision": { "tau": 0.6, "equilibrium": "incompresible" }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'collision.equilibrium" = "incompresible" must be compressible or incompressible'
case_ "bad input: collision.equilibrium not a string"
echo '{ "size": [8, 8], "collision": { "tau": 0.6, "equilibrium": 0 }, "steps": 1 }' >"$WORK/bad.json"
run lbmsim run "$WORK/bad.json"
expect_clean_failure 3 lbmsim
expect_stderr_has 'collision.equilibrium'
case_ "bad input: unknown field"
run lbmsim run "$WORK/cav.json" --fields velocty -o "$WORK/x%d.vti"
expect_clean_failure 3 lbmsim
expect_stderr_has 'did you mean "velocity"'
case_ "usage: an unstable value given by --set"
run lbmsim run "$WORK/cav.json" --set collision.tau=0.5 -o "$WORK/x%d.vti"
expect_clean_failure 2 lbmsim
expect_stderr_has 'collision.tau = 0.5 gives zero viscosity'
case_ "usage: several frames need a %d"
run lbmsim run "$WORK/cav.json" -o "$WORK/one.vti"
expect_clean_failure 2 lbmsim
case_ "I/O: an output folder that cannot be created"
run lbmsim run "$WORK/cav.json" --steps 1 -o /proc/nonexistent/f%d.vti
expect_clean_failure 4 lbmsim
case_ "run time: a diverging run stops with status 1 and writes no frame"
echo '{ "size": [64, 64], "collision": { "tau": 0.5002 }, "u_ref": 0.17,
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.17, 0] } } }, "steps": 20000 }' >"$WORK/div.json"
run lbmsim -q run "$WORK/div.json"
expect_clean_failure 1 lbmsim
expect_stderr_has 'non-finite|lattice speed'

finish
