// libFuzzer target for the frames a V4L2 camera hands over (devices/v4l2_frame): the
// bytes of a dequeued buffer are untrusted (a USB transfer cut short, a camera's
// firmware bug). The first 4 bytes choose the pixel format, the frame size and the row
// padding; the rest is the buffer. For MJPEG the size is also taken from the JPEG's own
// header when it has one, so that mutations reach the decoder instead of stopping at
// the size check. Only fest::Error may escape.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "capture/pixel_formats.hpp"
#include "core/error.hpp"
#include "devices/v4l2_frame.hpp"
#include "formats/image/image_io.hpp"

namespace {

constexpr std::uint32_t formats[] = {fest::capture::fourcc_yuyv, fest::capture::fourcc_mjpg,
                                     fest::capture::fourcc_grey, fest::capture::fourcc_rgb3,
                                     fest::capture::fourcc_y16, fest::capture::fourcc('N', 'V', '1', '2')};

void decode(const fest::capture::RawFrame& f) {
  try {
    (void)fest::devices::decode_v4l2_frame(f);
  } catch (const fest::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 4) return 0;
  fest::capture::RawFrame f;
  f.fourcc = formats[data[0] % (sizeof formats / sizeof formats[0])];
  f.width = 1 + data[1] % 96;
  f.height = 1 + data[2] % 96;
  f.stride = fest::capture::raw_row_bytes(f.fourcc, f.width) + data[3] % 16 - 2;  // sometimes too short
  f.bytes = std::string_view(reinterpret_cast<const char*>(data) + 4, size - 4);
  decode(f);
  if (f.fourcc == fest::capture::fourcc_mjpg) {
    try {
      const fest::formats::ImageHeader h = fest::formats::read_image_header(f.bytes, fest::formats::Format::jpeg);
      if (std::uint64_t(h.width) * std::uint64_t(h.height) > (std::uint64_t{1} << 22)) return 0;
      f.width = h.width;
      f.height = h.height;
      decode(f);
    } catch (const fest::Error&) {
    }
  }
  return 0;
}
