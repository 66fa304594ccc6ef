#!/usr/bin/env bash
# fluidsim end to end: the analytic self-checks, the frame stream's definition, exact
# interpolation, thread-count determinism, output formats, and bad input.
. "$(dirname "$0")/lib.sh"

SCENE2D="$WORK/smoke2d.json"
cat >"$SCENE2D" <<'JSON'
{ "dims": [32, 32], "frame_dt": 0.05, "frames": 10, "viscosity": 0.001,
  "scalars": [ { "name": "density", "alpha": 0.05,
                 "sources": [ { "shape": "sphere", "centre": [16, 5], "radius": 3, "rate": 10 } ] } ],
  "forces": [ { "type": "buoyancy", "scalar": "density", "beta": 1.0 } ] }
JSON
SCENE3D="$WORK/smoke3d.json"
cat >"$SCENE3D" <<'JSON'
{ "dims": [32, 32, 32], "frame_dt": 0.05, "frames": 3,
  "scalars": [ { "name": "density",
                 "sources": [ { "shape": "box", "min": [14, 14, 2], "max": [18, 18, 5], "rate": 10, "velocity": [0, 0, 0.5] } ] } ],
  "forces": [ { "type": "buoyancy", "scalar": "density", "beta": 1.0 } ] }
JSON

case_ "check all: every analytic criterion of docs/fluidsim.md §7 holds"
run fluidsim check all --threads 1
expect_status 0
expect_json '.pass' 'true'
expect_json '[.cases[].check]' '["projection","taylor-green","abc","mass","stability","interp"]'
expect_json '[.cases[] | select(.check=="taylor-green") | .error_ratios[] >= 1.5] | all' 'true'

case_ "the frame stream: one complete NRRD per frame, header as man 5 fest-frame defines it"
run fluidsim run "$SCENE2D" --threads 1
expect_status 0
check "10 frames" test "$(grep -c '^NRRD0004$' "$out")" -eq 10
check "frame 0 header" grep -qx '# fest-frame: index=0 time=0 fields=velocity:3,density:1' "$out"
check "frame 9 header" grep -qx '# fest-frame: index=9 time=0.45 fields=velocity:3,density:1' "$out"
check "channel axis first, wall nodes included" grep -qx 'sizes: 4 34 34' "$out"

case_ "two scalars: temperature drives the buoyancy, both are in the stream"
cat >"$WORK/hot.json" <<'JSON'
{ "dims": [16, 16], "frames": 3,
  "scalars": [ { "name": "density" },
               { "name": "temperature", "kappa": 0.001, "alpha": 0.1,
                 "sources": [ { "shape": "gauss", "centre": [8, 3], "radius": 2, "rate": 5 } ] } ],
  "forces": [ { "type": "buoyancy", "scalar": "temperature", "beta": 1.0, "ambient": 0.0 } ] }
JSON
run fluidsim run "$WORK/hot.json" --threads 1
expect_status 0
check "header lists both scalars" grep -qx '# fest-frame: index=2 time=0.08 fields=velocity:3,density:1,temperature:1' "$out"
cp "$out" "$WORK/hot.stream"
run fluidsim render "$WORK/hot.stream" --field temperature --mode slice -o "$WORK/hot%d.png"
expect_status 0

case_ "render reads the stream: one PNG per frame, 34x34 for a 2-D frame"
mkdir -p "$WORK/png"
"$FEST_BIN/fluidsim" run "$SCENE2D" --threads 1 | "$FEST_BIN/fluidsim" render -o "$WORK/png/f%03d.png"
check "ten images" test "$(ls "$WORK/png" | wc -l)" -eq 10
run fconv --info "$WORK/png/f009.png"
expect_json '[.width, .height, .channels]' '[34,34,3]'

