#!/usr/bin/env python3
"""Generates the small volume fixtures of tests/unit/test_volume_*.cpp (python3, stdlib only).

Every fixture holds a 4x3x2 grid whose values follow a formula the tests restate, so the
expectations come from the formula, not from fest's own output:

  be_int16.nii     NIfTI-1, BIG-endian, int16, v = x + 10y + 100z - 50,
                   sform_code 2: srow_x = (-1.5,0,0,10), srow_y = (0,2,0,-20), srow_z = (0,0,2.5,5)
  scaled_uint8.nii NIfTI-1, uint8 stored s = x + 4y + 12z, scl_slope 0.5, scl_inter -10,
                   no qform/sform: pixdim (0.5, 0.75, 1.25)
  qform_only.nii   NIfTI-1, float32, v = 0.25 * (x + 4y + 12z), qform_code 1, sform_code 0,
                   quaternion (b,c,d) = (0,0,sqrt(1/2)) (90 degrees about z), qfac -1,
                   pixdim (2,3,4), qoffset (10,20,30)
  lps_ascii.nrrd   NRRD, ascii, int16, space LPS, v = x + 10y + 100z - 50,
                   space directions (-1.5,0,0) (0,2,0) (0,0,2.5) (LPS), origin (-10,20,5) (LPS)
                   i.e. in RAS: directions diag(1,-1,1), spacing (1.5,2,2.5), origin (10,-20,5)
  gzip_uint16.nrrd NRRD, gzip, big-endian uint16, v = 1000 + x + 4y + 12z, spacings 0.5 0.5 2
  msb_short.mha    MetaImage, MET_SHORT, ElementByteOrderMSB True, v = x + 10y + 100z - 50,
                   TransformMatrix = 0 1 0  -1 0 0  0 0 1 (axis0 = +y LPS, axis1 = -x LPS),
                   Offset 1 2 3 (LPS), ElementSpacing 0.5 0.25 2
  zlib_float.mha   MetaImage, MET_FLOAT, CompressedData True (zlib), v = 0.5 * (x + 4y + 12z)
"""
import gzip
import math
import struct
import zlib

NX, NY, NZ = 4, 3, 2


def grid(f):
    return [f(x, y, z) for z in range(NZ) for y in range(NY) for x in range(NX)]


def nifti_header(endian, datatype, bitpix, pixdim, slope, inter, qform, sform, quat, srow):
    h = bytearray(352)
    struct.pack_into(endian + "i", h, 0, 348)
    struct.pack_into(endian + "8h", h, 40, 3, NX, NY, NZ, 1, 1, 1, 1)
    struct.pack_into(endian + "hh", h, 70, datatype, bitpix)
    struct.pack_into(endian + "8f", h, 76, *pixdim)
    struct.pack_into(endian + "fff", h, 108, 352.0, slope, inter)
    h[123] = 2  # mm
    struct.pack_into(endian + "hh", h, 252, qform, sform)
    struct.pack_into(endian + "6f", h, 256, *quat)
    struct.pack_into(endian + "12f", h, 280, *srow)
    h[344:348] = b"n+1\0"
    return bytes(h)


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


# be_int16.nii
values = grid(lambda x, y, z: x + 10 * y + 100 * z - 50)
hdr = nifti_header(">", 4, 16, (1, 1.5, 2, 2.5, 0, 0, 0, 0), 1.0, 0.0, 0, 2, (0,) * 6,
                   (-1.5, 0, 0, 10, 0, 2, 0, -20, 0, 0, 2.5, 5))
write("be_int16.nii", hdr + struct.pack(">%dh" % len(values), *values))

# scaled_uint8.nii
stored = grid(lambda x, y, z: x + 4 * y + 12 * z)
hdr = nifti_header("<", 2, 8, (1, 0.5, 0.75, 1.25, 0, 0, 0, 0), 0.5, -10.0, 0, 0, (0,) * 6, (0,) * 12)
write("scaled_uint8.nii", hdr + bytes(stored))

# qform_only.nii
values = grid(lambda x, y, z: 0.25 * (x + 4 * y + 12 * z))
hdr = nifti_header("<", 16, 32, (-1, 2, 3, 4, 0, 0, 0, 0), 0.0, 0.0, 1, 0,
                   (0, 0, math.sqrt(0.5), 10, 20, 30), (0,) * 12)
write("qform_only.nii", hdr + struct.pack("<%df" % len(values), *values))

# lps_ascii.nrrd
values = grid(lambda x, y, z: x + 10 * y + 100 * z - 50)
text = ("NRRD0004\n# ascii fixture\ntype: short\ndimension: 3\nspace: left-posterior-superior\n"
        "sizes: 4 3 2\nspace directions: (-1.5,0,0) (0,2,0) (0,0,2.5)\nkinds: domain domain domain\n"
        "encoding: ascii\nspace origin: (-10,20,5)\nkey:=value with: colon\n\n")
text += "\n".join(" ".join(str(v) for v in values[i:i + NX]) for i in range(0, len(values), NX)) + "\n"
write("lps_ascii.nrrd", text.encode())

# gzip_uint16.nrrd
values = grid(lambda x, y, z: 1000 + x + 4 * y + 12 * z)
head = ("NRRD0005\ntype: uint16\ndimension: 3\nsizes: 4 3 2\nspacings: 0.5 0.5 2\nendian: big\n"
        "encoding: gzip\n\n").encode()
write("gzip_uint16.nrrd", head + gzip.compress(struct.pack(">%dH" % len(values), *values), mtime=0))

# msb_short.mha
values = grid(lambda x, y, z: x + 10 * y + 100 * z - 50)
head = ("ObjectType = Image\nNDims = 3\nBinaryData = True\nElementByteOrderMSB = True\n"
        "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nOffset = 1 2 3\nElementSpacing = 0.5 0.25 2\n"
        "DimSize = 4 3 2\nElementType = MET_SHORT\nElementDataFile = LOCAL\n").encode()
write("msb_short.mha", head + struct.pack(">%dh" % len(values), *values))

# zlib_float.mha
values = grid(lambda x, y, z: 0.5 * (x + 4 * y + 12 * z))
payload = zlib.compress(struct.pack("<%df" % len(values), *values))
head = ("ObjectType = Image\r\nNDims = 3\r\nBinaryData = True\r\nBinaryDataByteOrderMSB = False\r\n"
        "CompressedData = True\r\nCompressedDataSize = %d\r\nDimSize = 4 3 2\r\nElementType = MET_FLOAT\r\n"
        "ElementDataFile = LOCAL\r\n" % len(payload)).encode()
write("zlib_float.mha", head + payload)
