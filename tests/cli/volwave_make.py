#!/usr/bin/env python3
"""Analytic test volumes for tests/cli/volwave.sh, written as raw NRRD (no numpy needed).

  volwave_make.py KIND OUT.nrrd

KIND: smooth (float32 blob + noise), ct (int16 blob + noise), nan (float32 with a NaN),
sphere (float32, radius 9.3 about (16.2, 15.7, 14.4), one-voxel linear ramp across the
surface), step (float32, 0 for x <= 12, 100 for x >= 13: the edge at x = 12.5),
cylinder (float32, radius 7.6 about the z axis through (15.5, 16.25), blurred by a
Gaussian of sigma 1.2 voxels: erfc profile), mask (uint8 box 8..15 x 8..15 x 4..9).
"""
import math
import struct
import sys

N = (32, 30, 28)


def lcg(seed):
    state = seed
    while True:
        state = (6364136223846793005 * state + 1442695040888963407) % (1 << 64)
        yield ((state >> 11) / float(1 << 53)) - 0.5


def write(path, kind, dims, values, spacing=(1.0, 1.0, 1.0)):
    fmt = {"float": "<f", "short": "<h", "uchar": "<B"}[kind]
    data = b"".join(struct.pack(fmt, v) for v in values)
    header = (
        "NRRD0004\n"
        f"type: {kind}\n"
        "dimension: 3\n"
        f"sizes: {dims[0]} {dims[1]} {dims[2]}\n"
        "space: right-anterior-superior\n"
        f"space directions: ({spacing[0]},0,0) (0,{spacing[1]},0) (0,0,{spacing[2]})\n"
        "space origin: (0,0,0)\n"
        "endian: little\n"
        "encoding: raw\n\n"
    )
    with open(path, "wb") as f:
        f.write(header.encode() + data)


def grid(dims, fn):
    return [fn(x, y, z) for z in range(dims[2]) for y in range(dims[1]) for x in range(dims[0])]


def main():
    kind, out = sys.argv[1], sys.argv[2]
    noise = lcg(12345)
    if kind in ("smooth", "ct", "nan"):
        def blob(x, y, z):
            r2 = (x - 15.5) ** 2 + (y - 13.0) ** 2 + (z - 11.0) ** 2
            return 200.0 + 800.0 * math.exp(-r2 / 60.0) + 40.0 * math.sin(x / 3.0) + 8.0 * next(noise)
        vals = grid(N, blob)
        if kind == "ct":
            write(out, "short", N, [int(round(v)) - 1000 for v in vals], (0.8, 0.8, 1.5))
            return
        if kind == "nan":
            vals[137] = float("nan")
        write(out, "float", N, vals, (0.5, 0.5, 0.5))
    elif kind == "sphere":
        c, r = (16.2, 15.7, 14.4), 9.3
        def sphere(x, y, z):
            d = math.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2)
            return 100.0 * min(1.0, max(0.0, r - d + 0.5))
        write(out, "float", N, grid(N, sphere))
    elif kind == "step":
        write(out, "float", N, grid(N, lambda x, y, z: 0.0 if x <= 12 else 100.0))
    elif kind == "cylinder":
        c, r, s = (15.5, 16.25), 7.6, 1.2
        def cyl(x, y, z):
            d = math.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2)
            return 100.0 * 0.5 * math.erfc((d - r) / (s * math.sqrt(2.0)))
        write(out, "float", N, grid(N, cyl))
    elif kind == "mask":
        write(out, "uchar", N, grid(N, lambda x, y, z: 1 if 8 <= x <= 15 and 8 <= y <= 15 and 4 <= z <= 9 else 0))
    else:
        sys.exit(f"unknown kind {kind}")


if __name__ == "__main__":
    main()
