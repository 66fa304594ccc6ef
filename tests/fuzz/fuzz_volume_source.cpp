// The frame-stream splitter, the volume source reader, its frames and the raw-layout
// parser and reader (formats/volume_source): any bytes must give a volume or fest::Error
// (std::invalid_argument for a layout text), never a crash or an unbounded allocation.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
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
    const fest::formats::VolumeFrames frames(in, o);
    for (std::size_t t = 0; t < frames.count() && t < 4; ++t) (void)frames.frame(t);
  } catch (const fest::Error&) {
  }
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)fest::formats::parse_raw_layout(text);
  } catch (const std::invalid_argument&) {
  }
  if (size >= 3) {  // the first bytes as a small layout, the rest as its samples
    fest::formats::RawLayout layout;
    layout.dims = {std::size_t(data[0] % 8 + 1), std::size_t(data[1] % 8 + 1), std::size_t(data[2] % 8 + 1)};
    layout.type = static_cast<fest::ScalarType>(data[0] % 10);
    layout.big_endian = data[1] & 1;
    try {
      (void)fest::formats::read_raw_volume(text.substr(3), layout, "fuzz");
    } catch (const fest::Error&) {
    }
  }
  return 0;
}
