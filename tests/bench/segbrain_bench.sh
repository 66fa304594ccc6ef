#!/usr/bin/env bash
# segbrain benchmark (spec §7): operator throughputs (bench_segbrain), then head+brain on
# the real heads Debian ships, 5 runs each, median wall time, peak RSS, inferences and
# backtracks, and the brain Dice against the reference masks; plus the leak-recovery case
# (P3) on Colin27. One JSON line per case. Reports, never fails on timing.
#   tests/bench/segbrain_bench.sh [BUILD_BIN]
set -u
BIN=${1:-$(cd "$(dirname "$0")/../../build/bin" && pwd)}
DATA=${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}/mri
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
[ -x "$BIN/bench_segbrain" ] && "$BIN/bench_segbrain" 2>/dev/null

case_run() {  # name input reference extra-args...
  local name=$1 in=$2 ref=$3; shift 3
  if [ ! -f "$in" ]; then echo "{\"bench\":\"segbrain\",\"case\":\"$name\",\"skipped\":\"test data not fetched\"}"; return; fi
  local walls=() rss=()
  for i in 1 2 3 4 5; do
    /usr/bin/time -f "%e %M" -o "$W/time" "$BIN/segbrain" run "$in" -o "$W/l.nii.gz" --report "$W/r.json" --trace "$W/t.jsonl" "$@" 2>/dev/null
    read -r wall kb <"$W/time"; walls+=("$wall"); rss+=("$kb")
  done
  local med; med=$(printf '%s\n' "${walls[@]}" | sort -n | sed -n 3p)
  local peak; peak=$(printf '%s\n' "${rss[@]}" | sort -n | tail -1)
  local dice; dice=$("$BIN/segbrain" eval --ref "$ref" --seg "$W/l.nii.gz" --map "brain=2-8" --ref-map "brain=1-1000" 2>/dev/null | awk '$1=="brain"{print $2}')
  jq -c --arg n "$name" --argjson wall "$med" --argjson rss "$peak" --arg dice "${dice:-null}" \
    '{bench: "segbrain", case: $n, wall_s_median: $wall, peak_rss_mb: ($rss / 1024 | floor), dice_brain: ($dice | tonumber? // null),
      inferences: .counts.inferences, backtracks: .counts.backtracks, accepted_by: .accepted_by.find_brain}' "$W/r.json"
}

case_run colin27_head_brain "$DATA/ch2.nii.gz" "$DATA/ch2bet.nii.gz"
case_run itk_t1_head_brain "$DATA/t1_head.nii.gz" "$DATA/t1_skullstrip_labels.nii.gz"
# P3: the leaking window first; the trace must show the skin-contact check failing.
if [ -f "$DATA/ch2.nii.gz" ]; then
  "$BIN/segbrain" run "$DATA/ch2.nii.gz" -o "$W/p3.nii.gz" --trace "$W/p3.jsonl" \
      --set "brain_window=[(0.50,1.30),(0.55,1.25)]" --set "separation_mm=[2]" 2>"$W/p3.err"
  rc=$?
  jq -s -c --argjson rc "$rc" --arg err "$(cat "$W/p3.err")" '{bench: "segbrain", case: "colin27_leak_retry_P3", exit: $rc, error: $err,
      skin_contact_failures: [.[] | select(.port == "fail" and (.goal | startswith("no_connection_to_skincontour"))) | .measure.skin_contact_fraction],
      verify_exits: [.[] | select(.port == "exit" and (.goal | startswith("verify_brain_result")))] | length}' "$W/p3.jsonl"
fi
# Anchors (FSL BET, ANTs) are not in Debian main: reported as skipped.
echo '{"bench":"segbrain","case":"anchor_bet","skipped":"FSL BET is not packaged in Debian main"}'
