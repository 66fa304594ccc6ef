#pragma once
// NIfTI-1 single files (.nii, magic "n+1"). Compressed .nii.gz arrives here already
// gunzipped (formats/input), so this sees only the plain bytes.

#include <string>
#include <string_view>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

Volume read_nifti(std::string_view bytes);
// Little-endian, vox_offset 352, no scaling; sform and qform both state the geometry.
std::string write_nifti(const Volume& volume, ScalarType type);

}  // namespace fest::formats::volume_detail
