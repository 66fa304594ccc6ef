#!/usr/bin/env python3
"""Small NRRD volumes for the isosurf/volrender CLI tests, and independent checks of
their outputs (pure Python: no fest code).

  fixtures.py volume KIND OUT.nrrd      sphere | torus | slab | ramp | quadratic | blob | xramp | xramp2 | nan | flat
  fixtures.py crossings IN.nrrd ISO     number of voxel edges whose ends lie on both sides of ISO
  fixtures.py plycheck MESH.ply         binary PLY: every edge in exactly two triangles, in
                                        opposite directions -> prints "closed V F chi area volume"
  fixtures.py pfm IMG.pfm X Y           prints the RGB of pixel (X, Y) (Y from the top)
  fixtures.py centroid IMG.pfm          intensity-weighted centroid "x y" of channel 0
  fixtures.py subset A.ply B.ply        exit 0 when every vertex of A is a vertex of B (bitwise)
  fixtures.py png OUT.png W H R,G,B[,A]  a constant 8-bit RGB(A) PNG
  fixtures.py pngpixel IN.png X Y       prints the channels of pixel (X, Y) of an 8-bit PNG
  fixtures.py radial MESH.ply X,Y,Z      binary PLY with nx ny nz: the largest angle (degrees)
                                        between a vertex normal and the ray from (X, Y, Z) to it
  fixtures.py stream OUT N              a fest frame stream (man/man5/fest-frame.5) of N frames, field
                                        density on 24^3: a Gaussian blob at x = 7 + 3k in frame k
  fixtures.py series OUT.nrrd N         the same N frames as one 4-D NRRD (a time series)
  fixtures.py raw OUT.raw OUT.nrrd      one int16 volume twice: headerless big-endian, and NRRD
                                        (little-endian, spacing 0.5 0.5 1.25)
  fixtures.py mask OUT.png W H          a screen mask: pixel (x, y) marked (white, opaque) iff
                                        x < W/2 and y >= 2; rows 0-1 white but transparent; the
                                        right half black
  fixtures.py maskcheck FULL MASKED W H R,G,B
                                        PFMs: marked pixels of MASKED equal FULL bit for bit, the
                                        others are exactly the background R,G,B
  fixtures.py trianglecheck FULL MASKED W H R,G,B LEG
                                        PFMs: pixels with centres inside the triangle (0,0),
                                        (LEG,0), (0,LEG) equal FULL bit for bit, the others are the
                                        background; prints how many are inside
  fixtures.py pyramidcheck COMP.png TOP.png RIGHT.png BOTTOM.png LEFT.png W H
                                        COMP equals, byte for byte, the part whose triangle of the
                                        image diagonals holds each pixel centre (alpha 0: any colour)
  fixtures.py crop IN.ply OUT.ply X,Y,Z R0 R1
                                        binary PLY of the triangles whose three vertices lie at a
                                        distance in [R0, R1) from (X, Y, Z) (for region-wise
                                        Hausdorff distances; unused vertices dropped)
"""
import math
import struct
import sys


def write_nrrd(path, dims, values, spacing=(1, 1, 1)):
    with open(path, "wb") as f:
        f.write(b"NRRD0004\ntype: float\ndimension: 3\n")
        f.write(("sizes: %d %d %d\n" % dims).encode())
        f.write(("spacings: %r %r %r\n" % spacing).encode())
        f.write(b"encoding: raw\nendian: little\n\n")
        f.write(struct.pack("<%df" % len(values), *values))


def read_nrrd(path):
    data = open(path, "rb").read()
    head, body = data.split(b"\n\n", 1)
    dims = None
    for line in head.decode().splitlines():
        if line.startswith("sizes:"):
            dims = tuple(int(x) for x in line.split()[1:])
    n = dims[0] * dims[1] * dims[2]
    return dims, struct.unpack("<%df" % n, body[: 4 * n])


def field(dims, f):
    nx, ny, nz = dims
    return [f(i, j, k) for k in range(nz) for j in range(ny) for i in range(nx)]


