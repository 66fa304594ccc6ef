#!/usr/bin/env bash
# lemtrace probes: a ribbon in a rigid rotation keeps its width and twists at the
# rotation rate (analytic: the helix field v = (-y, x, 0.05) rotates at rate 1 about z);
# one arrow glyph per seed, pointing along the analytic velocity; tubes; bad input.
source "$(dirname "$0")/lib.sh"

run lemtrace gen helix --n 20 -o "$WORK/helix.vtu"
expect_status 0

case_ "ribbon around the rotation axis"
run lemtrace probes "$WORK/helix.vtu" --seed-point 0,0,-0.8 --ribbon 0.1 --max-time 25 --samples-per-cell 16 \
  -o "$WORK/rib.ply" --report "$WORK/rib.json"
expect_status 0
check "one ribbon" test "$(jq .ribbons "$WORK/rib.json")" = 1
check "width 0.1 and twist = time (rate 1)" python3 - "$WORK/rib.ply" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
head, body = data.split(b"end_header\n", 1)
lines = head.decode().splitlines()
n = int([l for l in lines if l.startswith("element vertex")][0].split()[2])
props = [l.split()[2] for l in lines if l.startswith("property float")]
rec = struct.Struct("<" + "f" * len(props))
verts = [dict(zip(props, rec.unpack_from(body, i * rec.size))) for i in range(n)]
assert n > 40, n
worst_w = worst_t = 0.0
for i in range(0, n, 2):
    a, b = verts[i], verts[i + 1]
    w = ((a["x"] - b["x"]) ** 2 + (a["y"] - b["y"]) ** 2 + (a["z"] - b["z"]) ** 2) ** 0.5
    worst_w = max(worst_w, abs(w - 0.1))
    worst_t = max(worst_t, abs(a["twist"] - a["time"]) / max(1.0, a["time"]))
    assert abs(a["half_streamwise_vorticity"] - 1.0) < 1e-4, a
print("width error", worst_w, "twist error", worst_t, "last time", verts[-1]["time"], file=sys.stderr)
sys.exit(not (worst_w < 2e-4 and worst_t < 2e-3 and verts[-1]["time"] > 24))
PY

case_ "glyphs: one arrow per seed, along the velocity"
run lemtrace probes "$WORK/helix.vtu" --seed-line -0.5,-0.4,0.1:0.5,0.6,-0.2:7 --glyphs --glyph-scale 0.5 --sides 8 \
  -o "$WORK/g.ply" --report "$WORK/g.json"
expect_status 0
check "seven glyphs" test "$(jq .glyphs "$WORK/g.json")" = 7
check "arrows point along v = (-y, x, 0.05), length 0.5 |v|" python3 - "$WORK/g.ply" <<'PY'
import math, struct, sys
data = open(sys.argv[1], "rb").read()
head, body = data.split(b"end_header\n", 1)
lines = head.decode().splitlines()
n = int([l for l in lines if l.startswith("element vertex")][0].split()[2])
props = [l.split()[2] for l in lines if l.startswith("property float")]
rec = struct.Struct("<" + "f" * len(props))
pts = [rec.unpack_from(body, i * rec.size)[:3] for i in range(n)]
S = 8
per = 3 * S + 2
assert n == 7 * per, n
for g in range(7):
    t = g / 6
    seed = (-0.5 + t, -0.4 + t, 0.1 - 0.3 * t)
    tip, base = pts[g * per + 3 * S], pts[g * per + 3 * S + 1]
    v = (-seed[1], seed[0], 0.05)
    d = [tip[k] - base[k] for k in range(3)]
    assert max(abs(base[k] - seed[k]) for k in range(3)) < 1e-5, (base, seed)
    nv = math.sqrt(sum(c * c for c in v))
    assert max(abs(d[k] - 0.5 * v[k]) for k in range(3)) < 1e-5 * max(1, nv), (d, v)
PY

case_ "tubes, VTP"
run lemtrace probes "$WORK/helix.vtu" --seed-point 0.3,0,-0.5 --tube 0.02 --max-time 3 -o "$WORK/t.vtp" --report "$WORK/t.json"
expect_status 0
check "one tube" test "$(jq .tubes "$WORK/t.json")" = 1
check "VTP opens in fconv" "$FEST_BIN/fconv" --info "$WORK/t.vtp"

case_ "glyphs coloured by a point array (linear pressure: interpolation is exact)"
python3 - "$WORK/p.vti" <<'PY'
import sys
n = 9
pts = [(-1 + 2 * i / (n - 1), -1 + 2 * j / (n - 1), -1 + 2 * k / (n - 1)) for k in range(n) for j in range(n) for i in range(n)]
vel = " ".join(f"{-y} {x} 0.05" for x, y, z in pts)
pre = " ".join(f"{x + 2 * y + 3 * z}" for x, y, z in pts)
open(sys.argv[1], "w").write(f"""<?xml version="1.0"?>
<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
<ImageData WholeExtent="0 {n-1} 0 {n-1} 0 {n-1}" Origin="-1 -1 -1" Spacing="{2/(n-1)} {2/(n-1)} {2/(n-1)}">
<Piece Extent="0 {n-1} 0 {n-1} 0 {n-1}"><PointData Vectors="velocity">
<DataArray type="Float64" Name="velocity" NumberOfComponents="3" format="ascii">{vel}</DataArray>
<DataArray type="Float64" Name="pressure" format="ascii">{pre}</DataArray>
</PointData></Piece></ImageData></VTKFile>
""")
PY
run lemtrace probes "$WORK/p.vti" --seed-point 0.31,-0.22,0.45 --seed-point -0.6,0.1,-0.3 --glyphs --color pressure --sides 6 -o "$WORK/pg.ply"
expect_status 0
check "glyph colours = pressure at the seeds" python3 - "$WORK/pg.ply" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
head, body = data.split(b"end_header\n", 1)
lines = head.decode().splitlines()
n = int([l for l in lines if l.startswith("element vertex")][0].split()[2])
props = [l.split()[2] for l in lines if l.startswith("property float")]
rec = struct.Struct("<" + "f" * len(props))
per = 3 * 6 + 2
assert n == 2 * per and "pressure" in props, (n, props)
k = props.index("pressure")
for g, (x, y, z) in enumerate([(0.31, -0.22, 0.45), (-0.6, 0.1, -0.3)]):
    got = rec.unpack_from(body, g * per * rec.size)[k]
    assert abs(got - (x + 2 * y + 3 * z)) < 1e-5, (got, x + 2 * y + 3 * z)
PY
case_ "colour by a vector array"; run lemtrace probes "$WORK/p.vti" --seed-point 0,0,0 --glyphs --color velocity -o "$WORK/x.ply"
expect_clean_failure 3 lemtrace

case_ "nothing to draw"; run lemtrace probes "$WORK/helix.vtu" --seed-point 0,0,0 -o "$WORK/x.ply"; expect_clean_failure 2 lemtrace
case_ "unknown output"; run lemtrace probes "$WORK/helix.vtu" --seed-point 0,0,0 --glyphs -o "$WORK/x.obj"; expect_clean_failure 2 lemtrace
case_ "colour by a missing array"; run lemtrace probes "$WORK/helix.vtu" --seed-point 0,0,0 --glyphs --color pressure -o "$WORK/x.ply"
expect_clean_failure 3 lemtrace
expect_stderr_has "no point array 'pressure'"
check "nothing written" test ! -e "$WORK/x.ply"

finish
