#!/usr/bin/env bash
# volwave: the L-infinity bound checked by an independent comparison (fcompare max-abs),
# bit-exact lossless coding, truncated files decoding to coarser volumes whose stated
# error is the real one, a golden .vw that must keep decoding, and bad input.
source "$(dirname "$0")/lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
MAKE="python3 $HERE/volwave_make.py"
V="$FEST_BIN/volwave"
FC="$FEST_BIN/fcompare"

for k in smooth ct nan mask; do $MAKE $k "$WORK/$k.nrrd"; done

case_ "--version and --help"
run volwave --version; expect_status 0
run volwave encode --help; expect_status 0

# The bound holds on every voxel, as fcompare (not volwave) measures it.
for vol in smooth ct; do
  for e in 0.1 1 25; do
    for w in cdf53 haar; do
      case_ "bound $e on $vol with $w"
      run volwave encode "$WORK/$vol.nrrd" --max-error "$e" --wavelet "$w" -o "$WORK/a.vw"
      expect_status 0
      run volwave decode "$WORK/a.vw" -o "$WORK/a.nrrd"
      expect_status 0
      check "fcompare max-abs <= $e" "$FC" "$WORK/$vol.nrrd" "$WORK/a.nrrd" --tol "$e"
    done
  done
done

# Fixtures of other formats and types (big-endian NIfTI, gzip NRRD, zlib MHA).
for f in be_int16.nii gzip_uint16.nrrd zlib_float.mha msb_short.mha scaled_uint8.nii; do
  case_ "bound 1 on $f"
  run volwave encode "$FEST_FIXTURES/volume/$f" --max-error 1 -o "$WORK/f.vw"
  expect_status 0
  run volwave decode "$WORK/f.vw" -o "$WORK/f.nrrd"
  check "fcompare $f" "$FC" "$FEST_FIXTURES/volume/$f" "$WORK/f.nrrd" --tol 1
  case_ "lossless on $f"
  run volwave encode "$FEST_FIXTURES/volume/$f" --lossless -o "$WORK/f.vw"
  expect_status 0
  run volwave decode "$WORK/f.vw" -o "$WORK/f.nrrd"
  check "fcompare $f exact" "$FC" "$FEST_FIXTURES/volume/$f" "$WORK/f.nrrd" --tol 0
done

# Lossless is bit-exact: the decoded NRRD's data bytes equal the input's.
for vol in smooth ct; do
  case_ "lossless $vol"
  run volwave encode "$WORK/$vol.nrrd" --lossless -o "$WORK/l.vw"
  expect_status 0
  run volwave decode "$WORK/l.vw" -o "$WORK/l.nrrd"
  expect_status 0
  bytes=$([ "$vol" = ct ] && echo 53760 || echo 107520)  # 32*30*28 int16 / float32 voxels
  check "data bytes identical" cmp <(tail -c "$bytes" "$WORK/$vol.nrrd") <(tail -c "$bytes" "$WORK/l.nrrd")
  check "fcompare exact" "$FC" "$WORK/$vol.nrrd" "$WORK/l.nrrd" --tol 0
done
case_ "lossless keeps a NaN"
run volwave encode "$WORK/nan.nrrd" --lossless -o "$WORK/n.vw"
expect_status 0
run volwave decode "$WORK/n.vw" -o "$WORK/n.nrrd"
check "NaN data bytes identical" cmp <(tail -c 107520 "$WORK/nan.nrrd") <(tail -c 107520 "$WORK/n.nrrd")

# Deterministic: any thread count gives the same bytes.
case_ "deterministic"
"$V" encode "$WORK/smooth.nrrd" --max-error 0.5 --threads 1 -o "$WORK/t1.vw"
"$V" encode "$WORK/smooth.nrrd" --max-error 0.5 --threads 3 -o "$WORK/t3.vw"
check "same bytes with 1 and 3 threads" cmp "$WORK/t1.vw" "$WORK/t3.vw"

