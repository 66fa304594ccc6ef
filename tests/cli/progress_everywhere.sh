#!/usr/bin/env bash
# --progress in every command with a stage longer than about two seconds (README
# "Conventions"): each command runs twice on a small input, once with --progress and once
# without, each in a folder of its own with the same relative names. With it, standard
# error has a bar ("label: [###...] 100%"); without it (standard error is a file here, not a
# terminal) standard error has no bar at all; standard output and every file written are the
# same bytes either way.
source "$(dirname "$0")/lib.sh"
source "$(dirname "$0")/progress_pair.sh"

# ---- lib/core's callback through every layer: lib/ reports, the tool draws ----------------

pair decimate decimate "$FEST_FIXTURES/decimate/cube6_100.off" --ratio 0.2 -o d.ply

pair lmfsim --stdin "$FEST_FIXTURES/lmfsim/chain.json" lmfsim run

cat >"$WORK/cav.json" <<'JSON'
{ "size": [16, 16], "re": 100, "u_ref": 0.1,
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0] } } },
  "steps": 500, "output": { "every": 250, "fields": ["density", "velocity"], "precision": "float64" } }
JSON
pair lbmsim lbmsim run "$WORK/cav.json" --threads 1 -o f%05d.vti

pair radiosity radiosity solve "$FEST_FIXTURES/radiosity/cornell.json" --hemicube-res 32 --levels 1 -o lit.ply

"$FEST_BIN/lemtrace" gen helix --n 6 --jitter 0.2 --seed 1 -o "$WORK/h6.vtu" || fail "lemtrace gen"
pair lemtrace_csv lemtrace trace "$WORK/h6.vtu" --seed-line 0.2,0.2,0.2:0.8,0.8,0.8:50 -o lines.csv --threads 2
pair lemtrace_vtp lemtrace trace "$WORK/h6.vtu" --seed-line 0.2,0.2,0.2:0.8,0.8,0.8:50 -o lines.vtp --threads 2
pair lemtrace_classify lemtrace classify "$WORK/h6.vtu" --sweep-parallel 1e-7:1e-1

printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' >"$WORK/octa.off"
printf '{"origin":[-2,-2,-2],"axes":[[4,0,0],[0,4,0],[0,0,4]],"dims":[4,4,4]}\n' >"$WORK/zero.json"
printf 'time lattice\n0 %s\n0.5 %s\n' "$WORK/zero.json" "$WORK/zero.json" >"$WORK/keys.tsv"
SETUP="mkdir -p frames" pair ffd ffd animate --keys "$WORK/keys.tsv" "$WORK/octa.off" -o frames/f%04d.off

"$FEST_BIN/markerpose" gen --dict 4x4_50 --id 3 --size 0.05 --tilt 20 -o "$WORK/l%d.png" --frames 3 --roll-step 30 ||
  fail "markerpose gen"
printf '{"K":[600,0,319.5,0,600,239.5,0,0,1],"width":640,"height":480}' >"$WORK/ideal.json"
pair markerpose markerpose detect "$WORK/l0.png" "$WORK/l1.png" "$WORK/l2.png" --camera "$WORK/ideal.json" --size 0.05 --threads 2

pair volrender volrender mip "$FEST_FIXTURES/volume/gzip_uint16.nrrd" --size 40x30 -o v.png --threads 2

"$FEST_BIN/facefit" synth -o "$WORK/face" --resolution 16 --faces 12 --train 10 --seed 1 || fail "facefit synth"
pair facefit_build facefit build -o model.mmb --list "$WORK/face/train.txt" --landmarks "$WORK/face/landmarks.tsv"
"$FEST_BIN/facefit" project --mesh "$WORK/face/face011.ply" --vertices "$WORK/face/set17.tsv" >"$WORK/lm.tsv" ||
  fail "facefit project"
SETUP="printf '%s %s\n' '$WORK/lm.tsv' a.ply '$WORK/lm.tsv' b.tsv >batch.txt" \
  pair facefit_fit facefit fit -m "$WORK/facefit_build.plain/model.mmb" --batch batch.txt

