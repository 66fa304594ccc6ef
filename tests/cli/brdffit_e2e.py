#!/usr/bin/env python3
"""Checks for tests/cli/brdffit_e2e.sh against brdffit synth's ground truth.

Reads the binary files by their documented layouts (ltx(5), ltw(5), PLY) so that the
expectations come from synth's truth.json / mesh_true.ply, not from brdffit's output.

  assignment OBJECT.ltx SVBRDF.ltw truth.json [MIN_SAMPLES]
      fraction of lumitexels whose cluster (from the .ltw) agrees with the true material
      of their triangle, under the best one-to-one matching of clusters to materials,
      over the lumitexels with at least MIN_SAMPLES samples (and their count)
  materials OBJECT.ltx SVBRDF.ltw MESH.ply
      materials JSON (brdffit(1) MATERIALS) that render --svbrdf should derive: every
      triangle the first basis BRDF (f_C) of its lumitexels' majority cluster; triangles
      without lumitexels the majority of their vertex neighbours, wave after wave
  rerender L2_FILE
      median, maximum and count of the relative L2 errors in the file (one per line)
  halves OBJECT.ltx SVBRDF.ltw X0 MIN_SAMPLES
      as assignment, for capture's simulated sphere: material 1 where x < X0, else 0
      (lib/capture/sim_camera.cpp)
  translate MESH.ply DX DY DZ
      the mesh's vertices moved by (DX, DY, DZ) and its faces, as ASCII PLY on stdout
  normals OBJECT.ltx NORMALS.ply mesh_true.ply
      median angle (degrees) of refined and mesh normals to the true interpolated normal
"""
import itertools
import json
import math
import struct
import sys


def read_ltx(path):
    """Lumitexels (p, tri) of an .ltx file (48-byte records after the JSON header)."""
    data = open(path, "rb").read()
    assert data[:8] == b"LUMITEX1", "not an .ltx file"
    hlen = struct.unpack_from("<I", data, 8)[0]
    header = json.loads(data[12:12 + hlen])
    out, pos = [], 12 + hlen
    for _ in range(header["lumitexels"]):
        p = struct.unpack_from("<3f", data, pos)
        tri = struct.unpack_from("<I", data, pos + 24)[0]
        count = struct.unpack_from("<H", data, pos + 46)[0]
        out.append((p, tri, count))
        pos += 48
    return out


def read_ltw_clusters(path, with_header=False):
    """Per-lumitexel cluster of an .ltw file (u16 + f32 weights per record)."""
    data = open(path, "rb").read()
    assert data[:8] == b"LUMIWGT1", "not an .ltw file"
    hlen = struct.unpack_from("<I", data, 8)[0]
    header = json.loads(data[12:12 + hlen])
    per = header["basis_size"] * (3 if header["weights"] == "rgb" else 1)
    pos, out = 12 + hlen, []
    for _ in range(header["lumitexels"]):
        out.append(struct.unpack_from("<H", data, pos)[0])
        pos += 2 + 4 * per
    return (out, header) if with_header else out


