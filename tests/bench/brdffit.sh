#!/usr/bin/env bash
# brdffit geometry stages on bird-size synthetic data (docs/brdffit.md §7): 25 views of
# 3040x2008 (6 Mpixel) of a 20,480-triangle sphere with 5 materials, one point light,
# about 1.9 million lumitexels. One JSON line per stage with wall and CPU seconds and
# peak memory, the target of docs/brdffit.md §7 and the paper's time (SGI Octane 300 MHz, chapter 8
# §8.8: "HDR conversion + registration + lumitexel resampling ~ 5 h") beside it.
#
#   tests/bench/brdffit.sh [BIN_DIR] [WORK_DIR]      (defaults: build/bin, a temp dir)
# Not run by CTest. Set THREADS (default 2, the project machine's cores).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bin="${1:-$here/../../build/bin}"
work="${2:-$(mktemp -d)}"
threads="${THREADS:-2}"
testdata="${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}"
mkdir -p "$work"

# stage NAME TARGET_S PAPER NOTE -- COMMAND...: runs COMMAND under /usr/bin/time and
# prints {"stage", "wall_s", "cpu_s", "peak_rss_mb", "target_s", "paper", "note"}.
stage() {
  local name="$1" target="$2" paper="$3" note="$4"; shift 5
  local t0 t1
  t0=$(date +%s.%N)
  /usr/bin/time -f '%U %S %M' -o "$work/$name.time" "$@" > "$work/$name.stdout"
  t1=$(date +%s.%N)
  read -r user sys rss < "$work/$name.time"
  jq -cn --arg stage "$name" --argjson wall "$(echo "$t1 - $t0" | bc)" --argjson cpu "$(echo "$user + $sys" | bc)" \
    --argjson rss "$((rss / 1024))" --argjson target "$target" --arg paper "$paper" --arg note "$note" --argjson threads "$threads" \
    '{stage: $stage, threads: $threads, wall_s: $wall, cpu_s: $cpu, peak_rss_mb: $rss, target_s: $target, paper: $paper, note: $note}'
}

env_args=()
[ -f "$testdata/hdr/studio.exr" ] && env_args=(--env "$testdata/hdr/studio.exr")

stage synth null "photographs: acquisition ~2.5 h" "25 views x 1 light, 3040x2008, sphere L5 (20480 triangles), 5 materials" -- \
  "$bin/brdffit" synth --sphere 5 --materials 5 --views 25 --lights 1 --width 3040 --height 2008 --fill 0.4 \
  "${env_args[@]}" --threads "$threads" -o "$work/bird"

stage lumitexels 180 "HDR + registration + resampling ~5 h" "target (docs/brdffit.md §7): <= 3 min, <= 4 GB" -- \
  "$bin/brdffit" lumitexels --mesh "$work/bird/mesh.ply" --rig "$work/bird/rig.json" --threads "$threads" \
  --report "$work/lumitexels.json" -o "$work/bird.ltx"
jq -c '{stage: "lumitexels_counts", lumitexels, samples, mean_samples, dropped, stage_seconds, peak_rss_kb, bytes,
        paper_bird: {lumitexels: 1917043, mean_samples: 6.3}}' "$work/lumitexels.json"

# Registration of one 6 Mpixel silhouette from a pose perturbed by 10 degrees and 10 %
# (docs/brdffit.md §6), focal length known; then the automatic initial guess.
if [ -f "$testdata/meshes/bunny_scan.ply" ]; then
  "$bin/brdffit" synth --mesh "$testdata/meshes/bunny_scan.ply" --materials 1 --views 1 --width 3040 --height 2008 \
    --threads "$threads" -o "$work/bunny" 2>/dev/null
  jq '.images[0].camera' "$work/bunny/rig.json" > "$work/bunny_cam.json"
  # R := R Rx(10 deg) (about the object's frame axes), t scaled by 1.1.
  c=$(awk 'BEGIN { printf "%.17g", cos(10*atan2(0,-1)/180) }'); s=$(awk 'BEGIN { printf "%.17g", sin(10*atan2(0,-1)/180) }')
  jq --argjson c "$c" --argjson s "$s" '.R |= [.[0], .[1]*$c + .[2]*$s, -.[1]*$s + .[2]*$c,
      .[3], .[4]*$c + .[5]*$s, -.[4]*$s + .[5]*$c, .[6], .[7]*$c + .[8]*$s, -.[7]*$s + .[8]*$c] | .t |= map(. * 1.1)' \
    "$work/bunny_cam.json" > "$work/bunny_start.json"
  stage register 10 "part of the 5 h" "bunny, 3040x2008, start 10 deg / 10 % off, --fix-focal" -- \
    "$bin/brdffit" register --mesh "$testdata/meshes/bunny_scan.ply" --mask "$work/bunny/hdr/a000_mask.png" \
    --camera "$work/bunny_start.json" --fix-focal --threads "$threads" --report "$work/register.json" -o "$work/bunny_fit.json"
  jq -c --slurpfile t "$work/bunny_cam.json" --slurpfile r "$work/register.json" '{stage: "register_error", xor: $r[0].xor, evaluations: $r[0].evaluations,
      t_error_rel: ((([.t, $t[0].t] | transpose | map((.[0]-.[1])*(.[0]-.[1])) | add) | sqrt) / (($t[0].t | map(.*.) | add) | sqrt)),
      R_max_abs_diff: ([.R, $t[0].R] | transpose | map((.[0]-.[1]) | fabs) | max)}' "$work/bunny_fit.json"
  stage register_auto 10 "part of the 5 h" "bunny, 3040x2008, automatic initial guess (240 orientations), --fix-focal" -- \
    "$bin/brdffit" register --mesh "$testdata/meshes/bunny_scan.ply" --mask "$work/bunny/hdr/a000_mask.png" \
    --camera "$work/bunny_start.json" --auto --fix-focal --threads "$threads" --report "$work/register_auto.json" \
    -o "$work/bunny_auto.json" || true
  jq -c --slurpfile t "$work/bunny_cam.json" --slurpfile r "$work/register_auto.json" '{stage: "register_auto_error",
      xor: $r[0].xor, R_max_abs_diff: ([.R, $t[0].R] | transpose | map((.[0]-.[1]) | fabs) | max)}' "$work/bunny_auto.json" \
      2>/dev/null || true
else
  jq -cn '{stage: "register", skipped: "bunny_scan.ply not fetched (scripts/fetch-test-data.sh)"}'
fi