# ---- acquisition: capture run, then hdrmerge session on that session -----------------------

D="$FEST_FIXTURES/capture"
# The manifest (standard output, compared without its timestamps) and the journal carry the
# time of every shot; every other file must be the same bytes.
SETUP="cp '$D/small_scene.json' '$D/small_station.json' '$D/small_plan.json' ." \
  DIFF_EXCLUDE="-x manifest.json -x manifest.journal" pair capture --norm 'del(.started) | del(.shots[].time)' \
  capture run --station small_station.json --plan small_plan.json -o sess
case_ "capture: the same pictures"
check "same PNGs" bash -c "cd '$WORK/capture.bar/sess' && for f in \$(find . -name '*.png'); do cmp \"\$f\" '$WORK/capture.plain/sess/'\"\$f\" || exit 1; done"
SETUP="cp -r '$WORK/capture.plain/sess' ." pair hdrmerge hdrmerge session --manifest sess/manifest.json --threads 2
# A 64 x 32 radiance ramp over four decades (grey PFM), bracketed into three exposures.
T=0.01,0.1,1
python3 -c 'import struct, sys; w, h = 64, 32
sys.stdout.buffer.write(b"Pf\n%d %d\n-1\n" % (w, h) + b"".join(struct.pack("<f", 10 ** (-2 + 4 * (x + w * y) / (w * h))) for y in range(h) for x in range(w)))' \
  >"$WORK/rad.pfm" || fail "radiance ramp"
SETUP="mkdir -p br" pair hdrmerge_bracket hdrmerge bracket "$WORK/rad.pfm" -t "$T" -o br
pair hdrmerge_merge hdrmerge merge "$WORK"/hdrmerge_bracket.plain/br/e*.png -t "$T" -o m.exr --threads 2
pair hdrmerge_calibrate hdrmerge calibrate "$WORK"/hdrmerge_bracket.plain/br/e*.png -t "$T"

# ---- segbrain on the phantom of tests/cli/segbrain.sh ---------------------------------------

"$FEST_BIN/segbrain" synth -o "$WORK/head.nii.gz" --truth "$WORK/truth.nii.gz" --size 80,96,80 --spacing 2,2,2 --seed 1 ||
  fail "segbrain synth"
pair segbrain segbrain run "$WORK/head.nii.gz" -o labels.nii.gz --threads 2

# ---- brdffit: a small synthetic scene through lumitexels, cluster and register -------------

"$FEST_BIN/brdffit" synth --sphere 2 --materials 2 --views 4 --lights 2 --width 80 --height 60 --seed 1 -o "$WORK/syn" ||
  fail "brdffit synth"
pair brdffit_lumitexels brdffit lumitexels --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" -o syn.ltx --threads 2
pair brdffit_cluster brdffit cluster "$WORK/brdffit_lumitexels.plain/syn.ltx" --clusters 2 --min-samples 2 -o clusters.json --threads 2
pair brdffit_register brdffit register --mesh "$WORK/syn/mesh.ply" --rig "$WORK/syn/rig.json" --fix-focal --iters 20 \
  -o rig_back.json --threads 2

# ---- brdffit's materials stages and synth ----------------------------------------------------

"$FEST_BIN/brdffit_testdata" samples onelobe 400 3 0.02 >"$WORK/onelobe.csv" || fail "brdffit_testdata"
pair brdffit_fit --stdin "$WORK/onelobe.csv" brdffit fit --lobes 2 --starts 2 --threads 2
pair brdffit_project brdffit project "$WORK/brdffit_lumitexels.plain/syn.ltx" --clusters "$WORK/brdffit_cluster.plain/clusters.json" \
  -o w.ltw --threads 2
pair brdffit_normals brdffit normals "$WORK/brdffit_lumitexels.plain/syn.ltx" --svbrdf "$WORK/brdffit_project.plain/w.ltw" \
  -o n.ply --threads 2
pair brdffit_synth brdffit synth --sphere 1 --materials 2 --views 3 --lights 1 --width 40 --height 30 --seed 2 -o syn --threads 2

