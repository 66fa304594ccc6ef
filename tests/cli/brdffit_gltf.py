#!/usr/bin/env python3
"""glTF checks for tests/cli/brdffit_export.sh, from the glTF 2.0 and PNG specifications
and synth's truth.json -- not from brdffit's own code.

  check FILE.gltf|FILE.glb
      structural validity: buffers, bufferViews and accessors consistent (offsets, lengths,
      counts, POSITION min/max), TEXCOORD_0 in [0, 1], unit NORMAL/TANGENT with w = +-1,
      textures -> images/samplers that exist, every image a PNG of the size its IHDR says
      and readable; no texel centre inside two triangles' UV footprints. Prints JSON:
      triangles, images [{width, height}], uv_min, uv_max, texture names.
  truth FILE.gltf truth.json
      for every triangle: the base colour texel under its UV centroid is sRGB(rho_d) of its
      material and the roughness texel (G) sqrt(2/(N+2)) of the material's dominant lobe,
      within 1/255; prints the largest deviations (in 8-bit steps) as JSON.
  constant FILE.gltf R G B
      every base colour texel under any triangle's UV footprint (texel centres inside a
      triangle) equals (R, G, B) exactly; prints the count as JSON.
  exr_size FILE.exr
      width and height from the OpenEXR header's dataWindow, as JSON (for factor).
"""
import base64
import json
import math
import os
import struct
import sys
import zlib

COMPONENT = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
TYPE = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def fail(msg):
    print("brdffit_gltf.py: " + msg, file=sys.stderr)
    sys.exit(1)


def decode_png(data):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA non-interlaced PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("not a PNG")
    pos, idat, ihdr = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack_from(">I4s", data, pos)
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    w, h, depth, ctype, _, _, interlace = ihdr
    if depth != 8 or ctype not in (2, 6) or interlace:
        fail("unexpected PNG layout depth %d colour type %d" % (depth, ctype))
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev, p = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[p]
        line = bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def load(path):
    """(json, buffer bytes, list of PNG bytes per image)."""
    data = open(path, "rb").read()
    folder = os.path.dirname(path)
    binary = None
    if data[:4] == b"glTF":
        magic, version, length = struct.unpack_from("<III", data, 0)
        if version != 2 or length != len(data):
            fail("glb header: version %d, length %d of %d bytes" % (version, length, len(data)))
        jlen, jtype = struct.unpack_from("<II", data, 12)
        if jtype != 0x4E4F534A or jlen % 4:
            fail("glb JSON chunk")
        doc = json.loads(data[20:20 + jlen])
        blen, btype = struct.unpack_from("<II", data, 20 + jlen)
        if btype != 0x004E4942:
            fail("glb BIN chunk")
        binary = data[28 + jlen:28 + jlen + blen]
        if 28 + jlen + blen != len(data):
            fail("glb chunks do not fill the file")
    else:
        doc = json.loads(data)
    if doc.get("asset", {}).get("version") != "2.0":
        fail("asset.version is not 2.0")
    buffers = []
    for b in doc["buffers"]:
        if "uri" in b:
            uri = b["uri"]
            prefix = "data:application/octet-stream;base64,"
            raw = base64.b64decode(uri[len(prefix):]) if uri.startswith(prefix) else open(os.path.join(folder, uri), "rb").read()
        else:
            raw = binary
        if raw is None or len(raw) < b["byteLength"]:
            fail("buffer shorter than its byteLength")
        buffers.append(raw)
    for i, v in enumerate(doc["bufferViews"]):
        if v["byteOffset"] + v["byteLength"] > doc["buffers"][v["buffer"]]["byteLength"]:
            fail("bufferView %d runs past its buffer" % i)
    images = []
    for im in doc.get("images", []):
        if "uri" in im:
            uri = im["uri"]
            if uri.startswith("data:image/png;base64,"):
                images.append(base64.b64decode(uri.split(",", 1)[1]))
            else:
                if os.path.isabs(uri) or "/" in uri:
                    fail("image uri %s is not a file beside the glTF" % uri)
                images.append(open(os.path.join(folder, uri), "rb").read())
        else:
            v = doc["bufferViews"][im["bufferView"]]
            if im.get("mimeType") != "image/png":
                fail("image in a bufferView without mimeType image/png")
            images.append(buffers[v["buffer"]][v["byteOffset"]:v["byteOffset"] + v["byteLength"]])
    return doc, buffers, images


