#!/usr/bin/env python3
"""Variants of a .vtu that `lemtrace gen` wrote (raw appended data, UInt64 headers,
little endian, uncompressed), for tests/cli/vtk_robustness.sh.

    vtk_robustness.py GOOD.vtu OUTDIR

Legal re-encodings (ok_*.vtu): the same dataset with UInt32 block headers, with the
data in big-endian byte order, or both, encoded here independently of VTK and fest.
Broken copies (bad_*.vtu): the attributes changed without re-encoding the bytes, a
mistyped DataArray type, an appended block whose length points past the end of the
file, a negative appended offset, a truncated file, unreferenced appended bytes.
"""
import os
import re
import struct
import sys

SIZES = {"Int8": 1, "UInt8": 1, "Int16": 2, "UInt16": 2, "Int32": 4, "UInt32": 4, "Int64": 8,
         "UInt64": 8, "Float32": 4, "Float64": 8, "String": 1}

src, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
data = open(src, "rb").read()
marker = data.index(b"<AppendedData")
start = data.index(b"_", marker) + 1
end = data.rindex(b"</AppendedData>")
markup, appended, tail = data[:start], data[start:end], data[end:]
assert b'header_type="UInt64"' in markup and b'byte_order="LittleEndian"' in markup

# (type, offset) of every appended DataArray, in the order of the markup.
arrays = [(m.group(1).decode(), int(m.group(2)))
          for m in re.finditer(rb'<(?:Data)?Array type="(\w+)"[^>]*?offset="(\d+)"', markup)]


def reencode(header32, big_endian):
    """The appended blocks with other header widths / byte order, and the new offsets."""
    blocks, offsets, pos = [], [], 0
    for kind, offset in arrays:
        (length,) = struct.unpack_from("<Q", appended, offset)
        payload = appended[offset + 8:offset + 8 + length]
        size = SIZES[kind]
        if big_endian and kind != "String" and size > 1:
            payload = b"".join(payload[i:i + size][::-1] for i in range(0, len(payload), size))
        header = struct.pack((">" if big_endian else "<") + ("I" if header32 else "Q"), length)
        offsets.append(pos)
        blocks.append(header + payload)
        pos += len(header) + len(payload)
    new_markup = markup
    # Offsets are padded to a fixed width by VTK's writer; keep the markup's length.
    for (kind, old), new in zip(arrays, offsets):
        new_markup = re.sub(rb'offset="%d"(\s*)' % old,
                            lambda m: b'offset="NEW%d"' % new + m.group(1), new_markup, count=1)
    new_markup = new_markup.replace(b"NEW", b"")
    if header32:
        new_markup = new_markup.replace(b'header_type="UInt64"', b'header_type="UInt32"')
    if big_endian:
        new_markup = new_markup.replace(b'byte_order="LittleEndian"', b'byte_order="BigEndian"')
    return new_markup + b"".join(blocks) + tail


def write(name, content):
    with open(os.path.join(out, name), "wb") as f:
        f.write(content)


write("ok_uint32.vtu", reencode(True, False))
write("ok_bigendian.vtu", reencode(False, True))
write("ok_uint32_bigendian.vtu", reencode(True, True))

write("bad_uint32.vtu", data.replace(b'header_type="UInt64"', b'header_type="UInt32"', 1))
write("bad_no_header_type.vtu", data.replace(b' header_type="UInt64"', b"", 1))
write("bad_bigendian.vtu", data.replace(b'byte_order="LittleEndian"', b'byte_order="BigEndian"', 1))
write("bad_type_typo.vtu", data.replace(b'type="Float64" Name="velocity"', b'type="Flaot64" Name="velocity"', 1))
write("bad_type_int8.vtu", data.replace(b'type="Float64" Name="velocity"', b'type="Int8"    Name="velocity"', 1))
velocity = re.search(rb'Name="velocity"[^>]*?offset="(\d+)', markup)
at = start + int(velocity.group(1))
write("bad_long_block.vtu", data[:at] + struct.pack("<Q", 10**9) + data[at + 8:])
old = velocity.group(0)
write("bad_negative_offset.vtu",
      data.replace(old, old.replace(b'offset="' + velocity.group(1), b'offset="-' + velocity.group(1)[:-1]), 1))
write("bad_truncated.vtu", data[: start + len(appended) // 2])
field = re.search(rb"\s*<FieldData>.*?</FieldData>", markup, re.S)
write("bad_unreferenced.vtu", markup[:field.start()] + markup[field.end():] + appended + tail)