# ---- volumes: volwave, isosurf -------------------------------------------------------------------

V="$FEST_FIXTURES/volume/gzip_uint16.nrrd"
pair volwave_encode volwave encode "$V" --max-error 2 -o v.vw --threads 2
pair volwave_encode_rmse volwave encode "$V" --rmse 1 --wavelet cdf97 -o v.vw --threads 2
pair volwave_decode volwave decode "$WORK/volwave_encode.plain/v.vw" -o v.nrrd --threads 2
pair volwave_edges volwave edges "$V" --scales 2 -o e.nrrd --threads 2
pair isosurf_exact isosurf exact "$V" --iso 1000 -o s.ply --threads 2
pair isosurf_adaptive isosurf adaptive "$V" --iso 1000 --max-error 50 -o s.ply --threads 2
# The manifest holds the time of every level; the meshes must be the same bytes.
DIFF_EXCLUDE="-x manifest.json" pair isosurf_progressive isosurf progressive "$V" --iso 1000 --errors 50,0 -o levels --threads 2

# ---- simulations' checks, fluidsim render, feshape fit ------------------------------------------

# lbmsim's report carries its own run time.
pair lbmsim_check --norm 'del(.metrics.seconds)' lbmsim check poiseuille --threads 1
pair fluidsim_check fluidsim check mass --threads 1
cat >"$WORK/smoke2d.json" <<'JSON'
{ "dims": [16, 16], "frame_dt": 0.05, "frames": 4, "viscosity": 0.001,
  "scalars": [ { "name": "density", "alpha": 0.05,
                 "sources": [ { "shape": "sphere", "centre": [8, 4], "radius": 2, "rate": 10 } ] } ],
  "forces": [ { "type": "buoyancy", "scalar": "density", "beta": 1.0 } ] }
JSON
"$FEST_BIN/fluidsim" run "$WORK/smoke2d.json" --threads 1 >"$WORK/smoke.stream" || fail "fluidsim run"
# fluidsim's report would carry timings; the frame stream on standard output must not.
pair fluidsim_run fluidsim run "$WORK/smoke2d.json" --threads 1
SETUP="mkdir -p png" pair fluidsim_render fluidsim render "$WORK/smoke.stream" -o png/f%02d.png
pair feshape_fit feshape fit "$FEST_FIXTURES/feshape/squash123.xyz" --grid 5x5 --levels 1 --tau 0.02 -o f.ply --threads 2

# ---- terrainlod: extract one view, a camera path, verify ----------------------------------------

awk 'BEGIN { print "ncols 45\nnrows 37\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 37; r++) { line = ""; for (i = 0; i < 45; i++) line = line sprintf("%d ", (i * 7 + r * 13) % 11 + (i * r) % 5); print line } }' \
  >"$WORK/dem.asc"
"$FEST_BIN/terrainlod" build "$WORK/dem.asc" --tile 16 -o "$WORK/dem.tlp" || fail "terrainlod build"
pair terrainlod_build terrainlod build "$WORK/dem.asc" --tile 16 -o dem.tlp --threads 2
pair terrainlod_extract terrainlod extract "$WORK/dem.tlp" -o view.ply --png view.png
printf '{"eye":[225,185,3000],"target":[225,185,0],"up":[0,1,0],"fovy_deg":20,"width":64,"height":64}\n{"eye":[100,100,800],"target":[225,185,0],"up":[0,0,1],"fovy_deg":40,"width":64,"height":64}\n' \
  >"$WORK/path.jsonl"
pair terrainlod_path terrainlod extract "$WORK/dem.tlp" --path "$WORK/path.jsonl" -o f%d.ply
pair terrainlod_verify terrainlod verify "$WORK/dem.tlp" --dem "$WORK/dem.asc" --cameras 3
pair terrainlod_stats terrainlod stats "$WORK/dem.tlp"
pair terrainlod_export_qm terrainlod export-qm "$WORK/dem.tlp" -o qm
awk 'BEGIN { print "ncols 257\nnrows 257\nxllcorner 0\nyllcorner 0\ncellsize 10";
  for (r = 0; r < 257; r++) { line = ""; for (i = 0; i < 257; i++) line = line sprintf("%.2f ", 40 * sin(i / 9.0) * cos(r / 13.0) + (i * r) % 7); print line } }' \
  >"$WORK/dem257.asc"
