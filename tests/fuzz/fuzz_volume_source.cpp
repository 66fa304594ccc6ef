// The frame-stream splitter and the volume source reader (formats/volume_source): any
// bytes must give a volume or fest::Error, never a crash or an unbounded allocation.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "formats/input.hpp"
#include "formats/volume_source/volume_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    (void)fest::formats::split_frame_stream(bytes, "fuzz");
  } catch (const fest::Error&) {
  }
  try {
    const auto in = fest::formats::recognise(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
    fest::formats::VolumeSourceOptions o;
    o.field = size % 2 ? "density" : "";
    (void)fest::formats::read_volume_source(in, o);
  } catch (const fest::Error&) {
  }
  return 0;
}
