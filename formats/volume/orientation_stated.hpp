#pragma once
// Whether a volume file states its orientation in the patient's space, or only voxel
// sizes (fconv's quick look says "orientation unknown" rather than guess; docs/fconv.md).
// fest's Volume always has a direction matrix (the identity where the file has none),
// so the question is answered from the file's header.

#include "formats/input.hpp"

namespace fest::formats {

// NIfTI-1/2 (and pairs): qform_code or sform_code > 0; MGH: goodRASflag set; NRRD: a
// "space directions" field; MetaImage: TransformMatrix, Orientation, Rotation or a
// known AnatomicalOrientation. False for Analyze 7.5, VTK image data, frame streams and
// anything else. Reads only the header; never throws.
bool volume_orientation_stated(const Input& in) noexcept;

}  // namespace fest::formats