case_ "interpolated frames: states exact, frame 2 = 0.6 X0 + 0.4 X1, and 'interp' agrees"
mkdir -p "$WORK/i"
run fluidsim run "$SCENE2D" --interp 5 --frames 11 --precision double --fields velocity -o "$WORK/i/f%02d.nrrd" --threads 1 --report "$WORK/i.json"
expect_status 0
check "2 simulation steps for 11 frames at K=5" test "$(jq .simulation_steps "$WORK/i.json")" -eq 2
run fluidsim interp "$WORK/i/f00_velocity.nrrd" "$WORK/i/f05_velocity.nrrd" --alpha 0.4 -o "$WORK/i/mix.nrrd"
expect_status 0
data_bytes=$((34 * 34 * 3 * 8))
check "interp equals the in-run frame 2 bit for bit" cmp <(tail -c $data_bytes "$WORK/i/mix.nrrd") <(tail -c $data_bytes "$WORK/i/f02_velocity.nrrd")
run fluidsim interp "$WORK/i/f00_velocity.nrrd" "$WORK/i/f05_velocity.nrrd" --alpha 1 -o "$WORK/i/one.nrrd"
check "alpha 1 gives the next state" cmp <(tail -c $data_bytes "$WORK/i/one.nrrd") <(tail -c $data_bytes "$WORK/i/f05_velocity.nrrd")

case_ "determinism: --threads 1 and 2 give identical bytes (3-D, parallel loops active)"
"$FEST_BIN/fluidsim" run "$SCENE3D" --threads 1 >"$WORK/t1.stream"
"$FEST_BIN/fluidsim" run "$SCENE3D" --threads 2 >"$WORK/t2.stream"
check "identical streams" cmp "$WORK/t1.stream" "$WORK/t2.stream"
"$FEST_BIN/fluidsim" run "$SCENE3D" --threads 2 --interp 2 >"$WORK/p_on.stream"
"$FEST_BIN/fluidsim" run "$SCENE3D" --threads 2 --interp 2 --pipeline off >"$WORK/p_off.stream"
check "--pipeline on (solver thread ahead of the writer) and off give identical bytes" cmp "$WORK/p_on.stream" "$WORK/p_off.stream"

case_ "determinism: --threads 1, 2, 3 and 4 give identical double-precision bytes with diffusion, fdm and fft"
# Viscosity and a diffusing scalar: every stage runs its parallel pieces (the grid is above
# the 32768-node threshold, each parity class above the 4096-node box threshold), and odd
# sizes leave ragged last pieces.
VISC="$WORK/visc3d.json"
cat >"$VISC" <<'JSON'
{ "dims": [36, 33, 34], "frame_dt": 0.05, "frames": 2, "viscosity": 0.002,
  "scalars": [ { "name": "density", "kappa": 0.001, "alpha": 0.05,
                 "sources": [ { "shape": "box", "min": [14, 14, 2], "max": [18, 18, 5], "rate": 10, "velocity": [0, 0, 0.5] } ] } ],
  "forces": [ { "type": "buoyancy", "scalar": "density", "beta": 1.0 } ] }
JSON
for solver in fdm fft; do
  for t in 1 2 3 4; do
    "$FEST_BIN/fluidsim" run "$VISC" --poisson $solver --precision double --threads $t 2>/dev/null >"$WORK/visc_${solver}_$t.stream"
  done
  for t in 2 3 4; do
    check "$solver: --threads $t gives the bytes of --threads 1" cmp "$WORK/visc_${solver}_1.stream" "$WORK/visc_${solver}_$t.stream"
  done
done

case_ "VTI frames: image data with the wall nodes, spacing h, velocity and density arrays"
mkdir -p "$WORK/v"
run fluidsim run "$SCENE3D" -o "$WORK/v/f%05d.vti" --frames 2 --threads 2
expect_status 0
run fconv --info "$WORK/v/f00001.vti"
expect_status 0
check "34^3 points" grep -q '"points": *39304' "$out"
check "velocity array" grep -q 'velocity' "$out"

case_ "2-D PFM and EXR frames"
mkdir -p "$WORK/p"
run fluidsim run "$SCENE2D" -o "$WORK/p/d%02d.pfm" --frames 2 --threads 1
expect_status 0
run fconv --info "$WORK/p/d01.pfm"
expect_json '[.width, .height, .channels]' '[34,34,1]'
run fluidsim run "$SCENE2D" -o "$WORK/p/v%02d.exr" --fields velocity --frames 1 --threads 1
expect_status 0
run fconv --info "$WORK/p/v00.exr"
expect_json '.channels' '3'