# Truncation: a file cut inside chunk k decodes to the chunks before it, the stated
# error is what fcompare measures, and the error shrinks as more chunks arrive.
"$V" encode "$WORK/smooth.nrrd" --max-error 0.5 -o "$WORK/full.vw"
run volwave info "$WORK/full.vw"
expect_status 0
# The version info reports is the magic's last byte (fest-vw(5): byte 7).
expect_json '.version' "$(od -An -tu1 -j7 -N1 "$WORK/full.vw" | tr -d ' ')"
cp "$out" "$WORK/info.json"
nchunks=$(jq '.chunks | length' "$WORK/info.json")
prev=1e300
for k in $(seq 1 $((nchunks - 2))); do
  case_ "truncated inside chunk $k"
  through=$(jq ".chunks[$((k - 1))].file_bytes_through" "$WORK/info.json")
  size=$(jq ".chunks[$k].bytes" "$WORK/info.json")
  head -c $((through + size / 2)) "$WORK/full.vw" >"$WORK/cut.vw"
  run volwave decode "$WORK/cut.vw" -o "$WORK/cut.nrrd" --report "$WORK/cut.json"
  expect_status 0
  expect_stderr_has "^volwave: warning: truncated file: decoded $k of $nchunks chunks"
  stated=$(jq .max_error "$WORK/cut.json")
  measured=$("$FC" "$WORK/smooth.nrrd" "$WORK/cut.nrrd" --tol 1e9 --report "$WORK/fc.json" >/dev/null; jq .metrics.max_abs "$WORK/fc.json")
  check "stated error $stated = measured $measured" python3 -c "import sys; a,b=float('$stated'),float('$measured'); sys.exit(abs(a-b) > 1e-6*max(1,a))"
  rms=$(jq .rmse "$WORK/cut.json")
  check "rmse $rms does not grow with more chunks (was $prev)" python3 -c "import sys; sys.exit(not float('$rms') <= float('$prev') * 1.0001)"
  prev=$rms
  run volwave info "$WORK/cut.vw"
  expect_json '.truncated' 'true'
  expect_json '.chunks_complete' "$k"
done
case_ "--chunks decodes a coarser volume on purpose"
run volwave decode "$WORK/full.vw" --chunks 2 -o "$WORK/c2.nrrd" --report "$WORK/c2.json"
expect_status 0
check "two chunks used" test "$(jq .chunks_decoded "$WORK/c2.json")" = 2

# Region of interest: a box and a mask get their own, tighter bound.
case_ "roi box"
run volwave encode "$WORK/smooth.nrrd" --max-error 20 --roi-box 8,8,4,15,15,9 --roi-error 0.25 -o "$WORK/roi.vw" --report "$WORK/roi.json"
expect_status 0
run volwave decode "$WORK/roi.vw" -o "$WORK/roi.nrrd"
check "outside within 20" "$FC" "$WORK/smooth.nrrd" "$WORK/roi.nrrd" --tol 20
check "region bound reported" python3 -c "import json,sys; r=json.load(open('$WORK/roi.json')); sys.exit(not r['roi_max_error'] <= 0.25)"
case_ "roi mask"
run volwave encode "$WORK/smooth.nrrd" --max-error 20 --roi-mask "$WORK/mask.nrrd" --roi-error 0.25 -o "$WORK/roim.vw" --report "$WORK/roim.json"
expect_status 0
check "mask region bound reported" python3 -c "import json,sys; r=json.load(open('$WORK/roim.json')); sys.exit(not r['roi_max_error'] <= 0.25)"

# RMS targets, with CDF 9/7 and 5/3.
for w in cdf97 cdf53; do
  case_ "rmse 2 with $w"
  run volwave encode "$WORK/smooth.nrrd" --rmse 2 --wavelet "$w" -o "$WORK/r.vw"
  expect_status 0
  run volwave decode "$WORK/r.vw" -o "$WORK/r.nrrd"
  check "fcompare rmse <= 2" "$FC" "$WORK/smooth.nrrd" "$WORK/r.nrrd" --tol 1e9 -t 'rmse<=2'
