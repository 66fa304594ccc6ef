// libFuzzer target: raw bytes into feshape's point-row decoder; what decodes must encode
// and decode again to the same points.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/error.hpp"
#include "feshape/xyz_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto points = fest::feshape::decode_points(bytes);
    if (fest::feshape::decode_points(fest::feshape::encode_points(points)) != points) std::abort();
  } catch (const fest::Error&) {
  }
  return 0;
}
