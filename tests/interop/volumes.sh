#!/usr/bin/env bash
# Volumes fest writes (NIfTI .nii and .nii.gz, NRRD, MetaImage; 3-D and 4-D), read by
# nibabel, by teem (the NRRD format's reference library) and by VTK's MetaImage reader.
# Every source is a NIfTI file read by nibabel, so the reference geometry and values
# never pass through fest's readers.
. "$(dirname "$0")/../cli/lib.sh"
. "$(dirname "$0")/interop_lib.sh"
here=$(cd "$(dirname "$0")" && pwd)

have_nib=0; py_has nibabel python3-nibabel && have_nib=1
have_vtk=0; py_has vtk python3-vtk9 && have_vtk=1
have_teem=0; reader teem-unu teem-apps && have_teem=1
[ $have_nib = 1 ] || finish_interop   # the reference itself needs nibabel

# Sources made by nibabel itself: an oblique int16 volume with a scale factor, and a
# float32 one.
"$PY" - "$WORK" <<'PY'
import sys
import nibabel as nib, numpy as np
rng = np.random.default_rng(7)
c, s = np.cos(0.3), np.sin(0.3)
affine = np.array([[0.9 * c, -1.1 * s, 0, -12.5], [0.9 * s, 1.1 * c, 0, 30.0], [0, 0, 2.0, -7.25], [0, 0, 0, 1]])
img = nib.Nifti1Image(rng.integers(-300, 900, (7, 6, 5)).astype(np.int16), affine)
img.header.set_slope_inter(0.5, 10.0)
img.header.set_qform(affine, 1); img.header.set_sform(affine, 2)
nib.save(img, sys.argv[1] + "/oblique_int16.nii")
f = nib.Nifti1Image(rng.normal(0, 1, (9, 5, 3)).astype(np.float32), np.diag([0.5, 0.5, 1.5, 1.0]))
nib.save(f, sys.argv[1] + "/float32.nii.gz")
PY
sources=("$FEST_FIXTURES/volume/be_int16.nii" "$WORK/oblique_int16.nii" "$WORK/float32.nii.gz")
head="$FEST_TESTDATA/mri/t1_head.nii.gz"
[ -f "$head" ] && sources+=("$head") || echo "interop: t1_head.nii.gz not fetched: the real-volume case is skipped"
# nibabel's own 4-D test series (2 frames, oblique int16): written back as 4-D NIfTI and NRRD.
series="$FEST_TESTDATA/volumes/nibabel/example4d.nii.gz"
[ -f "$series" ] && sources+=("$series") || echo "interop: nibabel's example4d.nii.gz not fetched: the 4-D case is skipped"

# facts FILE: shape, affine and value range as nibabel sees them (JSON).
facts() {
  "$PY" - "$1" <<'PY'
import json, sys
import nibabel as nib, numpy as np
img = nib.load(sys.argv[1])
d = np.asarray(img.dataobj, dtype=np.float64)
print(json.dumps({"shape": [int(n) for n in img.shape], "affine": img.affine.tolist(),
                  "min": float(np.nanmin(d)), "max": float(np.nanmax(d)), "sum": float(np.nansum(d))}))
PY
}

for src in "${sources[@]}"; do
  name=$(basename "$src"); name=${name%%.*}
  facts "$src" >"$WORK/$name.ref.json"
  # NIfTI-1 (.nii, .nii.gz), NIfTI-2, the NIfTI-1 header/image pair and FreeSurfer's MGZ:
  # nibabel reads every one. (MGH stores its geometry as float32: 1e-4 mm still holds.)
  for ext in nii nii.gz n2.nii hdr mgz; do
    f="$WORK/$name.$ext"
    case $ext in
      n2.nii) "$FEST_BIN/fconv" --to nifti2 "$src" -o "$f" ;;
      *) "$FEST_BIN/fconv" "$src" -o "$f" ;;
    esac
    case_ "nibabel reads fconv's $name.$ext: shape, affine and values of the source"
    [ $ext = n2.nii ] && check "a NIfTI-2 header (sizeof_hdr 540)" "$PY" -c "import nibabel as nib, sys; sys.exit(0 if isinstance(nib.load('$f'), nib.Nifti2Image) else 1)"
    facts "$f" >"$out" 2>"$err"; rc=$?
    expect_status 0
    check "same shape, affine (1e-4 mm), values (1e-6 relative)" "$PY" - "$WORK/$name.ref.json" "$out" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ok = a["shape"] == b["shape"]
ok &= max(abs(x - y) for ra, rb in zip(a["affine"], b["affine"]) for x, y in zip(ra, rb)) <= 1e-4
for k in ("min", "max", "sum"):
    ok &= abs(a[k] - b[k]) <= 1e-6 * max(1.0, abs(a[k]))
sys.exit(0 if ok else 1)
PY
  done
  if [ $have_teem = 1 ]; then
    f="$WORK/$name.nrrd"
    "$FEST_BIN/fconv" "$src" -o "$f"
    case_ "teem reads fconv's $name.nrrd: sizes, geometry and value range of the source"
    { teem-unu head "$f" && teem-unu minmax "$f"; } >"$out" 2>"$err"; rc=$?
    expect_status 0
    check "same sizes, affine (1e-4 mm) and range" "$PY" - "$WORK/$name.ref.json" "$out" <<'PY'
import json, re, sys
import numpy as np
a = json.load(open(sys.argv[1]))
h = dict(l.split(": ", 1) for l in open(sys.argv[2]).read().splitlines() if ": " in l and not l.startswith("#"))
vec = lambda t: [float(x) for x in t.strip("()").split(",")]
cols = [vec(t) for t in re.findall(r"\([^)]*\)", h["space directions"])]
m = np.eye(4)
m[:3, :3] = np.array(cols).T
m[:3, 3] = vec(h["space origin"])
if h["space"].startswith("left-posterior"):
    m[:2, :] *= -1          # LPS -> RAS, nibabel's frame
ok = [int(x) for x in h["sizes"].split()] == a["shape"]
ok &= np.abs(m - np.array(a["affine"])).max() <= 1e-4
ok &= abs(float(h["min"]) - a["min"]) <= 1e-6 * max(1.0, abs(a["min"]))
ok &= abs(float(h["max"]) - a["max"]) <= 1e-6 * max(1.0, abs(a["max"]))
sys.exit(0 if ok else 1)
PY
  fi
  # VTK's image data is 3-D: a 4-D MetaImage has no VTK reader to check it with.
  if [ $have_vtk = 1 ] && [ "$("$PY" -c "import json; print(len(json.load(open('$WORK/$name.ref.json'))['shape']))")" = 3 ]; then
    f="$WORK/$name.mha"
    "$FEST_BIN/fconv" "$src" -o "$f"
    case_ "VTK reads fconv's $name.mha: dimensions and value range of the source"
    "$PY" "$here/vtk_read.py" "$f" >"$out" 2>"$err"; rc=$?
    expect_status 0
    check "same dimensions and range" "$PY" - "$WORK/$name.ref.json" "$out" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ok = a["shape"][:3] == b["dims"]
ok &= abs(a["min"] - b["range"][0]) <= 1e-6 * max(1.0, abs(a["min"]))
ok &= abs(a["max"] - b["range"][1]) <= 1e-6 * max(1.0, abs(a["max"]))
sys.exit(0 if ok else 1)
PY
  fi
done

finish_interop