def volume(kind, out):
    if kind == "sphere":  # R = 9.3 in 24^3, high inside
        c = 11.5
        write_nrrd(out, (24, 24, 24), field((24, 24, 24), lambda i, j, k: 9.3 - math.sqrt((i - c) ** 2 + (j - c) ** 2 + (k - c) ** 2)))
    elif kind == "torus":  # R = 8, r = 3.5 in 28 x 28 x 16
        write_nrrd(out, (28, 28, 16), field((28, 28, 16), lambda i, j, k: 3.5 - math.hypot(math.hypot(i - 13.5, j - 13.5) - 8, k - 7.5)))
    elif kind == "slab":  # homogeneous 33^3 (docs/volrender.md)
        write_nrrd(out, (33, 33, 33), [5.0] * 33 ** 3)
    elif kind == "ramp":  # f = y / 32
        write_nrrd(out, (33, 33, 33), field((33, 33, 33), lambda i, j, k: j / 32.0))
    elif kind == "quadratic":  # f = (y / 32)^2 at the samples
        write_nrrd(out, (33, 33, 33), field((33, 33, 33), lambda i, j, k: (j / 32.0) ** 2))
    elif kind == "blob":  # a bright Gaussian off centre, 40^3, spacing 0.01 (a 0.4 m box)
        write_nrrd(out, (40, 40, 40), field((40, 40, 40), lambda i, j, k: 100 * math.exp(-((i - 24) ** 2 + (j - 17) ** 2 + (k - 20) ** 2) / 6.0)),
                   spacing=(0.01, 0.01, 0.01))
    elif kind == "xramp":  # f = x on 65^3 (slice contours)
        write_nrrd(out, (65, 65, 65), field((65, 65, 65), lambda i, j, k: float(i)))
    elif kind == "xramp2":  # f = i on 33^3 with spacing 2: |grad f| = 1/2 per world unit
        write_nrrd(out, (33, 33, 33), field((33, 33, 33), lambda i, j, k: float(i)), spacing=(2, 2, 2))
    elif kind == "nan":
        v = [0.0] * 8 ** 3
        v[100] = float("nan")
        write_nrrd(out, (8, 8, 8), v)
    elif kind == "flat":  # 2-D: 16 x 16 x 1
        write_nrrd(out, (16, 16, 1), [float(i % 16) for i in range(256)])
    else:
        sys.exit("unknown kind " + kind)


def blob_frame(k):
    return field((24, 24, 24), lambda i, j, m: 100 * math.exp(-((i - 7 - 3 * k) ** 2 + (j - 11.5) ** 2 + (m - 11.5) ** 2) / 8.0))


def stream(out, n):
    with open(out, "wb") as f:
        for k in range(n):
            f.write(("NRRD0004\n# fest-frame: index=%d time=%d fields=density:1\ntype: float\ndimension: 4\n"
                     "sizes: 1 24 24 24\nkinds: list space space space\nspacings: nan 1 1 1\nendian: little\n"
                     "encoding: raw\n\n" % (k, k)).encode())
            v = blob_frame(k)
            f.write(struct.pack("<%df" % len(v), *v))


def series(out, n):
    with open(out, "wb") as f:
        f.write(("NRRD0004\ntype: float\ndimension: 4\nsizes: 24 24 24 %d\nspacings: 1 1 1 1\n"
                 "encoding: raw\nendian: little\n\n" % n).encode())
        for k in range(n):
            v = blob_frame(k)
            f.write(struct.pack("<%df" % len(v), *v))


def raw_pair(raw, nrrd):
    dims = (20, 17, 13)
    v = field(dims, lambda i, j, k: int(round(1000 * math.exp(-((i - 9.5) ** 2 / 30 + (j - 8) ** 2 / 20 + (k - 6) ** 2 / 12)))) - 300)
    open(raw, "wb").write(struct.pack(">%dh" % len(v), *v))
    with open(nrrd, "wb") as f:
        f.write(b"NRRD0004\ntype: short\ndimension: 3\nsizes: 20 17 13\nspacings: 0.5 0.5 1.25\nencoding: raw\nendian: little\n\n")
        f.write(struct.pack("<%dh" % len(v), *v))


def marked(x, y, w):
    return x < w // 2 and y >= 2


