#!/usr/bin/env python3
"""Pinhole projection of an OBJ's vertices with the camera of a terrainlod extract report
(docs/terrainlod.md section 5), written independently of the tool.

usage: project.py REPORT.json MESH.obj
prints "inside_all fill_x fill_y": 1 if every vertex lies in front of the near plane and
inside the image, then the fraction of the image width and height the vertices span."""
import json
import math
import sys


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return [x / math.sqrt(dot(a, a)) for x in a]


def main():
    c = json.load(open(sys.argv[1]))["camera"]
    f = norm(sub(c["target"], c["eye"]))
    r = norm(cross(f, c["up"]))
    u = cross(r, f)
    W, H = c["width"], c["height"]
    fpx = (H / 2) / math.tan(math.radians(c["fovy_deg"]) / 2)
    slack = 1e-9 * max(W, H)  # rounding at the image's edge
    xs, ys, ok = [], [], True
    for line in open(sys.argv[2]):
        if line.startswith("v "):
            d = sub([float(v) for v in line.split()[1:4]], c["eye"])
            z = dot(d, f)
            if z <= 0:
                ok = False
                continue
            x, y = W / 2 + fpx * dot(d, r) / z, H / 2 - fpx * dot(d, u) / z
            ok = ok and z > c.get("near", 0) and -slack <= x <= W + slack and -slack <= y <= H + slack
            xs.append(x)
            ys.append(y)
    if not xs:
        print(0, 0, 0)
        return
    print(int(ok), (max(xs) - min(xs)) / W, (max(ys) - min(ys)) / H)


main()
