#!/usr/bin/env python3
"""Compares what fest read from a volume with what nibabel (an independent reader) reads.

    nibabel_check.py ORIGINAL INFO.json [CONVERTED]
    nibabel_check.py --list FILE      (lines "ORIGINAL INFO.json [CONVERTED]": one Python start)

ORIGINAL is any file nibabel loads; INFO.json is `fconv --info ORIGINAL`; CONVERTED (optional)
is the volume as fest wrote it (any format nibabel loads: .nii, .mgz, .hdr). Checks:
  * dimensions and frame count equal nibabel's shape;
  * fest's affine (direction * diag(spacing), origin) equals nibabel's affine to 1e-5 mm
    relative to the largest entry;
  * the converted file's voxels equal nibabel's get_fdata() of the original (NaN = NaN),
    and its affine equals the original's.
Prints one line per check and exits 0 when all pass, 1 otherwise.
"""
import json
import sys

import numpy as np
import nibabel as nib


def check(original, info_path, converted=None):
    print(f"-- {original}")
    img = nib.load(original)
    info = json.load(open(info_path))
    ok = True

    shape = tuple(int(x) for x in img.shape)
    fest_shape = tuple(info["dimensions"]) + ((info["frames"],) if "frames" in info else ())
    # nibabel keeps trailing singleton axes (dim[4] = 1); fest drops them.
    while len(shape) > 3 and shape[-1] == 1:
        shape = shape[:-1]
    if shape != fest_shape:
        print(f"shape: fest {fest_shape} nibabel {shape}")
        ok = False
    else:
        print(f"shape {shape} ok")

    d = np.array(info["direction"], dtype=float).reshape(3, 3)
    fest_aff = np.eye(4)
    fest_aff[:3, :3] = d * np.array(info["spacing"], dtype=float)
    fest_aff[:3, 3] = info["origin"]
    aff = np.asarray(img.affine, dtype=float)
    tol = 1e-5 * max(1.0, np.abs(aff).max())
    err = np.abs(fest_aff - aff).max()
    if err > tol:
        print(f"affine differs by {err}:\nfest\n{fest_aff}\nnibabel\n{aff}")
        ok = False
    else:
        print(f"affine ok (max difference {err:.3g})")

    if converted:
        a = np.asarray(img.dataobj, dtype=np.float64)
        out = nib.load(converted)
        b = np.asarray(out.dataobj, dtype=np.float64)
        while a.ndim > 3 and a.shape[-1] == 1:
            a = a[..., 0]
        if a.shape != b.shape:
            print(f"converted shape {b.shape} differs from {a.shape}")
            ok = False
        else:
            same = np.array_equal(a, b, equal_nan=True)
            print(f"converted voxels {'equal' if same else 'DIFFER (max ' + str(np.nanmax(np.abs(a - b))) + ')'}")
            ok = ok and same
        err2 = np.abs(np.asarray(out.affine, dtype=float) - aff).max()
        if err2 > tol:
            print(f"converted affine differs by {err2}")
            ok = False
        else:
            print(f"converted affine ok (max difference {err2:.3g})")
    return ok


def main():
    if sys.argv[1] == "--list":
        rows = [line.split() for line in open(sys.argv[2]) if line.strip()]
    else:
        rows = [sys.argv[1:4]]
    failed = [row[0] for row in rows if not check(*row)]
    if failed:
        print("DISAGREE: " + " ".join(failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
