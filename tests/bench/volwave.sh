#!/usr/bin/env bash
# volwave benchmark: bytes and decode time against ZFP (fixed-accuracy mode at the same
# L-infinity bound), gzip -9, zstd -19 and Blosc (zstd 9 + shuffle), all measured in the
# same run by bench_volwave on real volumes: the CT head (cranium.nrrd), the MRI head
# (ch2.nii.gz) of scripts/fetch-test-data.sh, and a fluidsim smoke plume (density of
# the last frame). One JSON line per (volume, codec, bound). Not run by CTest; read the
# figures (docs/volwave.md §8 has a table of one run).
#
#   tests/bench/volwave.sh [build/bin] [plume size] [repeat]
set -euo pipefail
BIN=${1:-build/bin}
N=${2:-64}
REPEAT=${3:-3}
DATA=${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/volwave-bench.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

for f in volumes/cranium.nrrd mri/ch2.nii.gz; do
  if [ -f "$DATA/$f" ]; then
    "$BIN/bench_volwave" --repeat "$REPEAT" --bounds 0.5,1,2,4,8,16 "$DATA/$f"
  else
    echo "{\"skipped\": \"$f (run scripts/fetch-test-data.sh)\"}"
  fi
done

# A smoke plume as in examples/Makefile (sphere source, buoyancy, a vortex), N^3.
FR=40
printf '{"dims": [%d, %d, %d], "frame_dt": 0.04, "frames": %d, "interp": 5,
 "scalars": [{"name": "density", "alpha": 0.02, "sources": [{"shape": "sphere", "centre": [%d, %d, %d], "radius": %d, "rate": 6, "velocity": [0, 0, 0.25]}]}],
 "forces": [{"type": "buoyancy", "scalar": "density", "beta": 2.0}, {"type": "vortex", "centre": [%d, %d, %d], "strength": 0.02, "radius": %d}]}\n' \
  "$N" "$N" "$N" "$FR" $((N / 2)) $((N / 2)) $((N / 10 + 2)) $((N / 12 + 1)) $((N / 2)) $((N / 2)) $((N / 2)) $((N / 4)) >"$WORK/plume.json"
"$BIN/fluidsim" run "$WORK/plume.json" --fields density -o - >"$WORK/plume.stream"
"$BIN/bench_volwave" --repeat "$REPEAT" --frame $((FR - 1)) --bounds 1e-4,1e-3,1e-2 "$WORK/plume.stream"
