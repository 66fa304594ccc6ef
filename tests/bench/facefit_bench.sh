#!/usr/bin/env bash
# facefit at the chapter's scale: bench_facefit (model build, compute per fit, uncertainty,
# baseline) and then the executable end to end on a page-cached model: `facefit fit`
# (median of 20 runs, binary PLY output; target 0.3 s, paper 1.6 s) and `fit --batch`
# throughput with meshes (target >= 50 fits/s) and with coefficients only (>= 200 fits/s).
# One JSON line per case. Usage: tests/bench/facefit_bench.sh [BUILD_BIN_DIR]
set -euo pipefail
BIN=${1:-$(cd "$(dirname "$0")/../.." && pwd)/build/bin}
W=$(mktemp -d "${TMPDIR:-/tmp}/facefit-bench.XXXXXX")
trap 'rm -rf "$W"' EXIT
"$BIN/bench_facefit" --resolution 276 --write-model "$W/model.mmb" --write-faces "$W"
cat "$W/model.mmb" >/dev/null   # page cache
ms_now() { date +%s%N; }
times=()
for i in $(seq 20); do
  t0=$(ms_now); "$BIN/facefit" fit -m "$W/model.mmb" --landmarks "$W/landmarks50.tsv" >"$W/face.ply"; t1=$(ms_now)
  times+=($(( (t1 - t0) / 1000 )))
done
median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n 10p)
bytes=$(stat -c %s "$W/model.mmb"); mesh=$(stat -c %s "$W/face.ply")
"$BIN/facefit" fit -m "$W/model.mmb" --landmarks "$W/landmarks50.tsv" --report "$W/r.json" >/dev/null
cpu=()
for i in $(seq 5); do
  cpu+=($( { /usr/bin/time -f "%U %S %M" "$BIN/facefit" fit -m "$W/model.mmb" --landmarks "$W/landmarks50.tsv" >/dev/null; } 2>&1 | tail -1 | awk '{print ($1 + $2) * 1000 "_" $3}'))
done
cpu_ms=$(printf '%s\n' "${cpu[@]}" | cut -d_ -f1 | sort -n | sed -n 3p)
rss=$(printf '%s\n' "${cpu[@]}" | cut -d_ -f2 | sort -n | tail -1)
echo "{\"bench\":\"facefit_fit_end_to_end\",\"load_average\":$(cut -d" " -f1 /proc/loadavg),\"camera\":\"similarity\",\"median_ms\":$(awk "BEGIN{print $median/1000}"),\"cpu_ms_user_sys\":$cpu_ms,\"runs\":20,\"target_ms\":300,\"paper_ms\":1600,\"model_bytes\":$bytes,\"mesh_bytes\":$mesh,\"peak_rss_kb\":$rss,\"timings_ms\":$(jq -c .timings_ms "$W/r.json")}"
for kind in ply tsv; do
  : >"$W/batch.txt"
  for i in $(seq 50); do echo "$W/landmarks50.tsv $W/out$i.$kind" >>"$W/batch.txt"; done
  t0=$(ms_now); "$BIN/facefit" fit -m "$W/model.mmb" --batch "$W/batch.txt"; t1=$(ms_now)
  secs=$(awk "BEGIN{print ($t1 - $t0)/1e9}")
  target=$([ "$kind" = ply ] && echo 50 || echo 200)
  echo "{\"bench\":\"facefit_fit_batch\",\"output\":\"$kind\",\"fits\":50,\"seconds\":$secs,\"fits_per_s\":$(awk "BEGIN{print 50/$secs}"),\"target_fits_per_s\":$target}"
done
