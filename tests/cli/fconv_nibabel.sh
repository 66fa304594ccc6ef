#!/usr/bin/env bash
# fconv against nibabel, the independent reader: nibabel's own test volumes (fetched from
# Debian's python3-nibabel by scripts/fetch-test-data.sh) read by fest must have
# nibabel's shape and affine, and what fest writes (NIfTI-1, NIfTI-2, .hdr/.img pairs,
# MGZ, NRRD, MHA, 3-D and 4-D) must read back in nibabel with the same voxels and affine.
# The comparison is tests/cli/nibabel_check.py. Skips (77) without the data or nibabel.
. "$(dirname "$0")/lib.sh"
nib=$(need_testdata volumes/nibabel/functional.nii) || exit 77
nib=$(dirname "$nib")
# Debian's python3 (where python3-nibabel lives), else whatever python3 finds nibabel.
PY=""
for p in /usr/bin/python3 python3; do
  if "$p" -c 'import nibabel, numpy' 2>/dev/null; then PY=$p; break; fi
done
if [ -z "$PY" ]; then
  echo "skipped: nibabel is not installed (apt-get install python3-nibabel)" >&2
  exit 77
fi
check_py="$(dirname "$0")/nibabel_check.py"

# nibabel_agrees FILE: queues FILE for the comparison with nibabel (nibabel_check.py, run
# once for all files at the end, as Python's start is slow): fest's --info and a float64
# NIfTI written by fest must have nibabel's shape, affine and voxels.
agree_list="$WORK/agree.txt"
: >"$agree_list"
nibabel_agrees() {
  local f="$1" k
  k=$(wc -l <"$agree_list")
  "$FEST_BIN/fconv" --info "$f" >"$WORK/agree$k.json" 2>"$err" || { fail "fconv --info $f: $(cat "$err")"; return; }
  "$FEST_BIN/fconv" "$f" -o "$WORK/agree$k.nii" --type float64 2>"$err" || { fail "fconv $f: $(cat "$err")"; return; }
  echo "$f $WORK/agree$k.json $WORK/agree$k.nii" >>"$agree_list"
}
# nibabel_reads ORIGINAL WRITTEN: queues the check that nibabel reads fest's WRITTEN file
# with ORIGINAL's voxels and affine.
nibabel_reads() {
  local k
  k=$(wc -l <"$agree_list")
  "$FEST_BIN/fconv" --info "$1" >"$WORK/agree$k.json"
  echo "$1 $WORK/agree$k.json $2" >>"$agree_list"
}

# Each file: the dimensions nibabel states (shape; checked again by nibabel_check.py).
case_ "functional.nii: 4-D NIfTI-1, 20 frames"
run fconv --info "$nib/functional.nii"
expect_status 0
expect_json '[.dimensions, .frames, .format]' '[[17,21,3],20,"nifti"]'
nibabel_agrees "$nib/functional.nii"

case_ "example4d.nii.gz: 4-D NIfTI-1 with an oblique qform/sform"
run fconv --info "$nib/example4d.nii.gz"
expect_json '[.dimensions, .frames]' '[[128,96,24],2]'
nibabel_agrees "$nib/example4d.nii.gz"

case_ "example_nifti2.nii.gz: NIfTI-2 is recognised by content"
run fconv --info "$nib/example_nifti2.nii.gz"
expect_status 0
expect_json '[.format, .dimensions, .frames]' '["nifti2",[32,20,12],2]'
nibabel_agrees "$nib/example_nifti2.nii.gz"

case_ "3-D NIfTI-1 files"
for f in anatomical.nii reoriented_anat_moved.nii standard.nii.gz; do nibabel_agrees "$nib/$f"; done

case_ "test.mgz: FreeSurfer MGZ, 4-D, recognised by content"
run fconv --info "$nib/test.mgz"
expect_status 0
expect_json '[.format, .gzip, .dimensions, .frames]' '["mgh",true,[3,4,5],2]'
nibabel_agrees "$nib/test.mgz"

