#!/usr/bin/env bash
# volwave benchmark: bytes and decode time against ZFP (fixed-accuracy mode at the same
# L-infinity bound), gzip -9, zstd -19 and Blosc (zstd 9 + shuffle), all measured in the
# same run by bench_volwave on real volumes: the CT head (cranium.nrrd), the MRI head
# (ch2.nii.gz) of scripts/fetch-test-data.sh, a fluidsim smoke plume (density of the
# last frame) and an lbmsim flow past a sphere in a duct (speed |u| of the last step).
# One JSON line per (volume, codec, bound). Not run by CTest; read the figures
# (docs/volwave.md §8 has a table of one run).
#
#   tests/bench/volwave.sh [build/bin] [plume size] [repeat] [cases]
#
# cases: a comma-separated list of ct,mri,plume,lbm,lbm-centred (default: the first four).
set -euo pipefail
BIN=${1:-build/bin}
N=${2:-64}
REPEAT=${3:-3}
CASES=,${4:-ct,mri,plume,lbm},
want() { [[ $CASES == *",$1,"* ]]; }
for c in ${CASES//,/ }; do
  case $c in ct|mri|plume|lbm|lbm-centred) ;; *) echo "volwave.sh: unknown case '$c' (ct, mri, plume, lbm, lbm-centred)" >&2; exit 2 ;; esac
done
DATA=${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/volwave-bench.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

for f in volumes/cranium.nrrd mri/ch2.nii.gz; do
  case $f in volumes/*) want ct || continue ;; *) want mri || continue ;; esac
  if [ -f "$DATA/$f" ]; then
    "$BIN/bench_volwave" --repeat "$REPEAT" --bounds 0.5,1,2,4,8,16 "$DATA/$f"
  else
    echo "{\"skipped\": \"$f (run scripts/fetch-test-data.sh)\"}"
  fi
done

# A smoke plume as in examples/Makefile (sphere source, buoyancy, a vortex), N^3.
if want plume; then
FR=40
printf '{"dims": [%d, %d, %d], "frame_dt": 0.04, "frames": %d, "interp": 5,
 "scalars": [{"name": "density", "alpha": 0.02, "sources": [{"shape": "sphere", "centre": [%d, %d, %d], "radius": %d, "rate": 6, "velocity": [0, 0, 0.25]}]}],
 "forces": [{"type": "buoyancy", "scalar": "density", "beta": 2.0}, {"type": "vortex", "centre": [%d, %d, %d], "strength": 0.02, "radius": %d}]}\n' \
  "$N" "$N" "$N" "$FR" $((N / 2)) $((N / 2)) $((N / 10 + 2)) $((N / 12 + 1)) $((N / 2)) $((N / 2)) $((N / 2)) $((N / 4)) >"$WORK/plume.json"
"$BIN/fluidsim" run "$WORK/plume.json" --fields density -o - >"$WORK/plume.stream"
"$BIN/bench_volwave" --repeat "$REPEAT" --frame $((FR - 1)) --bounds 1e-4,1e-3,1e-2 "$WORK/plume.stream"
fi

# lbmsim: D3Q19 flow past a sphere (diameter 16, Bouzidi walls) in a 96x64x64 duct with
# no-slip walls, a parabolic inlet (U_max 0.08, Mach 0.14) and a pressure outlet; TRT,
# Re = U_max D / nu = 100, float arithmetic, 1500 steps (the recirculation behind the
# sphere at x = 16..32 ends near x = 45; the wake's velocity deficit reaches the outlet).
# The field is the speed |u| of the last step (0 inside the sphere, up to ~0.087 in the
# duct's core): the scalar one renders and isosurfaces in a flow. It is in lattice
# units, so the bounds are fractions of its range (1e-5 of the range is ~110 float32
# ulps of the maximum). About 35 s on one core.
# Case lbm: the sphere off the duct's axis (centre y = 29, z = 34), so the field has no
# symmetry, as behind any real obstacle. Case lbm-centred (not in the default list): the
# sphere on the axis; the field is then mirror-symmetric in y and z up to rounding, and
# rows (y, z) and (63 - y, z) are nearly the same bytes, which dictionary coders
# (zstd, gzip) find and a wavelet coder does not (docs/volwave.md section 8).
lbm_case() {  # lbm_case NAME CENTRE-Y CENTRE-Z
  cat >"$WORK/$1.json" <<JSON
{ "lattice": "d3q19", "size": [96, 64, 64],
  "collision": { "model": "trt", "nu": 0.0128 },
  "faces": { "x-": { "velocity": { "profile": "parabolic", "u": 0.08 } }, "x+": { "pressure": { "rho": 1.0 } },
             "y-": "wall", "y+": "wall", "z-": "wall", "z+": "wall" },
  "geometry": [ { "sphere": { "center": [24, $2, $3], "radius": 8, "flag": 1 } } ],
  "curved_walls": "bouzidi", "init": { "u": [0.035, 0, 0] },
  "u_ref": 0.08, "l_ref": 16, "steps": 1500,
  "output": { "fields": ["speed"] } }
JSON
  "$BIN/lbmsim" -q run "$WORK/$1.json" --precision float -o - >"$WORK/$1.stream"
  "$BIN/bench_volwave" --repeat "$REPEAT" --field speed --range-bounds 1e-5,1e-4,1e-3,1e-2 "$WORK/$1.stream"
}
if want lbm; then lbm_case lbm_sphere 29 34; fi
if want lbm-centred; then lbm_case lbm_sphere_centred 32 32; fi
