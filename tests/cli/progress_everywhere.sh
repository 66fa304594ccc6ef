#!/usr/bin/env bash
# --progress in every command with a stage longer than about two seconds (README
# "Conventions"): each command runs twice on a small input, once with --progress and once
# without, each in a folder of its own with the same relative names. With it, standard
# error has a bar ("label: [###...] 100%"); without it (standard error is a file here, not a
# terminal) standard error has no bar at all; standard output and every file written are the
# same bytes either way.
source "$(dirname "$0")/lib.sh"

# pair NAME [--stdin FILE] [--norm JQ] TOOL ARGS...: the command in $WORK/NAME.bar with
# --progress appended and in $WORK/NAME.plain without; both must succeed. --norm: standard
# output is JSON compared after this jq filter (timestamps); files are compared with cmp.
pair() {
  local name="$1"; shift
  local stdin=/dev/null norm=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --stdin) stdin="$2"; shift 2 ;;
      --norm) norm="$2"; shift 2 ;;
      *) break ;;
    esac
  done
  local mode extra d
  for mode in bar plain; do
    d="$WORK/$name.$mode"
    mkdir -p "$d"
    if [ -n "${SETUP:-}" ]; then (cd "$d" && eval "$SETUP"); fi
    extra=()
    if [ "$mode" = bar ]; then extra=(--progress); fi
    (cd "$d" && "$FEST_BIN/$1" "${@:2}" "${extra[@]}" <"$stdin" >"$WORK/$name.$mode.out" 2>"$WORK/$name.$mode.err")
    echo $? >"$WORK/$name.$mode.rc"
  done
  case_ "$name: --progress draws a bar to 100 %, nothing without it, the same output"
  err="$WORK/$name.bar.err"
  check "exit 0 with --progress ($(cat "$WORK/$name.bar.rc"))" test "$(cat "$WORK/$name.bar.rc")" = 0
  check "exit 0 without ($(cat "$WORK/$name.plain.rc"))" test "$(cat "$WORK/$name.plain.rc")" = 0
  check "a bar that reaches 100 %" grep -Eq '\[#+\] 100%' "$err"
  check "redrawn in place (carriage return)" grep -q $'\r' "$err"
  err="$WORK/$name.plain.err"
  check "no bar without --progress" bash -c "! grep -Eq '\] +[0-9]+%' '$err' && ! grep -q $'\r' '$err'"
  if [ -n "$norm" ]; then
    check "same standard output (jq '$norm')" cmp <(jq -S "$norm" "$WORK/$name.bar.out") <(jq -S "$norm" "$WORK/$name.plain.out")
  else
    check "same standard output" cmp "$WORK/$name.bar.out" "$WORK/$name.plain.out"
  fi
  check "same files" diff -r ${DIFF_EXCLUDE:-} "$WORK/$name.bar" "$WORK/$name.plain"
}

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

finish
