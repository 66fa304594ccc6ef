#!/usr/bin/env python3
"""Test helper for segbrain.sh (standard library only).

  reorient.py permute IN.nii OUT.nii   stores a float32/uint8 NIfTI with voxel axes
                                       (posterior, superior, right): "PSR", the same
                                       anatomy with another axis order and a flip;
  reorient.py compare A.nii B.nii      A is a label volume in RAS voxel order, B the one
                                       in PSR order; exit 0 when they agree voxel by voxel.
  reorient.py shuffle IN.nii OUT.nii   any stored orientation: voxel axes rotated (new
                                       axes = old z, x, y) and the new second axis flipped,
                                       the sform rewritten to keep every voxel's world place;
  reorient.py unshuffled A.nii B.nii   A labels of IN, B labels of OUT: exit 0 when they
                                       agree voxel by voxel after undoing the shuffle;
  reorient.py centroid IN.nii[.gz] LO HI [LO HI ...]  world (sform) centroid of the
                                       voxels with LO <= value <= HI, printed "R A S";
  reorient.py nerves LABELS.nii[.gz] NERVE EYE  for the voxels labelled NERVE on
                                       either side of the midline (the mean world R of
                                       all of them): "side touches_eye front_R front_A
                                       back_R back_A" per side, touches_eye = voxels with
                                       an EYE voxel within 2 voxels, front/back = world
                                       mean of the side's most anterior/posterior 5 mm;
  reorient.py bias IN.nii OUT.nii G    intensities times a smooth field, linear along the
                                       three voxel axes, from 1 - G to 1 + G corner to
                                       corner (the shading of a receive coil).
Only files written by fest (vox_offset 352, sform set, little-endian) are handled.
"""
import gzip
import struct
import sys

TYPES = {2: ('B', 1), 4: ('h', 2), 8: ('i', 4), 16: ('f', 4), 512: ('H', 2)}


def read(path):
    data = gzip.open(path).read() if path.endswith('.gz') else open(path, 'rb').read()
    dims = struct.unpack_from('<8h', data, 40)
    dtype = struct.unpack_from('<h', data, 70)[0]
    pix = struct.unpack_from('<8f', data, 76)
    offset = int(struct.unpack_from('<f', data, 108)[0])
    srow = [struct.unpack_from('<4f', data, 280 + 16 * r) for r in range(3)]
    code, size = TYPES[dtype]
    n = dims[1] * dims[2] * dims[3]
    values = struct.unpack_from('<%d%s' % (n, code), data, offset)
    return data, dims[1:4], pix[1:4], srow, dtype, values


def permute(src, dst):
    data, (nx, ny, nz), (sx, sy, sz), srow, dtype, v = read(src)
    ox, oy, oz = srow[0][3], srow[1][3], srow[2][3]
    out = [0] * len(v)
    # new voxel (a, b, c) = source (x = c, y = ny-1-a, z = b); dims (ny, nz, nx)
    for c in range(nx):
        for b in range(nz):
            for a in range(ny):
                out[a + ny * (b + nz * c)] = v[c + nx * ((ny - 1 - a) + ny * b)]
    h = bytearray(data[:352])
    struct.pack_into('<8h', h, 40, 3, ny, nz, nx, 1, 1, 1, 1)
    struct.pack_into('<4f', h, 80, sy, sz, sx, 1)
    struct.pack_into('<hh', h, 252, 0, 1)  # qform_code 0, sform_code 1
    struct.pack_into('<4f', h, 280, 0, 0, sx, ox)
    struct.pack_into('<4f', h, 296, -sy, 0, 0, oy + sy * (ny - 1))
    struct.pack_into('<4f', h, 312, 0, sz, 0, oz)
    code, _ = TYPES[dtype]
    open(dst, 'wb').write(bytes(h) + struct.pack('<%d%s' % (len(out), code), *out))


def compare(ras_path, psr_path):
    _, (nx, ny, nz), _, _, _, a = read(ras_path)
    _, dims, _, _, _, b = read(psr_path)
    if tuple(dims) != (ny, nz, nx):
        print('dims differ', dims)
        return 1
    bad = 0
    for c in range(nx):
        for bb in range(nz):
            for aa in range(ny):
                if b[aa + ny * (bb + nz * c)] != a[c + nx * ((ny - 1 - aa) + ny * bb)]:
                    bad += 1
    print('%d voxels differ' % bad)
    return 1 if bad else 0


PERM = (2, 0, 1)       # new axis k comes from old axis PERM[k]
FLIP = (False, True, False)


def shuffled_index(dims, new):
    """Old voxel (x, y, z) shown at new voxel `new`."""
    old = [0, 0, 0]
    for k in range(3):
        old[PERM[k]] = dims[PERM[k]] - 1 - new[k] if FLIP[k] else new[k]
    return old


