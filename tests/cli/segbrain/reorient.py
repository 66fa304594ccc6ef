#!/usr/bin/env python3
"""Test helper for segbrain.sh (standard library only).

  reorient.py permute IN.nii OUT.nii   stores a float32/uint8 NIfTI with voxel axes
                                       (posterior, superior, right): "PSR", the same
                                       anatomy with another axis order and a flip;
  reorient.py compare A.nii B.nii      A is a label volume in RAS voxel order, B the one
                                       in PSR order; exit 0 when they agree voxel by voxel.
Only files written by fest (vox_offset 352, sform set, little-endian) are handled.
"""
import struct
import sys

TYPES = {2: ('B', 1), 16: ('f', 4)}


def read(path):
    data = open(path, 'rb').read()
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


if __name__ == '__main__':
    if sys.argv[1] == 'permute':
        permute(sys.argv[2], sys.argv[3])
    else:
        sys.exit(compare(sys.argv[2], sys.argv[3]))
