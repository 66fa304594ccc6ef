#pragma once
// MetaImage (ITK's .mha) with the data in the same file (ElementDataFile = LOCAL).
// MetaImage world coordinates are LPS; fest's are RAS, so x and y flip both ways.

#include <string>
#include <string_view>

#include "core/volume.hpp"

namespace fest::formats::volume_detail {

Volume read_metaimage(std::string_view bytes);
// Little-endian binary, zlib-compressed when asked (CompressedData = True).
std::string write_metaimage(const Volume& volume, ScalarType type, bool compress);

}  // namespace fest::formats::volume_detail