done

# Golden: a .vw written by this version must keep decoding to within its bound of the
# volume it came from (file-format stability), and encoding again gives the same bytes.
case_ "golden"
golden="$FEST_FIXTURES/volwave/smooth_e0.5.vw"
run volwave decode "$golden" -o "$WORK/g.nrrd"
expect_status 0
check "golden decodes within 0.5" "$FC" "$WORK/smooth.nrrd" "$WORK/g.nrrd" --tol 0.5
check "encoding again gives the golden bytes" cmp "$golden" "$WORK/full.vw"
# Version 5: the small slabs of this 32x30x28 volume take lower rANS table precisions.
run volwave info "$golden"
expect_json '.version' 5
check "some packed slabs below 11-bit tables" jq -e '.slabs.packed.table_bits | to_entries | map(select(.key != "11")) | length > 0' "$out"
# Format versions 3 (no packed slabs) and 4 (packed slabs at full table precision,
# FNV-1a checksums) are still read: the same quantised coefficients, so the same voxels
# as the version-5 golden (the coders are lossless on coefficients).
case_ "version 3 still decodes"
run volwave decode "$FEST_FIXTURES/volwave/smooth_e0.5_v3.vw" -o "$WORK/g3.nrrd"
expect_status 0
check "version-3 golden decodes within 0.5" "$FC" "$WORK/smooth.nrrd" "$WORK/g3.nrrd" --tol 0.5
check "version 3 and 5 decode to the same voxels" cmp "$WORK/g.nrrd" "$WORK/g3.nrrd"
run volwave info "$FEST_FIXTURES/volwave/smooth_e0.5_v3.vw"
expect_json '.version' 3
expect_json '.slabs.packed.slabs' 0
case_ "version 4 still decodes"
run volwave decode "$FEST_FIXTURES/volwave/smooth_e0.5_v4.vw" -o "$WORK/g4.nrrd"
expect_status 0
check "version 4 and 5 decode to the same voxels" cmp "$WORK/g.nrrd" "$WORK/g4.nrrd"
run volwave info "$FEST_FIXTURES/volwave/smooth_e0.5_v4.vw"
expect_json '.version' 4
# A version-4 file whose chunk checksum is FNV-1a's: one byte of a chunk changed is
# still caught.
python3 -c "
b=bytearray(open('$FEST_FIXTURES/volwave/smooth_e0.5_v4.vw','rb').read()); b[-20]^=1; open('$WORK/g4bad.vw','wb').write(b)"
run volwave decode "$WORK/g4bad.vw" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
expect_stderr_has "checksum"

# --favour: packed slabs where they cost little (speed) or only where they are not
# larger (size); the bound holds and the voxels are the same either way.
for vol in smooth ct; do
  for f in speed size; do
    case_ "--favour $f on $vol"
    run volwave encode "$WORK/$vol.nrrd" --max-error 1 --favour "$f" -o "$WORK/fv_$f.vw"
    expect_status 0
    run volwave decode "$WORK/fv_$f.vw" -o "$WORK/fv_$f.nrrd"
    expect_status 0
    check "max error <= 1 (fcompare)" "$FC" "$WORK/$vol.nrrd" "$WORK/fv_$f.nrrd" --tol 1
  done
  check "$vol: speed and size decode alike" cmp "$WORK/fv_speed.nrrd" "$WORK/fv_size.nrrd"
  check "$vol: size is not larger" test "$(stat -c %s "$WORK/fv_size.vw")" -le "$(stat -c %s "$WORK/fv_speed.vw")"
done