def read_ply(path):
    """Vertex rows and faces of a PLY (ascii or binary little endian), by its header."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    lines = data[:end].decode().splitlines()
    fmt = lines[1].split()[1]
    elements, cur = [], None
    for ln in lines:
        w = ln.split()
        if w[0] == "element":
            cur = [w[1], int(w[2]), []]
            elements.append(cur)
        elif w[0] == "property":
            cur[2].append(w[1:])
    sizes = {"float": "f", "double": "d", "uchar": "B", "int": "i", "uint": "I", "char": "b"}
    result = {}
    if fmt == "ascii":
        toks = data[end:].split()
        t = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for pr in props:
                    if pr[0] == "list":
                        n = int(toks[t]); t += 1
                        row.append([int(x) for x in toks[t:t + n]]); t += n
                    else:
                        row.append(float(toks[t])); t += 1
                rows.append(row)
            result[name] = (rows, [pr[-1] for pr in props])
        return result
    pos = end
    for name, count, props in elements:
        rows = []
        for _ in range(count):
            row = []
            for pr in props:
                if pr[0] == "list":
                    n = struct.unpack_from("<" + sizes[pr[1]], data, pos)[0]
                    pos += struct.calcsize(sizes[pr[1]])
                    row.append(list(struct.unpack_from("<%d%s" % (n, sizes[pr[2]]), data, pos)))
                    pos += n * struct.calcsize(sizes[pr[2]])
                else:
                    row.append(struct.unpack_from("<" + sizes[pr[0]], data, pos)[0])
                    pos += struct.calcsize(sizes[pr[0]])
            rows.append(row)
        result[name] = (rows, [pr[-1] for pr in props])
    return result


def assignment(ltx, ltw, truth_path, min_samples="0"):
    truth = json.load(open(truth_path))
    tri_mat = truth["triangle_material"]
    lum = read_ltx(ltx)
    clusters = read_ltw_clusters(ltw)
    assert len(lum) == len(clusters), "ltx and ltw disagree on the lumitexel count"
    k = max(len(truth["materials"]), max(clusters) + 1)
    counts = [[0] * k for _ in range(k)]
    used = 0
    for (_, tri, n), c in zip(lum, clusters):
        if n >= int(min_samples):
            counts[c][tri_mat[tri]] += 1
            used += 1
    best = max(sum(counts[c][perm[c]] for c in range(k)) for perm in itertools.permutations(range(k)))
    print("%.6f %d" % (best / used, used))


def materials(ltx, ltw, mesh_path):
    faces = [r[0] for r in read_ply(mesh_path)["face"][0]]
    triangles = len(faces)
    lum = read_ltx(ltx)
    clusters, header = read_ltw_clusters(ltw, True)
    k = len(header["clusters"])
    votes = [[0] * k for _ in range(int(triangles))]
    total = [0] * k
    for (_, tri, n), c in zip(lum, clusters):
        if n > 0:
            votes[tri][c] += 1
            total[c] += 1
    fallback = total.index(max(total))
    tri_mat = [v.index(max(v)) if max(v) > 0 else fallback for v in votes]
    known = [max(v) > 0 for v in votes]
    around = {}
    for t, f in enumerate(faces):
        for v in f:
            around.setdefault(v, []).append(t)
    while True:
        wave = []
        for t, f in enumerate(faces):
            if known[t]:
                continue
            count = [0] * k
            for v in f:
                for u in around[v]:
                    if known[u]:
                        count[tri_mat[u]] += 1
            if max(count) > 0:
                wave.append((t, count.index(max(count))))
        if not wave:
            break
        for t, c in wave:
            tri_mat[t], known[t] = c, True
    mats = [header["basis"][cl["basis"][0]]["brdf"] for cl in header["clusters"]]
    print(json.dumps({"materials": mats, "triangle_material": tri_mat}))


def rerender(path):
    v = sorted(float(x) for x in open(path).read().split())
    med = v[(len(v) - 1) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])
    print("%.6f %.6f %d" % (med, v[-1], len(v)))


def halves(ltx, ltw, x0, min_samples):
    lum = read_ltx(ltx)
    clusters = read_ltw_clusters(ltw)
    k = max(2, max(clusters) + 1)
    counts = [[0] * k for _ in range(k)]
    used = 0
    for (p, _, n), c in zip(lum, clusters):
        if n >= int(min_samples):
            counts[c][1 if p[0] < float(x0) else 0] += 1
            used += 1
    best = max(sum(counts[c][perm[c]] for c in range(k)) for perm in itertools.permutations(range(k)))
    print("%.6f %d" % (best / used, used))


def translate(mesh_path, dx, dy, dz):
    mesh = read_ply(mesh_path)
    vrows, vnames = mesh["vertex"]
    ix = vnames.index("x")
    faces = [r[0] for r in mesh["face"][0]]
    out = ["ply", "format ascii 1.0", "element vertex %d" % len(vrows)]
    out += ["property double %s" % c for c in "xyz"]
    out += ["element face %d" % len(faces), "property list uchar int vertex_indices", "end_header"]
    d = (float(dx), float(dy), float(dz))
    out += ["%.17g %.17g %.17g" % tuple(r[ix + i] + d[i] for i in range(3)) for r in vrows]
    out += ["%d %s" % (len(f), " ".join(map(str, f))) for f in faces]
    print("\n".join(out))


def angle(a, b):
    d = sum(x * y for x, y in zip(a, b)) / math.sqrt(sum(x * x for x in a) * sum(y * y for y in b))
    return math.degrees(math.acos(max(-1.0, min(1.0, d))))


def normals(ltx, normals_ply, mesh_true):
    mesh = read_ply(mesh_true)
    vrows, vnames = mesh["vertex"]
    ix, inx = vnames.index("x"), vnames.index("nx")
    verts = [r[ix:ix + 3] for r in vrows]
    vnorm = [r[inx:inx + 3] for r in vrows]
    faces = [r[0] for r in mesh["face"][0]]
    nrows, nnames = read_ply(normals_ply)["vertex"]
    jr, jm = nnames.index("nx"), nnames.index("nx0")
    lum = read_ltx(ltx)
    refined, given = [], []
    for (p, tri, _), row in zip(lum, nrows):
        a, b, c = (verts[i] for i in faces[tri])
        # Barycentrics of p in the triangle, then the interpolated true vertex normal.
        e1 = [b[i] - a[i] for i in range(3)]
        e2 = [c[i] - a[i] for i in range(3)]
        d = [p[i] - a[i] for i in range(3)]
        dot = lambda u, v: sum(x * y for x, y in zip(u, v))
        d11, d12, d22, d1, d2 = dot(e1, e1), dot(e1, e2), dot(e2, e2), dot(d, e1), dot(d, e2)
        den = d11 * d22 - d12 * d12
        b1 = (d22 * d1 - d12 * d2) / den
        b2 = (d11 * d2 - d12 * d1) / den
        na, nb, nc = (vnorm[i] for i in faces[tri])
        t = [(1 - b1 - b2) * na[i] + b1 * nb[i] + b2 * nc[i] for i in range(3)]
        refined.append(angle(row[jr:jr + 3], t))
        given.append(angle(row[jm:jm + 3], t))
    med = lambda v: sorted(v)[len(v) // 2]
    print("%.6f %.6f" % (med(refined), med(given)))


if __name__ == "__main__":
    {"assignment": assignment, "materials": materials, "rerender": rerender, "halves": halves, "translate": translate,
     "normals": normals}[sys.argv[1]](*sys.argv[2:])
