#!/usr/bin/env python3
"""Measures an extracted terrain mesh against the nodata samples of its DEM, independently
of fest: the DEM is read from an ESRI ASCII grid (written by the test, or by GDAL's
gdal_translate from a GeoTIFF), the mesh from an OBJ file.

    holes.py MESH.obj DEM.asc  ->  JSON on standard output

Sample (i, j) (j from the south) lies at x = xll + (i + 1/2) c, y = yll + (nrows - 1/2 - r) c
for row r from the north; grid units are (x - x0) / c with x0 the south-west sample. Beyond
the last column/row a pyramid pads by repeating the edge samples, so a point there has the
validity of the nearest edge sample.

  triangles           faces of the mesh
  over_nodata         faces whose closed footprint holds a nodata sample (exact, integers)
  nonlattice          faces with a vertex off the sample lattice (clipped meshes have some;
                      over_nodata is then counted on the lattice faces only)
  drawn_area          xy area of the faces inside the DEM rectangle, in cells
  dem_area            (ncols - 1)(nrows - 1) cells
  valid_fraction      valid samples / all samples
  all_nodata_area     area of the faces over cells whose four corners are all nodata
"""
import json
import sys


def read_asc(path):
    head, rows = {}, []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0][0].isalpha():
                head[parts[0].lower()] = parts[1]
            else:
                rows.append([float(v) for v in parts])
    nc, nr = int(head["ncols"]), int(head["nrows"])
    nd = float(head.get("nodata_value", "nan"))
    cs = float(head["cellsize"])
    x0 = float(head["xllcorner"]) + cs / 2
    y0 = float(head["yllcorner"]) + cs / 2
    values = [v for r in rows for v in r]
    assert len(values) == nc * nr, (len(values), nc, nr)
    nodata = [[False] * nc for _ in range(nr)]  # [j][i], j from the south
    for r in range(nr):
        for i in range(nc):
            v = values[r * nc + i]
            nodata[nr - 1 - r][i] = v == nd or v != v
    return nc, nr, cs, x0, y0, nodata


def read_obj(path):
    vs, fs = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vs.append(tuple(float(t) for t in line.split()[1:4]))
            elif line.startswith("f "):
                fs.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
    return vs, fs


def clip(poly, inside, cut):
    out = []
    for k in range(len(poly)):
        a, b = poly[k - 1], poly[k]
        if inside(b):
            if not inside(a):
                out.append(cut(a, b))
            out.append(b)
        elif inside(a):
            out.append(cut(a, b))
    return out


def clip_rect(poly, x0, y0, x1, y1):
    def cx(v):
        return lambda a, b: (v, a[1] + (b[1] - a[1]) * (v - a[0]) / (b[0] - a[0]))

    def cy(v):
        return lambda a, b: (a[0] + (b[0] - a[0]) * (v - a[1]) / (b[1] - a[1]), v)

    poly = clip(poly, lambda p: p[0] >= x0, cx(x0))
    poly = clip(poly, lambda p: p[0] <= x1, cx(x1))
    poly = clip(poly, lambda p: p[1] >= y0, cy(y0))
    poly = clip(poly, lambda p: p[1] <= y1, cy(y1))
    return poly


def area(poly):
    return abs(sum(poly[k - 1][0] * poly[k][1] - poly[k][0] * poly[k - 1][1] for k in range(len(poly)))) / 2


def main():
    nc, nr, cs, x0, y0, nodata = read_asc(sys.argv[2])
    vs, fs = read_obj(sys.argv[1])
    grid = [((x - x0) / cs, (y - y0) / cs) for x, y, _ in vs]

    def nd(i, j):
        return nodata[min(j, nr - 1)][min(i, nc - 1)]

    all_nd = [[nodata[j][i] and nodata[j][i + 1] and nodata[j + 1][i] and nodata[j + 1][i + 1] for i in range(nc - 1)]
              for j in range(nr - 1)]
    over = nonlattice = 0
    drawn = all_nd_area = 0.0
    for f in fs:
        p = [grid[k] for k in f]
        q = [(round(x), round(y)) for x, y in p]
        lattice = all(abs(a - b) < 1e-6 and abs(c - d) < 1e-6 for (a, c), (b, d) in zip(p, q))
        if not lattice:
            nonlattice += 1
        else:
            # Exact: (x, y) is in the closed triangle iff the edge functions share a sign.
            xs, ys = [v[0] for v in q], [v[1] for v in q]
            hit = False
            for j in range(max(0, min(ys)), max(ys) + 1):
                for i in range(max(0, min(xs)), max(xs) + 1):
                    s = [(q[(e + 1) % 3][0] - q[e][0]) * (j - q[e][1]) - (q[(e + 1) % 3][1] - q[e][1]) * (i - q[e][0])
                         for e in range(3)]
                    if (min(s) >= 0 or max(s) <= 0) and nd(i, j):
                        hit = True
                        break
                if hit:
                    break
            over += hit
        inside = clip_rect(p, 0, 0, nc - 1, nr - 1)
        if len(inside) >= 3:
            drawn += area(inside)
            xs, ys = [v[0] for v in inside], [v[1] for v in inside]
            for j in range(int(min(ys)), min(int(max(ys)) + 1, nr - 1)):
                for i in range(int(min(xs)), min(int(max(xs)) + 1, nc - 1)):
                    if all_nd[j][i]:
                        piece = clip_rect(inside, i, j, i + 1, j + 1)
                        if len(piece) >= 3:
                            all_nd_area += area(piece)
    valid = sum(not v for row in nodata for v in row)
    json.dump({"triangles": len(fs), "over_nodata": over, "nonlattice": nonlattice, "drawn_area": drawn,
               "dem_area": (nc - 1) * (nr - 1), "valid_fraction": valid / (nc * nr),
               "all_nodata_area": all_nd_area}, sys.stdout)
    print()


main()
