#!/usr/bin/env bash
# decimate against meshoptimizer, OpenMesh's Decimater and CGAL's edge_collapse on the
# fetched real meshes (scripts/fetch-test-data.sh), then a table: faces, Hausdorff and
# RMS error relative to the bounding-box diagonal (fcompare's metric), CPU ms. The CGAL
# anchor is compiled only with cmake -DFEST_BENCH_CGAL=ON (about 8 minutes on 2 cores).
#
#   tests/bench/decimate_bench.sh [BUILD_BIN] [RATIOS]     e.g. build/bin 0.1,0.02
set -eu
bin="${1:-build/bin}"
ratios="${2:-0.1,0.02}"
data="${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}/meshes"
meshes=()
for m in man bunny00 armadillo fandisk elephant camel; do
  [ -f "$data/$m.off" ] && meshes+=("$data/$m.off")
done
[ ${#meshes[@]} -gt 0 ] || { echo "no meshes under $data (run scripts/fetch-test-data.sh)" >&2; exit 77; }
"$bin/bench_decimate" "${meshes[@]}" --ratios "$ratios" | tee decimate_bench.jsonl |
  jq -r '[.mesh, .ratio, .method, .faces_kept, (.hausdorff_rel | . * 1e4 | round / 1e4 | tostring), (.rms_rel | . * 1e5 | round / 1e5 | tostring), (.cpu_ms | round)] | @tsv'
