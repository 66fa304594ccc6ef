#!/usr/bin/env bash
# The lmfsim chain benchmark of docs/lmfsim.md §7, with ODE (libode-dev) on the same chains
# in the same run: one JSON line per case on standard output.
#   tests/bench/lmfsim_chain.sh [build-dir] [--quick]
set -eu
build="${1:-build}"
shift || true
exec "$build/bin/bench_lmfsim" "$@"