# nibabel ships three headers without their image files: give each a .img of zeros of
# the size nibabel computes (offset + voxels), then compare the geometry.
case_ "nibabel's analyze.hdr, nifti1.hdr and nifti2.hdr with a zero .img"
for h in analyze nifti1 nifti2; do
  cp "$nib/$h.hdr" "$WORK/$h.hdr"
done
"$PY" -c "
import nibabel as nib, numpy as np
for h in ['analyze', 'nifti1', 'nifti2']:
    i = nib.load('$WORK/' + h + '.hdr')
    n = int(np.prod(i.shape)) * i.header.get_data_dtype().itemsize + int(i.dataobj.offset)
    open('$WORK/' + h + '.img', 'wb').write(bytes(n))"
for h in analyze nifti1 nifti2; do nibabel_agrees "$WORK/$h.hdr"; done
run fconv --info "$WORK/analyze.hdr"
expect_json '.format' '"analyze"'
run fconv --info "$WORK/nifti2.img"   # named by its image file: read through the header
expect_json '.format' '"hdr"'

case_ ".hdr/.img pairs and Analyze 7.5 written by nibabel"
"$PY" -c "
import nibabel as nib, numpy as np
f = nib.load('$nib/functional.nii'); e = nib.load('$nib/example4d.nii.gz'); a = nib.load('$nib/anatomical.nii')
nib.Nifti1Pair(np.asarray(f.dataobj), f.affine, f.header).to_filename('$WORK/func_pair.hdr')
nib.Nifti2Pair(np.asarray(e.dataobj), e.affine).to_filename('$WORK/ex_pair2.hdr')
nib.AnalyzeImage(np.asarray(a.dataobj), a.affine).to_filename('$WORK/anat.hdr')
nib.Spm2AnalyzeImage(np.asarray(a.dataobj), a.affine).to_filename('$WORK/spm.hdr')"
for f in func_pair.hdr ex_pair2.hdr anat.hdr; do nibabel_agrees "$WORK/$f"; done
# SPM keeps this one's orientation in spm.mat, which fest does not read: refused.
run fconv --info "$WORK/spm.hdr"
expect_clean_failure 3 fconv
expect_stderr_has "spm.mat"

case_ "a pair without its .img, and a pair header on standard input"
cp "$WORK/func_pair.hdr" "$WORK/lonely.hdr"
run fconv --info "$WORK/lonely.hdr"
expect_clean_failure 4 fconv
expect_stderr_has "lonely.img"
run_stdin "$WORK/func_pair.hdr" fconv --info
expect_clean_failure 3 fconv
expect_stderr_has "\.img file"

# What fest writes, read by nibabel: every volume format nibabel reads, 3-D and 4-D.
# example4d is unscaled int16 (functional.nii's scaled values become float32 in fest,
# which is why nibabel_agrees writes float64).
case_ "fest writes 4-D NIfTI-1, NIfTI-2, pairs and MGZ that nibabel reads identically"
for spec in "w1.nii" "w1.nii.gz" "w2.nii --to nifti2" "wpair.hdr" "w.mgz"; do
  set -- $spec
  name=$1; shift
  "$FEST_BIN/fconv" "$nib/example4d.nii.gz" -o "$WORK/$name" "$@" 2>"$err" || { fail "fconv -> $name: $(cat "$err")"; continue; }
  nibabel_reads "$nib/example4d.nii.gz" "$WORK/$name"
done
check "the pair is two files" test -s "$WORK/wpair.img"
check "NIfTI-2 written with the full magic" test "$(head -c 12 "$WORK/w2.nii" | tail -c 8 | od -An -c | tr -d ' ')" = 'n+2\0\r\n032\n'

# (MGH is left out here: it stores the centre in float32, so the origin moves by ~1e-6 mm;
# nibabel_check.py compares MGZ above with a 1e-5 tolerance.)
case_ "4-D through NRRD and MHA and back: voxels, geometry and frame step unchanged"
"$FEST_BIN/fconv" "$nib/example4d.nii.gz" --to nrrd | "$FEST_BIN/fconv" --to mha | "$FEST_BIN/fconv" --to nifti2 |
  "$FEST_BIN/fconv" -o "$WORK/round.nii"
