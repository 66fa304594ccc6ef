// Image stream splitter of formats/image (markerpose reading frames from a pipe).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/image/image_stream.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    for (std::string_view f : fest::formats::split_image_stream(std::string_view(reinterpret_cast<const char*>(data), size)))
      if (f.empty()) __builtin_trap();  // every frame has bytes
  } catch (const fest::Error&) {
  }
  return 0;
}