case_ "the paper's projection is exact; Stam 2003 (20 Gauss-Seidel sweeps) is not"
run fluidsim run "$SCENE2D" -o "$WORK/p/x%02d.pfm" --frames 3 --report "$WORK/paper.json" --threads 1
check "paper: max_div_rel < 1e-10" jq -e '.max_div_rel < 1e-10' "$WORK/paper.json"
run fluidsim run "$SCENE2D" -o "$WORK/p/y%02d.pfm" --frames 3 --order stam03 --poisson gs --iters 20 --report "$WORK/stam.json" --threads 1
expect_status 0
check "stam03: residual divergence > 1e-4 relative" jq -e '.max_div_rel > 1e-4' "$WORK/stam.json"
for s in fft mg jacobi; do
  run fluidsim run "$SCENE2D" -o "$WORK/p/z%02d.pfm" --frames 2 --poisson $s --report "$WORK/$s.json" --threads 1
  expect_status 0
done
check "fft exact" jq -e '.max_div_rel < 1e-10' "$WORK/fft.json"
check "mg to its tolerance" jq -e '.max_div_rel < 1e-6' "$WORK/mg.json"

case_ "render: slice, MIP and absorb of a 3-D stream; PFM output is the unmapped integral"
"$FEST_BIN/fluidsim" run "$SCENE3D" --frames 1 --threads 2 >"$WORK/one.stream"
for m in slice mip absorb; do
  run fluidsim render "$WORK/one.stream" --mode $m --axis y -o "$WORK/r_$m.png"
  expect_status 0
done
run fconv --info "$WORK/r_absorb.png"
expect_json '[.width, .height]' '[34,34]'
run fluidsim render "$WORK/one.stream" --mode mip --to pfm -o "$WORK/r.pfm"
expect_status 0

case_ "render reads VTI, PFM and volumes: the same field gives the same image"
run fluidsim render "$WORK/v/f00001.vti" --mode slice --axis z --to pfm -o "$WORK/from_vti.pfm"
expect_status 0
"$FEST_BIN/fluidsim" run "$SCENE3D" --frames 2 --threads 2 | "$FEST_BIN/fluidsim" render --mode slice --axis z --to pfm -o "$WORK/from_stream%d.pfm"
check "VTI and stream give the same slice" cmp "$WORK/from_vti.pfm" "$WORK/from_stream1.pfm"
run fluidsim render "$WORK/p/d01.pfm" --mode slice --to pfm -o "$WORK/d01_again.pfm"
expect_status 0
check "a 2-D slice of a PFM field is the field itself" cmp "$WORK/p/d01.pfm" "$WORK/d01_again.pfm"

case_ "restart from a written frame: init names a VTI file; scalars carry over exactly"
mkdir -p "$WORK/rs"
"$FEST_BIN/fluidsim" run "$SCENE2D" --frames 4 --precision double -o "$WORK/rs/f%d.vti" --threads 1
sed 's/"frames": 10,/"frames": 1, "init": "f3.vti",/' "$SCENE2D" >"$WORK/rs/restart.json"
run fluidsim run "$WORK/rs/restart.json" -o "$WORK/rs/again.pfm" --threads 1
expect_status 0
run fluidsim render "$WORK/rs/f3.vti" --mode slice --to pfm -o "$WORK/rs/f3.pfm"
check "frame 0 of the restart is the saved density" cmp "$WORK/rs/again.pfm" "$WORK/rs/f3.pfm"

# --- bad input: one line, the right status, nothing on stdout, no partial file ---
case_ "--help and a missing scene file"
run fluidsim run --help
expect_status 0
check "usage" grep -q "Usage" "$out"
run fluidsim run "$WORK/does-not-exist.json"
expect_clean_failure 4 fluidsim
expect_stderr_has "does-not-exist"
case_ "empty scene"
run_stdin /dev/null fluidsim run
expect_clean_failure 3 fluidsim
case_ "invalid JSON"
echo '{"dims": [8, 8' >"$WORK/bad.json"; run fluidsim run "$WORK/bad.json"
expect_clean_failure 3 fluidsim
case_ "unknown scene key, with the did-you-mean hint"
echo '{"dims": [8, 8], "viscocity": 0.1}' >"$WORK/bad.json"; run fluidsim run "$WORK/bad.json"
expect_clean_failure 3 fluidsim
expect_stderr_has 'scene key "viscocity" is unknown \(did you mean "viscosity"\?\)'
for doc in '{"dims": [8]}' '{"dims": [8, 8, 8, 8]}' '{"dims": [0, 8]}' '{"dims": [2000, 8]}'; do
  case_ "bad dims $doc"
  echo "$doc" >"$WORK/bad.json"; run fluidsim run "$WORK/bad.json"
  expect_clean_failure 3 fluidsim
  expect_stderr_has 'dims must be 2 or 3 integers in \[3, 1024\]'
