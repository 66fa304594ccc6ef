#!/usr/bin/env bash
# lemtrace output cost (issue 23): the whole CLI run writing CSV or VTP, next to the
# anchor measured in the same run, the tracing alone of the same lines
# (bench_lemtrace --no-vtk: same helix grid, 56^3 cubes = 1,053,696 tets, same seeds
# (0.2..0.8, 0, -0.9)). Every case runs REPEAT times (default 3); one JSON line per case
# with the median wall time (and every run's), the CPU (user+system) and peak RSS of the
# median run from /usr/bin/time, the report's stream phases (trace, format = the
# workers' tracing and formatting, writer_thread = the writer thread's copying and
# writing, finish = the VTP's header and block copy), and the target ratios of issue
# 23: wall <= 2x the anchor, peak RSS <= 1 GB. N=24 picks a smaller helix grid (N^3 cubes,
# 6 tets each) for both. Not run by CTest. OLD=path/to/an/earlier/lemtrace
# adds its runs (CSV) and a byte comparison.
#
#   tests/bench/lemtrace_output.sh [build/bin] [seeds: 1000,8000] [threads: 1,2] [work dir] [formats: csv,vtp]
set -euo pipefail
BIN=${1:-build/bin}
SEEDS=${2:-1000,8000}
THREADS=${3:-1,2}
WORK=${4:-$(mktemp -d)}
FORMATS=${5:-csv,vtp}
REPEAT=${REPEAT:-3}
N=${N:-56}
GRID="$WORK/helix$N.vtu"
LEMTRACE=$(realpath "$BIN/lemtrace")
[ -z "${OLD:-}" ] || OLD=$(realpath "$OLD")
mkdir -p "$WORK/new" "$WORK/old"
[ -f "$GRID" ] || "$BIN/lemtrace" gen helix --n "$N" -o "$GRID"

median_of() { tr ' ' '\n' | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

anchor() {  # seeds threads -> "wall cpu": medians of the tracing alone (wall, CPU seconds)
  local walls=() cpus=() line
  for _ in $(seq "$REPEAT"); do
    line=$("$BIN/bench_lemtrace" --no-vtk --n "$N" --seeds "$1" --threads "$2" | grep '"lem_trace"' | tail -1)
    walls+=("$(echo "$line" | jq .seconds)")
    cpus+=("$(echo "$line" | jq .cpu_seconds)")
  done
  echo "$(echo "${walls[*]}" | median_of) $(echo "${cpus[*]}" | median_of)"
}

timed() {  # name seeds threads anchor_s dir output command... (run in $WORK/dir) -> one JSON line (median of REPEAT runs)
  local name=$1 n=$2 th=$3 anchor_s=$4 dir=$5 target=$WORK/$5/$6
  shift 6
  local walls=() r
  for r in $(seq "$REPEAT"); do
    (cd "$WORK/$dir" && /usr/bin/time -f '%e %U %S %M' -o "$WORK/time.$r" "$@" >/dev/null)
    mv "$WORK/report.json" "$WORK/report.$r" 2>/dev/null || echo null >"$WORK/report.$r"
    walls+=("$(cut -d' ' -f1 "$WORK/time.$r")")
  done
  local med
  med=$(echo "${walls[*]}" | median_of)
  for r in $(seq "$REPEAT"); do [ "$(cut -d' ' -f1 "$WORK/time.$r")" = "$med" ] && break; done
  local wall user sys kb size=0
  read -r wall user sys kb <"$WORK/time.$r"
  [ -f "$target" ] && size=$(stat -c %s "$target")
  jq -cn --arg case "$name" --argjson seeds "$n" --argjson threads "$th" --argjson wall "$wall" \
    --argjson walls "[$(IFS=,; echo "${walls[*]}")]" --argjson cpu "$(echo "$user + $sys" | bc)" \
    --argjson rss "$(echo "$kb / 1024" | bc)" --argjson bytes "$size" --argjson anchor "$anchor_s" --argjson acpu "$A_CPU" \
    --slurpfile report "$WORK/report.$r" --arg load "$(cut -d' ' -f1-3 /proc/loadavg)" \
    '{case: $case, seeds: $seeds, threads: $threads, wall_s: $wall, walls_s: $walls, cpu_s: $cpu,
      peak_rss_mb: $rss, bytes: $bytes, anchor_trace_only_s: $anchor,
      stream_s: ($report[0].timings_s.stream // null),
      read_build_locator_s: (if $report[0] then ($report[0].timings_s.read + $report[0].timings_s.build
                              + $report[0].timings_s.precompute + $report[0].timings_s.locator) else null end),
      anchor_trace_only_cpu_s: $acpu, cpu_over_anchor_cpu: (($cpu / $acpu) * 100 | round / 100),
      load: $load, wall_over_anchor: (($wall / $anchor) * 100 | round / 100), target_wall_over_anchor: 2,
      target_met: (($wall <= 2 * $anchor) and ($rss <= 1024))}'
}

for n in ${SEEDS//,/ }; do
  for th in ${THREADS//,/ }; do
    read -r a A_CPU < <(anchor "$n" "$th")
    echo "{\"case\": \"anchor_trace_only\", \"seeds\": $n, \"threads\": $th, \"median_s\": $a, \"median_cpu_s\": $A_CPU, \"load\": \"$(cut -d' ' -f1-3 /proc/loadavg)\"}"
    # Same relative names for both binaries: the VTP records the command line.
    lines=("../helix$N.vtu" --seed-line "0.2,0,-0.9:0.8,0,-0.9:$n" --threads "$th" --report "$WORK/report.json")
    for f in ${FORMATS//,/ }; do
      timed "lemtrace_${f}_file" "$n" "$th" "$a" new "out.$f" "$LEMTRACE" "${lines[@]}" -o "out.$f"
      if [ -n "${OLD:-}" ]; then
        timed "old_${f}_file" "$n" "$th" "$a" old "out.$f" "$OLD" "${lines[@]}" -o "out.$f"
        cmp -s "$WORK/new/out.$f" "$WORK/old/out.$f" && echo "{\"case\": \"bytes_$f\", \"identical\": true}" ||
          echo "{\"case\": \"bytes_$f\", \"identical\": false}"
        rm -f "$WORK/old/out.$f"
      fi
      rm -f "$WORK/new/out.$f"
    done
  done
done
