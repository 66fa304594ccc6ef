#pragma once
// FreeSurfer MGH volumes (.mgh; .mgz is the same gzip-compressed, unpacked by
// formats/input before this sees it). A small reader and writer of fest's own: the
// format is a fixed big-endian header, the voxels and an optional footer.
//
// Layout (FreeSurfer's mghformat, as nibabel reads it):
//   0  int32 version (1)          4  int32 width, height, depth, nframes
//   20 int32 type (0 uint8, 1 int32, 3 float32, 4 int16)
//   24 int32 dof                  28 int16 goodRASFlag
//   30 float32 spacing[3]         42 float32 Mdc[3][3] (row c: direction of voxel axis c)
//   78 float32 c_ras[3] (world position of voxel (width/2, height/2, depth/2))
//   284 voxels, x fastest, then y, z and frames
//   then optionally float32 TR (ms), flip angle, TE, TI, FoV and tags.
// World (RAS mm) of voxel ijk = Mdc^T diag(spacing) (ijk - dims/2) + c_ras; with
// goodRASFlag 0 the placement is FreeSurfer's default: spacing 1, Mdc rows (-1,0,0),
// (0,0,1), (0,-1,0), c_ras 0 (coronal slices, as nibabel does).

#include <string>
#include <string_view>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

constexpr std::size_t kMghDataOffset = 284;

// True when the bytes begin like an MGH file whose declared voxels fit in them.
bool looks_like_mgh(std::string_view bytes) noexcept;

Volume read_mgh(std::string_view bytes);
// Stores uint8, int16, int32 and float32; uint16 and int8 widen to int32 and int16
// without loss; other types are refused (bad_input naming --type), since MGH cannot
// hold them and fest does not narrow silently.
std::string write_mgh(const Volume& volume, ScalarType type);

}  // namespace fest::formats::volume_detail
