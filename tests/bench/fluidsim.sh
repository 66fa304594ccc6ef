#!/usr/bin/env bash
# fluidsim benchmark: one JSON line per (size, solver, threads, stage) from
# `fluidsim bench`, with the Stam-2003 anchor (stam03 order, 20 Gauss-Seidel sweeps:
# solver "gs") and 40 Jacobi sweeps measured in the same run, next to the exact
# solvers (fdm, fft) and multigrid. Not run by CTest (timings on shared machines are
# noise for pass/fail); read the figures, compare with docs/fluidsim.md §7.
#
#   tests/bench/fluidsim.sh [build/bin] [sizes] [threads] [steps]
#   tests/bench/fluidsim.sh build/bin 31,64,128 1,2,4,8,16 10     # a machine with 16 cores
#   tests/bench/fluidsim.sh build/bin 64 1,2 3 | tests/bench/fluidsim_amdahl.py
#       per-stage speed-up at the second thread count, parallel fraction p, Amdahl 4 / 16
set -euo pipefail
BIN=${1:-build/bin}
SIZES=${2:-16,31,50,64}
THREADS=${3:-1,2}
STEPS=${4:-5}
# nu = 0 (the paper's air: no diffusion stage) and nu > 0 (three Helmholtz solves a step).
"$BIN/fluidsim" bench --sizes "$SIZES" --threads "$THREADS" --steps "$STEPS" --poisson fdm,fft,mg,gs,jacobi --nu 0
"$BIN/fluidsim" bench --sizes "$SIZES" --threads "$THREADS" --steps "$STEPS" --poisson fdm,fft --nu 1e-4