# Edges of analytic volumes lie where the mathematics puts them, within half a voxel
# (sub-voxel points in voxel coordinates from --points; the surfaces of volwave_make.py).
for k in sphere step cylinder; do $MAKE $k "$WORK/$k.nrrd"; done
edge_check() {  # edge_check KIND PYTHON-DISTANCE-EXPRESSION MIN-POINTS
  local kind="$1" expr="$2" min="$3"
  case_ "edges of the $kind"
  run volwave edges "$WORK/$kind.nrrd" -o "$WORK/$kind.edges.nrrd" --points "$WORK/$kind.csv" --report "$WORK/$kind.ej.json"
  expect_status 0
  check "$kind edge points within 0.5 voxel, at least $min" python3 - "$WORK/$kind.csv" "$min" <<PY
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
worst = 0.0
for r in rows:
    i, j, k = float(r["i"]), float(r["j"]), float(r["k"])
    worst = max(worst, abs($expr))
print(len(rows), worst, file=sys.stderr)
sys.exit(not (len(rows) >= int(sys.argv[2]) and worst <= 0.5))
PY
  check "$kind edge volume has the edge count" test "$(jq .edge_voxels "$WORK/$kind.ej.json")" -ge "$min"
}
edge_check sphere "math.sqrt((i-16.2)**2 + (j-15.7)**2 + (k-14.4)**2) - 9.3" 700
edge_check step "i - 12.5" 840
edge_check cylinder "math.hypot(i-15.5, j-16.25) - 7.6" 1000
case_ "edges of NaN data"; run volwave edges "$WORK/nan.nrrd" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
case_ "edges min-scales above scales"; run volwave edges "$WORK/step.nrrd" --scales 2 --min-scales 3 -o "$WORK/x.nrrd"; expect_clean_failure 2 volwave

# VTI (two point arrays: one must be chosen) and a fluidsim frame stream (frames and
# fields must be chosen; a vector component by name.x).
python3 - "$WORK/two.vti" <<'PY'
import sys
n = 6
pts = [(i, j, k) for k in range(n) for j in range(n) for i in range(n)]
a = " ".join(f"{x * 10 + y - z}" for x, y, z in pts)
b = " ".join(f"{0.5 * x} {y} {z}" for x, y, z in pts)
open(sys.argv[1], "w").write(f"""<?xml version="1.0"?>
<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
<ImageData WholeExtent="0 5 0 5 0 5" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="0 5 0 5 0 5"><PointData>
<DataArray type="Int16" Name="density" format="ascii">{a}</DataArray>
<DataArray type="Float32" Name="velocity" NumberOfComponents="3" format="ascii">{b}</DataArray>
</PointData></Piece></ImageData></VTKFile>
""")
PY
case_ "vti with two arrays needs --field"
run volwave encode "$WORK/two.vti" --max-error 1 -o "$WORK/v.vw"
expect_clean_failure 3 volwave
expect_stderr_has "name one with --field"
case_ "vti field and component"
run volwave encode "$WORK/two.vti" --field density --lossless -o "$WORK/v.vw"
expect_status 0
run volwave info "$WORK/v.vw"
expect_json '.value_type' '"int16"'
run volwave encode "$WORK/two.vti" --field velocity.x --max-error 0.01 -o "$WORK/vx.vw"
expect_status 0
if [ -x "$FEST_BIN/fluidsim" ]; then
  printf '{"dims": [12, 10, 9], "frame_dt": 0.05, "frames": 3, "scalars": [{"name": "density", "alpha": 0.1, "sources": [{"shape": "box", "min": [3, 3, 1], "max": [5, 5, 2], "rate": 10, "velocity": [0, 0, 0.4]}]}], "forces": [{"type": "buoyancy", "scalar": "density", "beta": 0.3}]}\n' >"$WORK/s.json"
  "$FEST_BIN/fluidsim" run "$WORK/s.json" -o - >"$WORK/s.stream" 2>/dev/null
  case_ "frame stream needs --frame"
  run volwave encode "$WORK/s.stream" --max-error 0.001 -o "$WORK/s.vw"
  expect_clean_failure 3 volwave
  expect_stderr_has "choose one with --frame"
  case_ "frame stream field and component"
  run volwave encode "$WORK/s.stream" --frame 2 --field density --max-error 0.001 -o "$WORK/s.vw" --report "$WORK/s.json2"
  expect_status 0
  check "bound on the plume frame" python3 -c "import json,sys; sys.exit(not json.load(open('$WORK/s.json2'))['max_error'] <= 0.001)"
  run volwave encode "$WORK/s.stream" --frame 2 --field velocity.z --lossless -o "$WORK/sv.vw"
  expect_status 0
  run volwave encode "$WORK/s.stream" --frame 2 --field velocity --lossless -o "$WORK/sv.vw"
  expect_clean_failure 3 volwave
  expect_stderr_has "components"
