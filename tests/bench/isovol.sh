#!/usr/bin/env bash
# isosurf and volrender benchmarks against VTK in the same run (JSON lines), by hand:
#   tests/bench/isovol.sh [BUILD_DIR]
# The VTK volume mapper needs an X display: run under Xvfb (xvfb-run, Debian xvfb).
set -euo pipefail
build="${1:-build}"
"$build/bin/bench_isosurf"
"$(dirname "$0")/isosurf_adaptive.sh" "$build"
xvfb-run -a -s "-screen 0 1024x768x24" "$build/bin/bench_volrender"