pair terrainlod_simplify terrainlod simplify "$WORK/dem257.asc" --max-error 1 -o s.ply

# ---- softobj tongue --polygonize: frames of the /b i d A m u/ example at 5 frames per second --

TONGUE="$(dirname "$0")/../../examples/tongue"
"$FEST_BIN/softobj" animate --table "$TONGUE/phonemes.json" --fps 5 "$TONGUE/bidamu.tsv" -o "$WORK/bidamu.tsv" ||
  fail "softobj animate"
SETUP="mkdir -p t" pair softobj_tongue softobj tongue --polygonize --palate "$TONGUE/palate.json" -o t/t%02d.ply "$WORK/bidamu.tsv" \
  --threads 2

# ---- formats/: deflating a large PNG (resample writes 4 megapixels and more with a bar) ------

pair resample resample resize "$FEST_FIXTURES/image/pattern_raw.ppm" --size 2400x1800 --filter box -o big.png
"$FEST_BIN/resample" resize "$FEST_FIXTURES/image/pattern_raw.ppm" --size 2400x1800 --filter box -o "$WORK/big.ppm" ||
  fail "resample to PPM"
pair fconv fconv "$WORK/big.ppm" -o big.png

# ---- the one -q rule (README "Conventions"): on a terminal the bar is automatic; -q hides it;
# ---- --progress draws it even with -q. script(1) gives the command a terminal. -----------------

if command -v script >/dev/null 2>&1; then
  tty_run() {  # NAME ARGS...: the command on a pseudo-terminal; what it drew -> $WORK/NAME.tty
    local name="$1"; shift
    script -qec "$*" /dev/null </dev/null >"$WORK/$name.tty" 2>&1
    echo $? >"$WORK/$name.tty.rc"
  }
  F="$FEST_BIN/brdffit fit $WORK/onelobe.csv --lobes 2 --starts 2 --threads 2 -o /dev/null"
  tty_run auto "$F"
  tty_run quiet "$FEST_BIN/brdffit -q fit $WORK/onelobe.csv --lobes 2 --starts 2 --threads 2 -o /dev/null"
  tty_run quiet_progress "$FEST_BIN/brdffit -q fit $WORK/onelobe.csv --lobes 2 --starts 2 --threads 2 -o /dev/null --progress"
  case_ "-q and --progress on a terminal: automatic bar, hidden by -q, drawn by --progress even with -q"
  for n in auto quiet quiet_progress; do check "$n: exit 0" test "$(cat "$WORK/$n.tty.rc")" = 0; done
  check "a terminal gets the bar without asking" grep -Eq '\[#+\] 100%' "$WORK/auto.tty"
  check "-q hides the automatic bar" bash -c "! grep -Eq '\] +[0-9]+%' '$WORK/quiet.tty'"
  check "-q --progress draws it" grep -Eq '\[#+\] 100%' "$WORK/quiet_progress.tty"
  # The same rule in a tool that hid its bar with -q before (decimate): -q --progress draws it.
  tty_run decimate_qp "$FEST_BIN/decimate -q $FEST_FIXTURES/decimate/cube6_100.off --ratio 0.2 -o $WORK/dq.ply --progress"
  tty_run decimate_q "$FEST_BIN/decimate -q $FEST_FIXTURES/decimate/cube6_100.off --ratio 0.2 -o $WORK/dq.ply"
  check "decimate -q --progress draws the bar" grep -Eq '\[#+\] 100%' "$WORK/decimate_qp.tty"
  check "decimate -q alone draws none" bash -c "! grep -Eq '\] +[0-9]+%' '$WORK/decimate_q.tty'"
fi

finish
