#pragma once
// NRRD (teem's "nearly raw raster data") with attached data: raw, gzip or ascii encoding.

#include <string>
#include <string_view>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

Volume read_nrrd(std::string_view bytes);
// NRRD0004 in RAS space, little-endian, raw or gzip encoding.
std::string write_nrrd(const Volume& volume, ScalarType type, bool compress);

}  // namespace fest::formats::volume_detail
