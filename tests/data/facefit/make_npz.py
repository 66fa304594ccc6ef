#!/usr/bin/env python3
"""Writes the .npz fixtures of the facefit tests with Python's standard library only
(zipfile + the .npy v1.0 header exactly as numpy.save writes it), so that the reader is
tested against an independent writer. Model: p = 4 points, k = 2 components,
basis columns e_0 and e_5 of R^12 (orthonormal), sigma 3 and 2, two triangles."""
import struct
import zipfile

def npy(values, shape, dtype, fortran=False):
    header = "{'descr': '%s', 'fortran_order': %s, 'shape': %s, }" % (
        dtype, "True" if fortran else "False",
        "(%d,)" % shape[0] if len(shape) == 1 else "(" + ", ".join(str(s) for s in shape) + ")")
    # numpy pads the header with spaces and a newline to a multiple of 64 bytes.
    total = 10 + len(header) + 1
    header += " " * ((64 - total % 64) % 64) + "\n"
    code = {"<f8": "d", "<f4": "f", "<i4": "i", "<i8": "q"}[dtype]
    if fortran and len(shape) == 2:
        r, c = shape
        values = [values[i * c + j] for j in range(c) for i in range(r)]
    body = struct.pack("<" + code * len(values), *values)
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + body

mean = [float(v) for v in range(12)]
basis = [0.0] * 24          # 12 x 2, C order: row r, column c at r*2 + c
basis[0 * 2 + 0] = 1.0
basis[5 * 2 + 1] = 1.0
tris = [0, 1, 2, 0, 2, 3]

with zipfile.ZipFile("model_stored_f8.npz", "w", zipfile.ZIP_STORED) as z:
    z.writestr("mean.npy", npy(mean, (12,), "<f8"))
    z.writestr("basis.npy", npy(basis, (12, 2), "<f8"))
    z.writestr("sigma.npy", npy([3.0, 2.0], (2,), "<f8"))
    z.writestr("triangles.npy", npy(tris, (2, 3), "<i4"))

with zipfile.ZipFile("model_bfm_deflated_f4.npz", "w", zipfile.ZIP_DEFLATED) as z:
    z.writestr("shapeMU.npy", npy(mean, (12, 1), "<f4"))
    z.writestr("shapePC.npy", npy(basis, (12, 2), "<f4", fortran=True))
    z.writestr("pcaVariance.npy", npy([9.0, 4.0], (2,), "<f4"))
    z.writestr("tl.npy", npy([t + 1 for t in tris], (2, 3), "<i8"))
