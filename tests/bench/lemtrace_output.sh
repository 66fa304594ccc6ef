#!/usr/bin/env bash
# lemtrace output cost (issue 23): the whole CLI run writing CSV, next to the anchor
# measured in the same run, the tracing alone of the same lines (bench_lemtrace --no-vtk:
# same helix grid, 56^3 cubes = 1,053,696 tets, same seeds (0.2..0.8, 0, -0.9)). One JSON
# line per case: wall, CPU (user+system) and peak RSS from /usr/bin/time, the report's
# phase timings. Not run by CTest. OLD=path/to/an/earlier/lemtrace adds its runs.
#
#   tests/bench/lemtrace_output.sh [build/bin] [seeds: 1000,8000] [threads: 1,2] [work dir]
set -euo pipefail
BIN=${1:-build/bin}
SEEDS=${2:-1000,8000}
THREADS=${3:-1,2}
WORK=${4:-$(mktemp -d)}
GRID="$WORK/helix56.vtu"
[ -f "$GRID" ] || "$BIN/lemtrace" gen helix --n 56 -o "$GRID"
timed() {  # name seeds threads target command... -> one JSON line
  local name=$1 n=$2 th=$3 target=$4
  shift 4
  /usr/bin/time -f '%U %S %e %M' -o "$WORK/time.txt" "$@" >/dev/null
  read -r user sys wall kb <"$WORK/time.txt"
  local size=0
  [ -f "$target" ] && size=$(stat -c %s "$target")
  printf '{"case": "%s", "seeds": %s, "threads": %s, "wall_s": %s, "cpu_s": %.2f, "peak_rss_mb": %.0f, "bytes": %s, "timings_s": %s}\n' \
    "$name" "$n" "$th" "$wall" "$(echo "$user + $sys" | bc)" "$(echo "$kb / 1024" | bc)" "$size" \
    "$(jq -c .timings_s "$WORK/report.json" 2>/dev/null || echo null)"
  rm -f "$WORK/report.json"
}
for n in ${SEEDS//,/ }; do
  for th in ${THREADS//,/ }; do
    if [ -x "$BIN/bench_lemtrace" ]; then
      "$BIN/bench_lemtrace" --no-vtk --seeds "$n" --threads "$th" | grep '"lem_trace"' | tail -1 |
        sed 's/^{/{"anchor": "trace only", /'
    fi
    lines=(--seed-line "0.2,0,-0.9:0.8,0,-0.9:$n" --threads "$th" --report "$WORK/report.json")
    timed lemtrace_csv_file "$n" "$th" "$WORK/out.csv" "$BIN/lemtrace" "$GRID" "${lines[@]}" -o "$WORK/out.csv"
    timed lemtrace_csv_devnull "$n" "$th" /dev/null "$BIN/lemtrace" "$GRID" "${lines[@]}" --to csv -o /dev/null
    if [ -n "${OLD:-}" ]; then
      timed old_csv_file "$n" "$th" "$WORK/old.csv" "$OLD" "$GRID" "${lines[@]}" -o "$WORK/old.csv"
      cmp -s "$WORK/out.csv" "$WORK/old.csv" && echo '{"case": "bytes", "identical": true}' ||
        echo '{"case": "bytes", "identical": false}'
      rm -f "$WORK/old.csv"
    fi
    rm -f "$WORK/out.csv"
  done
done