def mask(out, w, h):
    import zlib
    rows = []
    for y in range(h):
        line = bytearray(b"\0")
        for x in range(w):
            line += bytes((255, 255, 255, 255) if marked(x, y, w) else (255, 255, 255, 0) if y < 2 else (0, 0, 0, 255))
        rows.append(bytes(line))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)
    open(out, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(b"".join(rows))) + chunk(b"IEND", b""))


def maskcheck(full, masked, w, h, bg):
    wf, hf, ch, a = read_pfm(full)
    wm, hm, _, b = read_pfm(masked)
    if (wf, hf, wm, hm) != (w, h, w, h):
        sys.exit("size")
    bg = [struct.unpack("<f", struct.pack("<f", float(x)))[0] for x in bg.split(",")]
    for y in range(h):  # y from the top; PFM rows are stored bottom up
        row = h - 1 - y
        for x in range(w):
            p = (row * w + x) * ch
            want = a[p:p + 3] if marked(x, y, w) else tuple(bg)
            if struct.pack("<3f", *b[p:p + 3]) != struct.pack("<3f", *want):
                sys.exit("pixel %d %d: %r, expected %r" % (x, y, b[p:p + 3], want))


def crossings(path, iso):
    (nx, ny, nz), v = read_nrrd(path)
    inside = [x >= iso for x in v]
    n = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                p = i + nx * (j + ny * k)
                if i + 1 < nx and inside[p] != inside[p + 1]:
                    n += 1
                if j + 1 < ny and inside[p] != inside[p + nx]:
                    n += 1
                if k + 1 < nz and inside[p] != inside[p + nx * ny]:
                    n += 1
    print(n)