def accessor(doc, buffers, index):
    a = doc["accessors"][index]
    v = doc["bufferViews"][a["bufferView"]]
    size = COMPONENT[a["componentType"]] * TYPE[a["type"]]
    start = v["byteOffset"] + a.get("byteOffset", 0)
    if a.get("byteOffset", 0) + a["count"] * size > v["byteLength"]:
        fail("accessor %d runs past its bufferView" % index)
    if start % COMPONENT[a["componentType"]]:
        fail("accessor %d is misaligned" % index)
    fmt = "<" + {5126: "f", 5125: "I", 5123: "H", 5121: "B"}[a["componentType"]] * TYPE[a["type"]]
    raw = buffers[v["buffer"]]
    return [struct.unpack_from(fmt, raw, start + i * size) for i in range(a["count"])]


def geometry(doc, buffers):
    if len(doc["meshes"]) != 1 or len(doc["meshes"][0]["primitives"]) != 1:
        fail("expected one mesh with one primitive")
    prim = doc["meshes"][0]["primitives"][0]
    att = prim["attributes"]
    pos = accessor(doc, buffers, att["POSITION"])
    acc = doc["accessors"][att["POSITION"]]
    for k in range(3):
        lo, hi = min(p[k] for p in pos), max(p[k] for p in pos)
        if abs(lo - acc["min"][k]) > 1e-6 * (1 + abs(lo)) or abs(hi - acc["max"][k]) > 1e-6 * (1 + abs(hi)):
            fail("POSITION min/max do not match the data")
    count = len(pos)
    if "indices" in prim:
        fail("expected non-indexed triangles")
    if count % 3:
        fail("vertex count %d is not a multiple of 3" % count)
    nrm = accessor(doc, buffers, att["NORMAL"])
    uv = accessor(doc, buffers, att["TEXCOORD_0"])
    for n in nrm:
        if abs(math.sqrt(sum(c * c for c in n)) - 1) > 1e-4:
            fail("a NORMAL is not unit length")
    if "TANGENT" in att:
        for t in accessor(doc, buffers, att["TANGENT"]):
            if abs(math.sqrt(sum(c * c for c in t[:3])) - 1) > 1e-4 or t[3] not in (1.0, -1.0):
                fail("a TANGENT is not unit length with w = +-1")
    if len(nrm) != count or len(uv) != count:
        fail("attribute counts differ")
    return pos, uv


def textures(doc, images):
    dims = [decode_png(png) for png in images]
    for t in doc["textures"]:
        if t["source"] >= len(images) or t["sampler"] >= len(doc["samplers"]):
            fail("texture names a missing image or sampler")
    mat = doc["materials"][doc["meshes"][0]["primitives"][0]["material"]]
    pbr = mat["pbrMetallicRoughness"]
    names = {"baseColor": dims[doc["textures"][pbr["baseColorTexture"]["index"]]["source"]],
             "metallicRoughness": dims[doc["textures"][pbr["metallicRoughnessTexture"]["index"]]["source"]]}
    if "normalTexture" in mat:
        names["normal"] = dims[doc["textures"][mat["normalTexture"]["index"]]["source"]]
    return names


def centres_inside(tri, w, h):
    """Texel centres strictly inside a triangle given in UV."""
    pts = [(u * w, v * h) for u, v in tri]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    out = []
    for y in range(max(0, int(min(ys)) - 1), min(h, int(max(ys)) + 2)):
        for x in range(max(0, int(min(xs)) - 1), min(w, int(max(xs)) + 2)):
            c = (x + 0.5, y + 0.5)
            s = [(pts[(k + 1) % 3][0] - pts[k][0]) * (c[1] - pts[k][1]) -
                 (pts[(k + 1) % 3][1] - pts[k][1]) * (c[0] - pts[k][0]) for k in range(3)]
            if all(v > 1e-9 for v in s) or all(v < -1e-9 for v in s):
                out.append((x, y))
    return out


