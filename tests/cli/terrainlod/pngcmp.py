#!/usr/bin/env python3
"""Compare two renderings of the same terrain view (terrainlod extract --png), without and
with --clip, using only the standard library (an 8-bit RGB PNG decoder of its own).

  pngcmp.py FULL.png CLIPPED.png [x0 y0 x1 y1]

Checks, printing one line per failure (exit 1 on any):
  - every pixel covered (not sky) in CLIPPED is covered in FULL, with the same colour
    (within 2 levels: a cut triangle is the same plane, its shading rounds alike);
  - with the pixel rectangle x0..x1, y0..y1 where the DEM projects (a view from straight
    above): CLIPPED draws every pixel inside it (no bite out of the DEM) and nothing
    outside it (none of the padding), each up to a margin of 1.5 pixels.
Prints "lost N" (pixels FULL covers and CLIPPED not) on success."""
import struct
import sys
import zlib

SKY = (235, 240, 245)  # the renderer's background (RGB)


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and ctype == 2, "8-bit RGB expected"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, bpp, stride = zlib.decompress(idat), 3, 3 * w
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def main():
    w, h, full = read_png(sys.argv[1])
    w2, h2, clip = read_png(sys.argv[2])
    assert (w, h) == (w2, h2), "sizes differ"
    rect = [float(v) for v in sys.argv[3:7]] if len(sys.argv) >= 7 else None
    bad, lost = [], 0
    for y in range(h):
        for x in range(w):
            a, b = tuple(full[y][3 * x:3 * x + 3]), tuple(clip[y][3 * x:3 * x + 3])
            ca, cb = a != SKY, b != SKY
            cx, cy, m = x + 0.5, y + 0.5, 1.5
            inside = rect and rect[0] + m <= cx <= rect[2] - m and rect[1] + m <= cy <= rect[3] - m
            outside = rect and not (rect[0] - m <= cx <= rect[2] + m and rect[1] - m <= cy <= rect[3] + m)
            if cb and outside:
                bad.append(f"pixel {x},{y}: outside the DEM, drawn with --clip")
            elif cb and not ca:
                bad.append(f"pixel {x},{y}: drawn with --clip only")
            elif cb and max(abs(p - q) for p, q in zip(a, b)) > 2:
                bad.append(f"pixel {x},{y}: {a} without --clip, {b} with")
            elif ca and not cb:
                lost += 1
                if inside:
                    bad.append(f"pixel {x},{y}: inside the DEM, lost by --clip")
            elif inside and not cb:
                bad.append(f"pixel {x},{y}: inside the DEM, not drawn")
    for line in bad[:10]:
        print(line)
    if bad:
        print(f"{len(bad)} bad pixels")
        return 1
    print(f"lost {lost}")
    return 0


sys.exit(main())
