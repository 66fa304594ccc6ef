#!/usr/bin/env bash
# lbmsim benchmark: JSON lines of MLUPS for D3Q19 double/float at 128^3 and D2Q9 at
# 1024^2 on 1 and 2 threads, each next to the copy bandwidth and the roofline
# (copy bytes/s / (2 Q sizeof(real))) measured in the same run; then MPI strong scaling
# of a 3-D lid-driven cavity on 1/2/4 ranks (when the build has MPI). Not run by CTest:
# timings on shared machines are noise for pass/fail; read the figures.
#
#   tests/bench/lbmsim.sh [build/bin] [threads] [size3d] [size2d]
set -euo pipefail
BIN=${1:-build/bin}
THREADS=${2:-1,2}
N3=${3:-128}
N2=${4:-1024}
"$BIN/lbmsim" bench --lattice d3q19 --size "$N3" --steps 20 --precision double,float --threads "$THREADS"
"$BIN/lbmsim" bench --lattice d3q19 --size "$N3" --steps 20 --precision double --threads 1 --collision trt
"$BIN/lbmsim" bench --lattice d2q9 --size "$N2" --steps 50 --precision double,float --threads "$THREADS"

if "$BIN/lbmsim" --version | grep -q "with MPI" && command -v mpirun >/dev/null; then
  WORK=$(mktemp -d)
  trap 'rm -rf "$WORK"' EXIT
  cat >"$WORK/cav.json" <<'JSON'
{ "size": [64, 64, 64], "re": 100, "u_ref": 0.1, "collision": { "model": "trt" },
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0, 0] } }, "z-": "wall", "z+": "wall" },
  "steps": 100, "output": { "fields": ["speed"] } }
JSON
  for np in 1 2 4; do
    mpirun --oversubscribe --allow-run-as-root -np "$np" "$BIN/lbmsim" run "$WORK/cav.json" --threads 1 \
      -o "$WORK/r$np.vti" --report "$WORK/r$np.json"
    jq -c --argjson np "$np" '{bench: "lbmsim_mpi_strong", size: 64, ranks: $np, threads: 1, steps, wall_seconds, mlups}' "$WORK/r$np.json"
  done
  cmp "$WORK/r1.vti" "$WORK/r4.vti" && echo '{"bench":"lbmsim_mpi_identical","ranks":[1,4],"identical":true}'
fi
