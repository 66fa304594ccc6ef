#!/usr/bin/env python3
"""Gzipped Cesium quantized-mesh-1.0 size of tile triangulations (OBJ files from
`terrainlod decode --to obj`), for the size comparison of specs/terrainlod.md section 7.
Written here from the format's published layout (88-byte header; u, v, height as 15-bit
values, zig-zag delta coded uint16; high-water-mark coded uint16 indices; four edge index
lists), independent of terrainlod's own coder. Prints the total gzipped bytes."""
import gzip, struct, sys

def zz(v):
    return ((v << 1) ^ (v >> 31)) & 0xFFFF

def qm_bytes(path):
    vs, fs = [], []
    for line in open(path):
        if line.startswith('v '):
            vs.append(tuple(map(float, line.split()[1:4])))
        elif line.startswith('f '):
            fs.append([int(t.split('/')[0]) - 1 for t in line.split()[1:4]])
    xs, ys, zs = zip(*vs)
    x0, x1, y0, y1, z0, z1 = min(xs), max(xs), min(ys), max(ys), min(zs), max(zs)
    q = lambda a, lo, hi: int(round((a - lo) / (hi - lo) * 32767)) if hi > lo else 0
    u = [q(x, x0, x1) for x in xs]; v = [q(y, y0, y1) for y in ys]; h = [q(z, z0, z1) for z in zs]
    out = bytearray(struct.pack('<3d2f4d3d', (x0+x1)/2, (y0+y1)/2, (z0+z1)/2, z0, z1,
                                (x0+x1)/2, (y0+y1)/2, (z0+z1)/2, max(x1-x0, y1-y0), 0, 0, 0))
    out += struct.pack('<I', len(vs))
    for arr in (u, v, h):
        prev = 0
        for a in arr:
            out += struct.pack('<H', zz(a - prev)); prev = a
    out += struct.pack('<I', len(fs))
    hw = 0
    for f in fs:
        for i in f:
            out += struct.pack('<H', hw - i); hw += (i == hw)
    for side in ([i for i in range(len(vs)) if u[i] == 0], [i for i in range(len(vs)) if v[i] == 0],
                 [i for i in range(len(vs)) if u[i] == 32767], [i for i in range(len(vs)) if v[i] == 32767]):
        out += struct.pack('<I', len(side)) + b''.join(struct.pack('<H', i) for i in side)
    return gzip.compress(bytes(out), 6)

print(sum(len(qm_bytes(p)) for p in sys.argv[1:]))