done
for doc in '{"dims": [8, 8], "viscosity": -1}' '{"dims": [8, 8], "frame_dt": 0}' '{"dims": [8, 8], "interp": 0}' \
           '{"dims": [8, 8], "scalars": [{"alpha": -1}]}' '{"dims": [8, 8], "scalars": [{"sources": [{"min": [50, 50], "max": [60, 60]}]}]}'; do
  case_ "bad value $doc"
  echo "$doc" >"$WORK/bad.json"; run fluidsim run "$WORK/bad.json"
  expect_clean_failure 3 fluidsim
done
case_ "pattern without %d for several frames"
run fluidsim run "$SCENE2D" -o "$WORK/nopattern.pfm"
expect_clean_failure 2 fluidsim
check "no file left" test ! -e "$WORK/nopattern.pfm"
case_ "unsupported solver and unknown flag"
run fluidsim run "$SCENE2D" --poisson pcg
expect_clean_failure 2 fluidsim
run fluidsim run "$SCENE2D" --no-such-flag
expect_clean_failure 2 fluidsim
case_ "a state that becomes non-finite: exit 1, completed frames only"
echo '{"dims": [8, 8], "h": 1e-300, "frames": 5, "forces": [{"type": "constant", "value": [1e30, 1e30]}]}' >"$WORK/nan.json"
mkdir -p "$WORK/nan"
run fluidsim run "$WORK/nan.json" -o "$WORK/nan/f%d.pfm"
expect_status 1
expect_stderr_has '^fluidsim: error: state became non-finite at step 1 \(velocity\)$'
check "frame 0 complete, nothing else" test "$(ls "$WORK/nan")" = "f0.pfm"
case_ "init file on another grid, and one with a NaN"
echo '{"dims": [20, 20], "frames": 1, "init": "f3.vti"}' >"$WORK/rs/wrong.json"
run fluidsim run "$WORK/rs/wrong.json" -o "$WORK/rs/w.pfm"
expect_clean_failure 3 fluidsim
expect_stderr_has 'init file has 34x34x1 nodes, the scene.s grid stores 22x22x1'
{ printf 'NRRD0004\n# fest-frame: index=0 time=0 fields=density:1\ntype: float\ndimension: 3\nsizes: 1 10 10\nendian: little\nencoding: raw\n\n'
  printf '\000\000\300\177'; head -c 396 /dev/zero; } >"$WORK/rs/nan.nrrd"
echo '{"dims": [8, 8], "frames": 1, "init": "nan.nrrd"}' >"$WORK/rs/nan.json"
run fluidsim run "$WORK/rs/nan.json" -o "$WORK/rs/n.pfm"
expect_clean_failure 3 fluidsim
expect_stderr_has 'init file holds non-finite values'
check "no output file" test ! -e "$WORK/rs/n.pfm"
case_ "truncated NRRD frame into render"
head -c 20000 "$WORK/t1.stream" >"$WORK/trunc.stream"
run fluidsim render "$WORK/trunc.stream" -o "$WORK/trunc.png"
expect_clean_failure 3 fluidsim
expect_stderr_has 'truncated NRRD frame: expected [0-9]+ bytes, got [0-9]+ \(.*, frame 0\)'
check "no image" test ! -e "$WORK/trunc.png"
case_ "render --index out of range"
run fluidsim render "$WORK/one.stream" --mode slice --index 99 -o "$WORK/idx.png"
expect_clean_failure 2 fluidsim
case_ "interp of frames of different shape"
"$FEST_BIN/fluidsim" run "$SCENE3D" --frames 1 --fields density -o "$WORK/d3.nrrd" --threads 2
run fluidsim interp "$WORK/i/f00_velocity.nrrd" "$WORK/d3_density.nrrd" --alpha 0.5
expect_clean_failure 3 fluidsim

finish
