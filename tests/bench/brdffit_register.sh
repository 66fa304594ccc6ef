#!/usr/bin/env bash
# brdffit register alone (docs/brdffit.md §6/§7): the bunny (bunny_scan.ply) rendered at
# 3040x2008 (6 Mpixel) from the first synth view, registered from a start turned by
# 10 degrees about the object's x axis with t scaled by 1.1, focal length known. The
# target, <= 10 s per image, is printed beside the CPU seconds (user + sys of all threads;
# on the shared machine wall time is inflated by the load, given as load_avg). A second
# line gives the errors against the true camera: rotation angle of R_fit^T R_true in
# degrees, |t_fit - t_true| / |t_true|, and the final XOR.
#
#   tests/bench/brdffit_register.sh [BIN_DIR] [WORK_DIR]    (SIZE=WxH, default 3040x2008)
# Not run by CTest. THREADS (default 2). With CALLGRIND=1 the register command runs under
# valgrind --tool=callgrind with --threads 1 and the instruction count is printed too
# (about 50x slower: use a smaller SIZE).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bin="${1:-$here/../../build/bin}"
work="${2:-$(mktemp -d)}"
threads="${THREADS:-2}"
size="${SIZE:-3040x2008}"
width="${size%x*}" height="${size#*x}"
testdata="${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}"
bunny="$testdata/meshes/bunny_scan.ply"
if [ ! -f "$bunny" ]; then jq -cn '{stage: "register", skipped: "bunny_scan.ply not fetched (scripts/fetch-test-data.sh)"}'; exit 0; fi
mkdir -p "$work"
if [ ! -f "$work/bunny_$size/hdr/a000_mask.png" ]; then
  "$bin/brdffit" synth --mesh "$bunny" --materials 1 --views 1 --width "$width" --height "$height" \
    --threads "$threads" -o "$work/bunny_$size" 2>/dev/null
fi
jq '.images[0].camera' "$work/bunny_$size/rig.json" > "$work/cam.json"
# R := R Rx(10 deg) (about the object's frame axes), t scaled by 1.1.
c=$(awk 'BEGIN { printf "%.17g", cos(10*atan2(0,-1)/180) }'); s=$(awk 'BEGIN { printf "%.17g", sin(10*atan2(0,-1)/180) }')
jq --argjson c "$c" --argjson s "$s" '.R |= [.[0], .[1]*$c + .[2]*$s, -.[1]*$s + .[2]*$c,
    .[3], .[4]*$c + .[5]*$s, -.[4]*$s + .[5]*$c, .[6], .[7]*$c + .[8]*$s, -.[7]*$s + .[8]*$c] | .t |= map(. * 1.1)' \
  "$work/cam.json" > "$work/start.json"
cmd=("$bin/brdffit" register --mesh "$bunny" --mask "$work/bunny_$size/hdr/a000_mask.png" --camera "$work/start.json"
     --fix-focal --report "$work/register.json" -o "$work/fit.json")
instructions=null
if [ "${CALLGRIND:-0}" = 1 ]; then
  threads=1
  valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" "${cmd[@]}" --threads 1 2> "$work/callgrind.log"
  instructions=$(grep -m1 '^summary:' "$work/callgrind.out" | awk '{print $2}')
fi
load=$(cut -d' ' -f1 /proc/loadavg)
t0=$(date +%s.%N)
/usr/bin/time -f '%U %S %M' -o "$work/register.time" "${cmd[@]}" --threads "$threads"
t1=$(date +%s.%N)
read -r user sys rss < "$work/register.time"
jq -cn --arg size "$size" --argjson threads "$threads" --argjson wall "$(echo "$t1 - $t0" | bc)" \
  --argjson cpu "$(echo "$user + $sys" | bc)" --argjson rss "$((rss / 1024))" --argjson load "$load" \
  --argjson instructions "$instructions" --slurpfile r "$work/register.json" \
  '{stage: "register", size: $size, threads: $threads, wall_s: $wall, cpu_s: $cpu, target_s: 10, peak_rss_mb: $rss,
    load_avg: $load, evaluations: $r[0].evaluations, instructions: $instructions,
    note: "bunny, start 10 deg / 10 % off, --fix-focal"}'
jq -c --slurpfile t "$work/cam.json" --slurpfile r "$work/register.json" '
  ([.R, $t[0].R] | transpose | map(.[0] * .[1]) | add) as $tr
  | {stage: "register_error", xor: $r[0].xor,
     rotation_error_deg: (((($tr - 1) / 2) | if . > 1 then 1 elif . < -1 then -1 else . end) | acos * 180 / 3.141592653589793),
     t_error_rel: ((([.t, $t[0].t] | transpose | map((.[0]-.[1])*(.[0]-.[1])) | add) | sqrt) / (($t[0].t | map(.*.) | add) | sqrt)),
     R_max_abs_diff: ([.R, $t[0].R] | transpose | map((.[0]-.[1]) | fabs) | max)}' "$work/fit.json"
