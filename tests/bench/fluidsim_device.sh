#!/usr/bin/env bash
# Packs bench_fluidsim with the shared libraries it needs beyond the C library (FFTW,
# libgomp, {fmt}, libstdc++, libgcc_s) into one folder that can be carried to a machine
# without Debian's packages (the project's `device` machine: 16 cores), and prints the
# command to run there. Issue 23's fluidsim row: speed-up >= 3x at 4 threads and >= 8x at
# 16 on 128^3, fdm and fft, read with tests/bench/fluidsim_amdahl.py or directly from
# the "speedup" field of each line.
#
#   tests/bench/fluidsim_device.sh [build/bin] [build-device]
set -euo pipefail
BIN=${1:-build/bin}
OUT=${2:-build-device}
[ -x "$BIN/bench_fluidsim" ] || { echo "fluidsim_device.sh: build bench_fluidsim first (cmake --build build --target bench_fluidsim)" >&2; exit 2; }
rm -rf "$OUT"
mkdir -p "$OUT"
cp "$BIN/bench_fluidsim" "$OUT/"
# Every library ldd resolves, except the C library's own (libc, libm, the loader), which
# any Linux has and which must match its kernel interface.
ldd "$BIN/bench_fluidsim" | awk '$3 ~ /^\// {print $3}' | while read -r lib; do
  case "$(basename "$lib")" in
    libc.so.*|libm.so.*|ld-linux*|libpthread.so.*|libdl.so.*|librt.so.*) ;;
    *) cp -L "$lib" "$OUT/" ;;
  esac
done
du -sh "$OUT" >&2
echo "LD_LIBRARY_PATH=$OUT $OUT/bench_fluidsim --sizes 64,128 --threads 1,4,16 --steps 5 --nu 1e-4 --poisson fdm,fft"
