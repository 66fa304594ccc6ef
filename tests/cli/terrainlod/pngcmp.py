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
import os
import sys

SKY = (235, 240, 245)  # the renderer's background (RGB)


# One PNG decoder for the CLI tests: the volrender fixtures' (standard library only).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "isovol"))
from fixtures import png_rows  # noqa: E402


def read_png(path):
    w, h, ch, rows = png_rows(path)
    assert ch == 3, "8-bit RGB expected (%s)" % path
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
