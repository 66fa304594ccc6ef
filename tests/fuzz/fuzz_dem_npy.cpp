// terrainlod's .npy DEM reader (formats/dem: read_npy): the magic, the Python-dict header
// (descr, fortran_order, shape) and the array of one of eight types. Any bytes must give a
// raster whose size matches its samples, or a clean fest::Error.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/dem/dem_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fest::formats::read_npy(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const fest::Error&) {
  }
  return 0;
}
