#!/usr/bin/env bash
# brdffit register --auto (docs/brdffit.md §7): the bunny seen from 10 turntable
# angles at 320x240; the automatic initial guess (240 orientations on SO(3), 20 simplex
# steps each at 1/8 resolution, the best 5 refined) must find the pose for >= 9 of 10.
# One JSON line per view and a summary line. Not run by CTest. REGISTER_FLAGS adds
# options (e.g. "--keep 15 --coarse-iters 40").
#
#   tests/bench/brdffit_register_auto.sh [BIN_DIR] [WORK_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bin="${1:-$here/../../build/bin}"
work="${2:-$(mktemp -d)}"
testdata="${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}"
bunny="$testdata/meshes/bunny_scan.ply"
if [ ! -f "$bunny" ]; then jq -cn '{stage: "register_auto", skipped: "bunny_scan.ply not fetched"}'; exit 0; fi
mkdir -p "$work"
"$bin/brdffit" synth --mesh "$bunny" --materials 1 --views 10 --elevation 35 --width 320 --height 240 -o "$work/b" 2>/dev/null
ok=0
for k in 0 1 2 3 4 5 6 7 8 9; do
  jq ".images[$k].camera" "$work/b/rig.json" > "$work/cam$k.json"
  "$bin/brdffit" register --mesh "$bunny" --mask "$work/b/hdr/a00${k}_mask.png" --camera "$work/cam$k.json" \
    --auto --fix-focal --threads "${THREADS:-2}" --max-xor 1 ${REGISTER_FLAGS:-} --report "$work/rep$k.json" -o "$work/fit$k.json"
  # Rotation error in degrees from the trace of R_fit^T R_true.
  # Rotation error in degrees: trace(R_fit^T R_true) = sum of the elementwise products.
  line=$(jq -c --slurpfile t "$work/cam$k.json" --slurpfile r "$work/rep$k.json" '
    ([.R, $t[0].R] | transpose | map(.[0] * .[1]) | add) as $tr
    | {view: '"$k"', xor: $r[0].xor, seconds: $r[0].seconds,
       rotation_error_deg: (((($tr - 1) / 2) | if . > 1 then 1 elif . < -1 then -1 else . end) | acos * 180 / 3.141592653589793)}' \
    "$work/fit$k.json")
  echo "$line"
  if jq -e '.rotation_error_deg < 1' <<< "$line" >/dev/null; then ok=$((ok + 1)); fi
done
jq -cn --argjson ok "$ok" --arg flags "${REGISTER_FLAGS:-}" '{stage: "register_auto", flags: $flags, correct: $ok, of: 10, criterion: "rotation error < 1 deg", target: ">= 9 of 10"}'
