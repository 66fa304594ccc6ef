#!/usr/bin/env python3
"""Checks the texture coordinates of an OBJ written by `terrainlod extract` (one material
per texture tile, "usemtl tile-L-X-Y") against the mathematics of docs/terrainlod.md §3-4:
a vertex at grid point (gx, gy) drawn with the texture of tile (L, X, Y), whose square is
S = cells[L] grid cells, has (u, v) = ((gx - X S) / S, (gy - Y S) / S).

Usage: terrainlod_uv.py VIEW.obj STATS.json   (STATS = `terrainlod stats PYRAMID`)
Prints JSON: faces, corners (corner vertices of a material's tile), mismatches,
corner_mismatches (corner (u, v) not exactly 0 or 1), outside (u or v outside [0, 1]),
material_levels."""
import json
import sys

obj_path, stats_path = sys.argv[1], sys.argv[2]
manifest = json.load(open(stats_path))["manifest"]
cells = [lv["cells"] for lv in manifest["level"]]
ox, oy = manifest["origin"]
dx, dy = manifest["cell_size"]
V, VT = [], []
material = None
res = {"faces": 0, "corners": 0, "mismatches": 0, "corner_mismatches": 0, "outside": 0}
levels = set()
for line in open(obj_path):
    p = line.split()
    if not p:
        continue
    if p[0] == "v":
        V.append((float(p[1]), float(p[2])))
    elif p[0] == "vt":
        VT.append((float(p[1]), float(p[2])))
    elif p[0] == "usemtl":
        material = tuple(int(k) for k in p[1][len("tile-"):].split("-"))
        levels.add(material[0])
    elif p[0] == "f":
        res["faces"] += 1
        level, x, y = material
        S = cells[level]
        for corner in p[1:]:
            i, t = (int(k) - 1 for k in corner.split("/")[:2])
            gx, gy = round((V[i][0] - ox) / dx), round((V[i][1] - oy) / dy)
            u, v = (gx - x * S) / S, (gy - y * S) / S
            tu, tv = VT[t]
            if abs(u - tu) > 1e-6 or abs(v - tv) > 1e-6:
                res["mismatches"] += 1
            if not (0 <= tu <= 1 and 0 <= tv <= 1):
                res["outside"] += 1
            if gx in (x * S, (x + 1) * S) and gy in (y * S, (y + 1) * S):
                res["corners"] += 1
                if tu not in (0.0, 1.0) or tv not in (0.0, 1.0):
                    res["corner_mismatches"] += 1
res["material_levels"] = sorted(levels)
print(json.dumps(res))