def srgb(x):
    x = min(max(x, 0.0), 1.0)
    return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055


def exr_size(path):
    data = open(path, "rb").read()
    if data[:4] != b"\x76\x2f\x31\x01":
        fail("not an OpenEXR file")
    pos = 8
    while data[pos] != 0:
        name_end = data.index(b"\0", pos)
        type_end = data.index(b"\0", name_end + 1)
        size = struct.unpack_from("<i", data, type_end + 1)[0]
        if data[pos:name_end] == b"dataWindow":
            x0, y0, x1, y1 = struct.unpack_from("<4i", data, type_end + 5)
            return x1 - x0 + 1, y1 - y0 + 1
        pos = type_end + 5 + size
    fail("no dataWindow")


def main():
    mode, path = sys.argv[1], sys.argv[2]
    if mode == "exr_size":
        w, h = exr_size(path)
        print(json.dumps({"width": w, "height": h}))
        return
    doc, buffers, images = load(path)
    pos, uv = geometry(doc, buffers)
    tex = textures(doc, images)
    w, h, base = tex["baseColor"]
    tris = [uv[i:i + 3] for i in range(0, len(uv), 3)]
    if mode == "check":
        for name, (tw, th, _) in tex.items():
            if (tw, th) != (w, h):
                fail("%s is %dx%d, base colour %dx%d" % (name, tw, th, w, h))
        owner = {}
        for t, tri in enumerate(tris):
            for c in centres_inside(tri, w, h):
                if c in owner:
                    fail("texel %s lies inside triangles %d and %d" % (c, owner[c], t))
                owner[c] = t
        print(json.dumps({"triangles": len(tris), "width": w, "height": h,
                          "images": [{"width": d[0], "height": d[1]} for d in tex.values()],
                          "textures": sorted(tex), "covered_texels": len(owner),
                          "uv_min": min(min(p) for p in uv), "uv_max": max(max(p) for p in uv)}))
    elif mode == "truth":
        truth = json.load(open(sys.argv[3]))
        _, _, mr = tex["metallicRoughness"]
        worst_base = worst_rough = 0
        for t, tri in enumerate(tris):
            m = truth["materials"][truth["triangle_material"][t]]
            cu = sum(p[0] for p in tri) / 3 * w
            cv = sum(p[1] for p in tri) / 3 * h
            x, y = min(int(cu), w - 1), min(int(cv), h - 1)
            for c in range(3):
                worst_base = max(worst_base, abs(base[y][x][c] - round(255 * srgb(m["rho_d"][c]))))
            peaks = [max(abs(sum(l_cxy) / 3), abs(sum(l_cz) / 3)) ** (sum(l_n) / 3)
                     for l_cxy, l_cz, l_n in zip(m["Cxy"], m["Cz"], m["N"])]
            n = sum(m["N"][peaks.index(max(peaks))]) / 3 if peaks else None
            rough = math.sqrt(2 / (n + 2)) if n is not None else 1.0
            worst_rough = max(worst_rough, abs(mr[y][x][1] - round(255 * rough)))
            if mr[y][x][2] != 0:
                fail("metallic is not 0")
        print(json.dumps({"base_steps": worst_base, "roughness_steps": worst_rough}))
    elif mode == "constant":
        want = tuple(int(v) for v in sys.argv[3:6])
        n = 0
        for tri in tris:
            for x, y in centres_inside(tri, w, h):
                if base[y][x] != want:
                    fail("texel (%d, %d) is %s, expected %s" % (x, y, base[y][x], want))
                n += 1
        print(json.dumps({"texels": n}))
    else:
        fail("unknown mode " + mode)


if __name__ == "__main__":
    main()
