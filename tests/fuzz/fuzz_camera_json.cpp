// camera.json decoder of lib/markers (markerpose --camera).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "markers/camera_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fest::markers::decode_camera_json(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const fest::Error&) {
  }
  return 0;
}