run fcompare "$nib/example4d.nii.gz" "$WORK/round.nii"
expect_status 0
"$FEST_BIN/fconv" "$nib/example4d.nii.gz" --to nrrd | "$FEST_BIN/fconv" --info >"$out"
expect_json '[.frames, .frame_spacing]' '[2,2000]'

case_ "--frame K takes one 3-D frame (nibabel's data[..., K])"
run fconv "$nib/functional.nii" --frame 7 -o "$WORK/f7.nii" --type float64
expect_status 0
"$FEST_BIN/fconv" --info "$WORK/f7.nii" >"$out"
expect_json '[.dimensions, .frames]' '[[17,21,3],null]'
check "frame 7 equals nibabel's" "$PY" -c "
import nibabel as nib, numpy as np, sys
a = np.asarray(nib.load('$nib/functional.nii').dataobj, dtype=float)[..., 7]
b = np.asarray(nib.load('$WORK/f7.nii').dataobj, dtype=float)
sys.exit(0 if np.array_equal(a, b) else 1)"
run fconv "$nib/functional.nii" --frame 20 -o "$WORK/f20.nii"
expect_clean_failure 3 fconv
expect_stderr_has "frame 20 does not exist"
check "nothing written" test ! -e "$WORK/f20.nii"

case_ "3-D tools refuse a 4-D series, naming the frames"
run segbrain run "$nib/functional.nii" -o "$WORK/seg.nii"
expect_status 3
expect_stderr_has "4-D series of 20 frames"

case_ "formats nibabel reads and fest refuses by name: MINC-1, MINC-2, CIFTI-2 (5-D)"
run fconv --info "$nib/minc1_4d.mnc"
expect_clean_failure 3 fconv
expect_stderr_has "MINC-1"
run fconv --info "$nib/minc2_4d.mnc"
expect_clean_failure 3 fconv
expect_stderr_has "MINC-2"
run fconv --info "$nib/row_major.dconn.nii"
expect_clean_failure 3 fconv
expect_stderr_has "5-D data"

# The count of clipped values comes from numpy: int16 values that round outside 0..255.
case_ "--type uint8 on int16 MRI: the warning's count is numpy's"
run fconv "$nib/example4d.nii.gz" --type uint8 -o "$WORK/u8.nii"
expect_status 0
want=$("$PY" -c "
import nibabel as nib, numpy as np
a = np.asarray(nib.load('$nib/example4d.nii.gz').dataobj).astype(float)
print(f'{int(np.count_nonzero((a < -0.5) | (a >= 255.5)))} of {a.size} values clipped to the uint8 range 0..255')")
expect_stderr_has "^fconv: warning: $want"

# --rescale: fest's voxels equal the formula of fconv(1) evaluated by numpy
# (round half away from zero; all values are >= 0 here, so floor(x + 0.5)).
case_ "--rescale on int16 MRI equals the documented formula"
run fconv "$nib/example4d.nii.gz" --type uint8 --rescale -o "$WORK/r8.nii"
expect_status 0
check "no warning" test ! -s "$err"
check "voxels equal numpy's" "$PY" -c "
import nibabel as nib, numpy as np, sys
a = np.asarray(nib.load('$nib/example4d.nii.gz').dataobj).astype(float)
lo, hi = a.min(), a.max()
want = np.floor(0 + (a - lo) * (255 - 0) / (hi - lo) + 0.5)
got = np.asarray(nib.load('$WORK/r8.nii').dataobj).astype(float)
sys.exit(0 if np.array_equal(want, got) else 1)"

case_ "nibabel agrees with fest on every file above (shape, affine, voxels)"
if "$PY" "$check_py" --list "$agree_list" >"$WORK/check.txt" 2>&1; then pass; else
  fail "$(grep -E 'DISAGREE|differ|DIFFER|shape:' "$WORK/check.txt" | tr '\n' ' ')"; fi
check "every queued file was compared" test "$(grep -c '^-- ' "$WORK/check.txt")" -eq "$(wc -l <"$agree_list")"

finish
