#!/usr/bin/env python3
"""Inputs of tests/bench/batch.sh, made deterministically from real data (standard library only).

  batch_inputs.py crops  N OUTDIR SRC.ppm...   N 512x384 binary PPM crops, OUTDIR/imgNNNN.ppm
  batch_inputs.py meshes N OUTDIR SRC.off...   N binary PLY meshes, OUTDIR/meshNNNN.ply

crops: the windows go round the sources in turn; the k-th window of a source sits on a
grid of 8-pixel steps walked with a stride coprime to the grid size, so windows of one
source differ and the same N always gives the same files. Sources smaller than 512x384
are skipped.

meshes: the k-th file is source k mod len(SRC) (triangle OFF files), rotated about z by
k times the golden angle, scaled by 1 + (k mod 7)/10 and moved by k/10 along x: the same
connectivity with different coordinates, so every file is a different real mesh.
"""
import math
import os
import struct
import sys

W, H, STEP = 512, 384, 8


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval (comments allowed between)
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    if fields[0] != b"P6" or fields[3] != b"255":
        raise SystemExit(f"batch_inputs: {path}: not an 8-bit binary PPM")
    return int(fields[1]), int(fields[2]), data[pos + 1:]


def crops(n, outdir, sources):
    images = [read_ppm(p) for p in sources]
    images = [im for im in images if im[0] >= W and im[1] >= H]
    if not images:
        raise SystemExit("batch_inputs: no source of at least 512x384")
    taken = [0] * len(images)
    for k in range(n):
        s = k % len(images)
        width, height, pixels = images[s]
        nx, ny = (width - W) // STEP + 1, (height - H) // STEP + 1
        cells = nx * ny
        stride = 7919 if math.gcd(7919, cells) == 1 else 1  # a prime: visits every cell once
        cell = (taken[s] * stride) % cells
        taken[s] += 1
        x0, y0 = (cell % nx) * STEP, (cell // nx) * STEP
        rows = [pixels[((y0 + y) * width + x0) * 3:((y0 + y) * width + x0 + W) * 3] for y in range(H)]
        with open(os.path.join(outdir, f"img{k:04d}.ppm"), "wb") as f:
            f.write(b"P6\n%d %d\n255\n" % (W, H))
            f.write(b"".join(rows))


def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#", 1)[0].split()]
    if tokens[0] != "OFF":
        raise SystemExit(f"batch_inputs: {path}: not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    verts = [tuple(float(t) for t in tokens[pos + 3 * i:pos + 3 * i + 3]) for i in range(nv)]
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        m = int(tokens[pos])
        faces.append(tuple(int(t) for t in tokens[pos + 1:pos + 1 + m]))
        pos += 1 + m
    return verts, faces


def meshes(n, outdir, sources):
    models = [read_off(p) for p in sources]
    golden = math.pi * (3 - math.sqrt(5))
    for k in range(n):
        verts, faces = models[k % len(models)]
        a, s, t = k * golden, 1 + (k % 7) / 10, k / 10
        c, sn = math.cos(a) * s, math.sin(a) * s
        body = bytearray()
        for x, y, z in verts:
            body += struct.pack("<3f", c * x - sn * y + t, sn * x + c * y, s * z)
        for f in faces:
            body += struct.pack("<B%di" % len(f), len(f), *f)
        header = ("ply\nformat binary_little_endian 1.0\ncomment batch.sh input %d\n"
                  "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                  % (k, len(verts), len(faces)))
        with open(os.path.join(outdir, f"mesh{k:04d}.ply"), "wb") as f:
            f.write(header.encode("ascii"))
            f.write(body)


def main(argv):
    if len(argv) < 4 or argv[0] not in ("crops", "meshes"):
        raise SystemExit(__doc__)
    (crops if argv[0] == "crops" else meshes)(int(argv[1]), argv[2], argv[3:])


if __name__ == "__main__":
    main(sys.argv[1:])