fi

# An lbmsim frame stream (D3Q19 flow past an off-centre sphere in a 32x20x20 duct, 300
# steps, a fraction of a second): its frames list velocity:3, pressure:1, speed:1, so the
# scalar fields sit at channels 3 and 4. The reference is a second run of the same case
# written by lbmsim's own NRRD writer (one file per field; lbmsim is deterministic), so
# the comparison does not go through volwave's frame-stream reader.
if [ -x "$FEST_BIN/lbmsim" ]; then
  cat >"$WORK/duct.json" <<'JSON'
{ "lattice": "d3q19", "size": [32, 20, 20], "collision": { "model": "trt", "nu": 0.02 },
  "faces": { "x-": { "velocity": { "profile": "parabolic", "u": 0.05 } }, "x+": { "pressure": { "rho": 1.0 } },
             "y-": "wall", "y+": "wall", "z-": "wall", "z+": "wall" },
  "geometry": [ { "sphere": { "center": [10, 9, 11], "radius": 4 } } ],
  "init": { "u": [0.02, 0, 0] }, "steps": 300 }
JSON
  "$FEST_BIN/lbmsim" -q run "$WORK/duct.json" --fields speed,velocity,pressure --precision float --threads 1 -o - >"$WORK/duct.stream"
  "$FEST_BIN/lbmsim" -q run "$WORK/duct.json" --fields speed,pressure --precision float --threads 1 -o "$WORK/duct.nrrd"
  case_ "lbmsim stream needs --field"
  run volwave encode "$WORK/duct.stream" --max-error 1e-4 -o "$WORK/d.vw"
  expect_clean_failure 3 volwave
  expect_stderr_has "name one with --field"
  # Speed peaks near 0.05 (the inlet's U_max): 1e-4 is 1/500 of it, 1e-6 ~270 float32 ulps.
  for f in speed:1e-4 speed:1e-6 pressure:1e-6; do
    field=${f%:*} e=${f#*:}
    case_ "lbmsim $field, bound $e"
    run volwave encode "$WORK/duct.stream" --field "$field" --max-error "$e" -o "$WORK/d.vw"
    expect_status 0
    run volwave decode "$WORK/d.vw" -o "$WORK/d.nrrd"
    expect_status 0
    check "fcompare max-abs <= $e against lbmsim's NRRD" "$FC" "$WORK/duct_$field.nrrd" "$WORK/d.nrrd" --tol "$e"
    case_ "lbmsim $field lossless"
    run volwave encode "$WORK/duct.stream" --field "$field" --lossless -o "$WORK/dl.vw"
    expect_status 0
    check "lossy file smaller than the lossless one" test "$(stat -c %s "$WORK/d.vw")" -lt "$(stat -c %s "$WORK/dl.vw")"
    run volwave decode "$WORK/dl.vw" -o "$WORK/dl.nrrd"
    expect_status 0
    check "data bytes identical to lbmsim's NRRD" cmp <(tail -c 51200 "$WORK/duct_$field.nrrd") <(tail -c 51200 "$WORK/dl.nrrd")  # 32*20*20 float32
    check "fcompare exact" "$FC" "$WORK/duct_$field.nrrd" "$WORK/dl.nrrd" --tol 0
  done
fi

# Standard input and output.
case_ "pipes"
"$V" encode --max-error 1 <"$WORK/ct.nrrd" | "$V" decode >"$WORK/p.nrrd"
check "pipe round trip" "$FC" "$WORK/ct.nrrd" "$WORK/p.nrrd" --tol 1

# Bad input and usage.
case_ "bound zero"; run volwave encode "$WORK/smooth.nrrd" --max-error 0 -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "bound negative"; run volwave encode "$WORK/smooth.nrrd" --max-error -1 -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "rmse zero"; run volwave encode "$WORK/smooth.nrrd" --rmse 0 -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "two modes"; run volwave encode "$WORK/smooth.nrrd" --max-error 1 --lossless -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "no mode"; run volwave encode "$WORK/smooth.nrrd" -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "cdf97 with a bound"; run volwave encode "$WORK/smooth.nrrd" --max-error 1 --wavelet cdf97 -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "NaN with a bound"
run volwave encode "$WORK/nan.nrrd" --max-error 1 -o "$WORK/x.vw"
expect_clean_failure 3 volwave
expect_stderr_has "1 voxels are NaN"
check "nothing written" test ! -e "$WORK/x.vw"
case_ "roi box outside"; run volwave encode "$WORK/smooth.nrrd" --max-error 5 --roi-box 0,0,0,40,10,10 --roi-error 1 -o "$WORK/x.vw"; expect_clean_failure 3 volwave
expect_stderr_has "outside the volume"
case_ "roi error above bound"; run volwave encode "$WORK/smooth.nrrd" --max-error 1 --roi-box 0,0,0,4,4,4 --roi-error 2 -o "$WORK/x.vw"; expect_clean_failure 2 volwave
case_ "roi mask of other size"; run volwave encode "$WORK/smooth.nrrd" --max-error 1 --roi-mask "$FEST_FIXTURES/volume/be_int16.nii" --roi-error 0.5 -o "$WORK/x.vw"; expect_clean_failure 3 volwave
case_ "truncated header"
head -c 60 "$WORK/full.vw" >"$WORK/h.vw"
run volwave decode "$WORK/h.vw" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
expect_stderr_has "truncated"
check "nothing written" test ! -e "$WORK/x.nrrd"
case_ "truncated inside the coarsest level"
through=$(jq '.chunks[0].file_bytes_through' "$WORK/info.json")
head -c $((through - 1)) "$WORK/full.vw" >"$WORK/h.vw"
run volwave decode "$WORK/h.vw" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
case_ "damaged chunk"
python3 -c "
b=bytearray(open('$WORK/full.vw','rb').read()); b[-200]^=0x55; open('$WORK/d.vw','wb').write(b)"
run volwave decode "$WORK/d.vw" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
expect_stderr_has "checksum"
case_ "not a .vw"; run volwave decode "$WORK/smooth.nrrd" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
case_ "empty .vw"; : >"$WORK/e.vw"; run volwave decode "$WORK/e.vw" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
case_ "info on garbage"; run volwave info "$WORK/smooth.nrrd"; expect_clean_failure 3 volwave
case_ "not a volume"; run volwave encode "$WORK/info.json" --max-error 1 -o "$WORK/x.vw"; expect_clean_failure 3 volwave
case_ "bad --favour"; run volwave encode "$WORK/smooth.nrrd" --max-error 1 --favour fast -o "$WORK/x.vw"; expect_clean_failure 2 volwave
expect_stderr_has "favour"
case_ "version 6 .vw"
python3 -c "
b=bytearray(open('$WORK/full.vw','rb').read()); b[7]=6; open('$WORK/v6.vw','wb').write(b)"
run volwave decode "$WORK/v6.vw" -o "$WORK/x.nrrd"; expect_clean_failure 3 volwave
expect_stderr_has "version 6"
case_ "unknown flag"; run volwave encode --no-such-flag x; expect_clean_failure 2 volwave
case_ "missing file"; run volwave encode "$WORK/none.nrrd" --max-error 1 -o "$WORK/x.vw"; expect_clean_failure 4 volwave

finish
