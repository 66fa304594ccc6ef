#!/usr/bin/env python3
"""Generates the small hand-made image fixtures in this folder (run from here).

Every fixture encodes the same 2 x 2 pattern, stated in image (top-down) order:
  grey:   (x=0,y=0)=1  (x=1,y=0)=2  (x=0,y=1)=3  (x=1,y=1)=4
  colour: (0,0) blue (0,0,1)  (1,0) red (1,0,0)  (0,1) green (0,1,0)  (1,1) (0.5,0.25,-2)
PFM stores rows bottom to top; the sign of the scale gives the byte order
(negative: little-endian, positive: big-endian).
"""
import struct

GREY = [[1.0, 2.0], [3.0, 4.0]]
COLOUR = [[(0, 0, 1), (1, 0, 0)], [(0, 1, 0), (0.5, 0.25, -2.0)]]


def pfm(name, magic, rows, big_endian, scale):
    order = '>' if big_endian else '<'
    data = b''
    for row in reversed(rows):  # bottom row first
        for px in row:
            values = px if isinstance(px, tuple) else (px,)
            data += struct.pack(order + 'f' * len(values), *values)
    header = b'%s\n%d %d\n%s\n' % (magic, len(rows[0]), len(rows), scale)
    with open(name, 'wb') as f:
        f.write(header + data)


pfm('grey_big_endian.pfm', b'Pf', GREY, True, b'1.0')
pfm('grey_little_endian.pfm', b'Pf', GREY, False, b'-1.0')
pfm('colour_big_endian.pfm', b'PF', COLOUR, True, b'2.5')
pfm('colour_little_endian.pfm', b'PF', COLOUR, False, b'-1')

# Plain PGM with comments between every header token, maxval 1000 (so 16-bit).
with open('comments_ascii.pgm', 'wb') as f:
    f.write(b'P2 # magic\n# a whole comment line\n2 # width\n2\n1000 # maxval\n1 2\n3 4\n')
# Raw PPM, maxval 255, the colour pattern with 0.5/0.25/-2 as 128/64/0.
with open('pattern_raw.ppm', 'wb') as f:
    f.write(b'P6\n2 2\n255\n' + bytes([0, 0, 255, 255, 0, 0, 0, 255, 0, 128, 64, 0]))