def shuffle(src, dst):
    data, dims, pix, srow, dtype, v = read(src)
    nd = [dims[PERM[k]] for k in range(3)]
    out = [0] * len(v)
    for c in range(nd[2]):
        for b in range(nd[1]):
            for a in range(nd[0]):
                x, y, z = shuffled_index(dims, (a, b, c))
                out[a + nd[0] * (b + nd[1] * c)] = v[x + dims[0] * (y + dims[1] * z)]
    cols = [[srow[r][PERM[k]] * (-1 if FLIP[k] else 1) for r in range(3)] for k in range(3)]
    origin = [srow[r][3] + sum(srow[r][PERM[k]] * (dims[PERM[k]] - 1) for k in range(3) if FLIP[k]) for r in range(3)]
    h = bytearray(data[:352])
    struct.pack_into('<8h', h, 40, 3, nd[0], nd[1], nd[2], 1, 1, 1, 1)
    struct.pack_into('<3f', h, 80, *[pix[PERM[k]] for k in range(3)])
    struct.pack_into('<hh', h, 252, 0, 1)  # qform_code 0, sform_code 1
    for r in range(3):
        struct.pack_into('<4f', h, 280 + 16 * r, cols[0][r], cols[1][r], cols[2][r], origin[r])
    code, _ = TYPES[dtype]
    open(dst, 'wb').write(bytes(h) + struct.pack('<%d%s' % (len(out), code), *out))


def unshuffled(a_path, b_path):
    _, dims, _, _, _, a = read(a_path)
    _, nd, _, _, _, b = read(b_path)
    if tuple(nd) != tuple(dims[PERM[k]] for k in range(3)):
        print('dims differ', nd)
        return 1
    bad = 0
    for c in range(nd[2]):
        for bb in range(nd[1]):
            for aa in range(nd[0]):
                x, y, z = shuffled_index(dims, (aa, bb, c))
                if b[aa + nd[0] * (bb + nd[1] * c)] != a[x + dims[0] * (y + dims[1] * z)]:
                    bad += 1
    print('%d voxels differ' % bad)
    return 1 if bad else 0


def centroid(path, ranges):
    _, dims, _, srow, _, v = read(path)
    s = [0.0, 0.0, 0.0]
    n = 0
    for i, x in enumerate(v):
        if any(lo <= x <= hi for lo, hi in ranges):
            s[0] += i % dims[0]
            s[1] += (i // dims[0]) % dims[1]
            s[2] += i // (dims[0] * dims[1])
            n += 1
    c = [t / n for t in s]
    print(' '.join('%.3f' % (srow[r][0] * c[0] + srow[r][1] * c[1] + srow[r][2] * c[2] + srow[r][3]) for r in range(3)))


def nerves(path, nerve, eye):
    _, dims, _, srow, _, v = read(path)
    nx, ny = dims[0], dims[1]
    def world(i):
        p = (i % nx, (i // nx) % ny, i // (nx * ny))
        return [srow[r][0] * p[0] + srow[r][1] * p[1] + srow[r][2] * p[2] + srow[r][3] for r in range(3)]
    idx = [i for i, x in enumerate(v) if x == nerve]
    if not idx:
        return 1
    pts = {i: world(i) for i in idx}
    mid = sum(p[0] for p in pts.values()) / len(pts)
    for name, side in (('left', [i for i in idx if pts[i][0] < mid]), ('right', [i for i in idx if pts[i][0] >= mid])):
        touch = 0
        for i in side:
            x, y, z = i % nx, (i // nx) % ny, i // (nx * ny)
            near = False
            for dz in range(-2, 3):
                for dy in range(-2, 3):
                    for dx in range(-2, 3):
                        if 0 <= x + dx < nx and 0 <= y + dy < ny and 0 <= z + dz < dims[2]:
                            near = near or v[(x + dx) + nx * ((y + dy) + ny * (z + dz))] == eye
            touch += near
        a = [pts[i][1] for i in side]
        front = [pts[i] for i in side if pts[i][1] >= max(a) - 5]
        back = [pts[i] for i in side if pts[i][1] <= min(a) + 5]
        mean = lambda ps, k: sum(p[k] for p in ps) / len(ps)
        print('%s %d %.1f %.1f %.1f %.1f' % (name, touch, mean(front, 0), mean(front, 1), mean(back, 0), mean(back, 1)))
    return 0


def bias(src, dst, g):
    data, dims, _, _, dtype, v = read(src)
    code, _ = TYPES[dtype]
    out = []
    for i, x in enumerate(v):
        p = (i % dims[0], (i // dims[0]) % dims[1], i // (dims[0] * dims[1]))
        t = sum(p[k] / (dims[k] - 1) for k in range(3)) / 3 * 2 - 1   # -1 .. 1
        y = x * (1 + g * t)
        out.append(y if code == 'f' else int(round(y)))
    off = int(struct.unpack_from('<f', data, 108)[0])
    open(dst, 'wb').write(data[:off] + struct.pack('<%d%s' % (len(out), code), *out))


if __name__ == '__main__':
    if sys.argv[1] == 'permute':
        permute(sys.argv[2], sys.argv[3])
    elif sys.argv[1] == 'shuffle':
        shuffle(sys.argv[2], sys.argv[3])
    elif sys.argv[1] == 'centroid':
        vals = [float(t) for t in sys.argv[3:]]
        centroid(sys.argv[2], list(zip(vals[0::2], vals[1::2])))
    elif sys.argv[1] == 'nerves':
        sys.exit(nerves(sys.argv[2], int(sys.argv[3]), int(sys.argv[4])))
    elif sys.argv[1] == 'bias':
        bias(sys.argv[2], sys.argv[3], float(sys.argv[4]))
    elif sys.argv[1] == 'unshuffled':
        sys.exit(unshuffled(sys.argv[2], sys.argv[3]))
    else:
        sys.exit(compare(sys.argv[2], sys.argv[3]))