def plycheck(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode().splitlines()
    nv = nf = 0
    vprops = []
    in_vertex = False
    for line in head:
        w = line.split()
        if w[:2] == ["element", "vertex"]:
            nv, in_vertex = int(w[2]), True
        elif w[:2] == ["element", "face"]:
            nf, in_vertex = int(w[2]), False
        elif w[0] == "property" and in_vertex:
            vprops.append(w[1])
    assert all(p == "float" for p in vprops), vprops
    stride = 4 * len(vprops)
    pos = end
    V = []
    for _ in range(nv):
        V.append(struct.unpack_from("<3f", data, pos))
        pos += stride
    uses = {}
    area = vol = 0.0
    for _ in range(nf):
        cnt = data[pos]
        assert cnt == 3
        a, b, c = struct.unpack_from("<3I", data, pos + 1)
        pos += 13
        for x, y in ((a, b), (b, c), (c, a)):
            key = (min(x, y), max(x, y))
            fwd, bwd = uses.get(key, (0, 0))
            uses[key] = (fwd + (x < y), bwd + (x > y))
        A, B, C = V[a], V[b], V[c]
        u = [B[i] - A[i] for i in range(3)]
        w = [C[i] - A[i] for i in range(3)]
        cr = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        area += 0.5 * math.sqrt(sum(x * x for x in cr))
        vol += (A[0] * (B[1] * C[2] - B[2] * C[1]) - A[1] * (B[0] * C[2] - B[2] * C[0]) + A[2] * (B[0] * C[1] - B[1] * C[0])) / 6
    closed = all(f == 1 and b == 1 for f, b in uses.values())
    print("closed" if closed else "open", nv, nf, nv - len(uses) + nf, "%.6f" % area, "%.6f" % vol)


def ply_vertices(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    nv = [int(l.split()[2]) for l in data[:end].decode().splitlines() if l.startswith("element vertex")][0]
    return {data[end + 12 * i: end + 12 * i + 12] for i in range(nv)}


def read_pfm(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    kind, (w, h), scale = parts[0], map(int, parts[1].split()), float(parts[2])
    ch = 3 if kind == b"PF" else 1
    fmt = "<" if scale < 0 else ">"
    vals = struct.unpack(fmt + "%df" % (w * h * ch), parts[3][: 4 * w * h * ch])
    return w, h, ch, vals  # rows bottom to top


def pfm(path, x, y):
    w, h, ch, v = read_pfm(path)
    row = h - 1 - y
    p = (row * w + x) * ch
    print(" ".join("%.9f" % v[p + c] for c in range(ch)))


def centroid(path):
    w, h, ch, v = read_pfm(path)
    sx = sy = s = 0.0
    for row in range(h):
        for x in range(w):
            val = v[(row * w + x) * ch]
            y = h - 1 - row
            sx += val * (x + 0.5)
            sy += val * (y + 0.5)
            s += val
    print("%.6f %.6f" % (sx / s, sy / s))


def png_write(path, w, h, px):
    import zlib
    raw = b"".join(b"\0" + bytes(px) * w for _ in range(h))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 6 if len(px) == 4 else 2, 0, 0, 0)
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def png_rows(path):
    """(w, h, channels, rows of bytes) of an 8-bit PNG."""
    import zlib
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, t = struct.unpack(">I4s", data[pos:pos + 8])
        d = data[pos + 8:pos + 8 + n]
        if t == b"IHDR":
            w, h, bits, ctype = struct.unpack(">IIBB", d[:10])
            assert bits == 8
            ch = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
        elif t == b"IDAT":
            idat += d
        pos += 12 + n
    raw, stride, prev, rows = zlib.decompress(idat), w * ch, bytearray(w * ch), []
    for r in range(h):
        f, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b, c = prev[i], prev[i - ch] if i >= ch else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, ch, rows


def png_pixel(path, x, y):
    _, _, ch, rows = png_rows(path)
    print(" ".join(str(v) for v in rows[y][x * ch:(x + 1) * ch]))


def trianglecheck(full, masked, w, h, bg, leg):
    """The right triangle (0,0), (leg,0), (0,leg) in pixel coordinates (y down): pixel (i, j)
    has its centre (i + 1/2, j + 1/2) strictly inside iff i + j + 1 < leg; the centres with
    i + j + 1 = leg lie on the hypotenuse, which the tie rule (move to +x) leaves outside.
    So the marked pixels are i + j <= leg - 2, (leg - 1) leg / 2 of them."""
    wf, hf, ch, a = read_pfm(full)
    wm, hm, _, b = read_pfm(masked)
    if (wf, hf, wm, hm) != (w, h, w, h):
        sys.exit("size")
    bg = [struct.unpack("<f", struct.pack("<f", float(x)))[0] for x in bg.split(",")]
    count = 0
    for y in range(h):
        row = h - 1 - y
        for x in range(w):
            p = (row * w + x) * ch
            inside = x + y <= leg - 2
            count += inside
            want = a[p:p + 3] if inside else tuple(bg)
            if struct.pack("<3f", *b[p:p + 3]) != struct.pack("<3f", *want):
                sys.exit("pixel %d %d: %r, expected %r" % (x, y, b[p:p + 3], want))
    print(count)


def pyramidcheck(composite, parts, w, h):
    """The four triangles of the diagonals of a w x h image (top, right, bottom, left; w, h
    chosen so that no pixel centre lies on a diagonal): every pixel of the composite equals,
    byte for byte, the part whose triangle holds its centre. Exact rational arithmetic."""
    from fractions import Fraction as F
    cw, chh, cc, crow = png_rows(composite)
    if (cw, chh) != (w, h):
        sys.exit("size")
    rows = [png_rows(p) for p in parts]
    partial = clear = 0
    for y in range(h):
        for x in range(w):
            u, v = F(2 * x + 1, 2 * w), F(2 * y + 1, 2 * h)   # centre in [0,1]^2, v down
            if u == v or u + v == 1:
                sys.exit("centre on a diagonal: choose another size")
            k = (0 if u > v else 3) if u + v < 1 else (1 if u > v else 2)
            pw, ph, pc, prow = rows[k]
            got = bytes(crow[y][x * cc:(x + 1) * cc])
            want = bytes(prow[y][x * pc:(x + 1) * pc])
            # a fully transparent pixel (alpha 0) has no colour: composite writes 0, a
            # --bg none rendering may keep the colour of a trace of opacity
            if pc != cc or (got != want and not (cc == 4 and got[3] == 0 and want[3] == 0)):
                sys.exit("pixel %d %d: %r, part %d has %r" % (x, y, got, k, want))
            partial += cc == 4 and 0 < got[3] < 255
            clear += cc == 4 and got[3] == 0
    print("%d pixels, %d partly transparent, %d transparent" % (w * h, partial, clear))


def radial(path, centre):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode().splitlines()
    nv = [int(l.split()[2]) for l in head if l.startswith("element vertex")][0]
    props = []
    for l in head:
        if l.startswith("element face"):
            break
        if l.startswith("property"):
            props.append(l.split()[2])
    assert props[:6] == ["x", "y", "z", "nx", "ny", "nz"], props
    c = [float(x) for x in centre.split(",")]
    worst = 0.0
    for i in range(nv):
        x = struct.unpack_from("<6f", data, end + 4 * len(props) * i)
        r = [x[a] - c[a] for a in range(3)]
        rl = math.sqrt(sum(v * v for v in r))
        nl = math.sqrt(sum(v * v for v in x[3:]))
        cosang = sum(r[a] * x[3 + a] for a in range(3)) / (rl * nl)
        worst = max(worst, math.degrees(math.acos(max(-1.0, min(1.0, cosang)))))
    print("%.6f" % worst)


def crop(src, dst, centre, r0, r1):
    data = open(src, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode().splitlines()
    nv = [int(l.split()[2]) for l in head if l.startswith("element vertex")][0]
    nf = [int(l.split()[2]) for l in head if l.startswith("element face")][0]
    nprops = 0
    for l in head:
        if l.startswith("element face"):
            break
        if l.startswith("property"):
            nprops += 1
    assert all(l.split()[1] == "float" for l in head if l.startswith("property") and "list" not in l)
    stride = 4 * nprops
    c = [float(x) for x in centre.split(",")]
    V, keep = [], []
    for i in range(nv):
        x = struct.unpack_from("<3f", data, end + stride * i)
        V.append(x)
        d = math.sqrt(sum((x[a] - c[a]) ** 2 for a in range(3)))
        keep.append(r0 <= d < r1)
    pos = end + stride * nv
    F = []
    for _ in range(nf):
        assert data[pos] == 3
        t = struct.unpack_from("<3I", data, pos + 1)
        pos += 13
        if keep[t[0]] and keep[t[1]] and keep[t[2]]:
            F.append(t)
    used = sorted({v for t in F for v in t})
    new = {v: i for i, v in enumerate(used)}
    out = bytearray(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
                     "property float y\nproperty float z\nelement face %d\n"
                     "property list uchar uint vertex_indices\nend_header\n" % (len(used), len(F))).encode())
    for v in used:
        out += struct.pack("<3f", *V[v])
    for t in F:
        out += struct.pack("<B3I", 3, new[t[0]], new[t[1]], new[t[2]])
    open(dst, "wb").write(out)
    print(len(used), len(F))


if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "volume":
        volume(sys.argv[2], sys.argv[3])
    elif cmd == "crossings":
        crossings(sys.argv[2], float(sys.argv[3]))
    elif cmd == "plycheck":
        plycheck(sys.argv[2])
    elif cmd == "pfm":
        pfm(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif cmd == "centroid":
        centroid(sys.argv[2])
    elif cmd == "subset":
        sys.exit(0 if ply_vertices(sys.argv[2]) <= ply_vertices(sys.argv[3]) else 1)
    elif cmd == "png":
        png_write(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), [int(v) for v in sys.argv[5].split(",")])
    elif cmd == "pngpixel":
        png_pixel(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif cmd == "radial":
        radial(sys.argv[2], sys.argv[3])
    elif cmd == "stream":
        stream(sys.argv[2], int(sys.argv[3]))
    elif cmd == "series":
        series(sys.argv[2], int(sys.argv[3]))
    elif cmd == "raw":
        raw_pair(sys.argv[2], sys.argv[3])
    elif cmd == "mask":
        mask(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif cmd == "maskcheck":
        maskcheck(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]), sys.argv[6])
    elif cmd == "trianglecheck":
        trianglecheck(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]), sys.argv[6], int(sys.argv[7]))
    elif cmd == "pyramidcheck":
        pyramidcheck(sys.argv[2], sys.argv[3:7], int(sys.argv[7]), int(sys.argv[8]))
    elif cmd == "crop":
        crop(sys.argv[2], sys.argv[3], sys.argv[4], float(sys.argv[5]), float(sys.argv[6]))
    else:
        sys.exit(__doc__)
