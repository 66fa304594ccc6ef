#pragma once
// NIfTI-1, NIfTI-2 and Analyze 7.5 volumes, single files (.nii) and header/image pairs
// (.hdr/.img). Compressed .nii.gz arrives here already gunzipped (formats/input), so
// this sees only plain bytes; the image file of a pair is passed beside its header.
//
// The header is checked here (for clear messages naming the field) and then converted
// to NIfTI's image description by nifti_clib (nifti_convert_n1hdr2nim /
// nifti_convert_n2hdr2nim: byte order, qform quaternion, sform, scaling), from which the
// volume takes its geometry. Analyze 7.5 has no orientation fields; its placement
// follows SPM's convention, as nibabel does: x flipped (radiological storage), origin
// from the `originator` voxel, else the centre of the grid (see fest-formats(5)).

#include <string>
#include <string_view>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

// Reads a single file (`image` empty and unused) or a pair: `bytes` is the header file
// and `image` the content of the image file. A pair header without its image file is
// refused with a message saying where the data would be.
Volume read_nifti(std::string_view bytes, const std::string_view* image = nullptr);

// NIfTI-1 single file: little-endian, vox_offset 352, no scaling; sform and qform both
// state the geometry; 4-D series set dim[4] and pixdim[4] (seconds).
std::string write_nifti(const Volume& volume, ScalarType type);
// NIfTI-2 single file (64-bit sizes, double-precision geometry), vox_offset 544.
std::string write_nifti2(const Volume& volume, ScalarType type);
// NIfTI-1 pair: the .hdr (348 bytes and the 4-byte extension flag, magic "ni1") and the
// .img (the voxels from byte 0).
struct NiftiPairBytes {
  std::string header, image;
};
NiftiPairBytes write_nifti_pair(const Volume& volume, ScalarType type);

}  // namespace fest::formats::volume_detail
