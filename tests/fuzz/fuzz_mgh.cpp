// libFuzzer target: raw bytes into fest's own MGH reader (formats/volume/mgh.cpp hand-parses
// the FreeSurfer header). Whatever reads is written back as MGH and read again.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/volume/volume_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  using fest::formats::Format;
  try {
    const fest::Volume v = fest::formats::read_volume(bytes, Format::mgh);
    if (v.size() <= 4096) (void)fest::formats::read_volume(fest::formats::write_volume(v, Format::mgh), Format::mgh);
  } catch (const fest::Error&) {
  }
  return 0;
}
