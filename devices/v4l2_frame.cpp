#include "devices/v4l2_frame.hpp"

#include <vector>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"

namespace fest::devices {

bool is_supported_v4l2_format(std::uint32_t code) {
  return code == capture::fourcc_mjpg || capture::is_raw_format(code);
}

Image decode_v4l2_frame(const capture::RawFrame& frame) {
  if (frame.fourcc != capture::fourcc_mjpg) return capture::unpack_raw_frame(frame);
  if (frame.bytes.empty()) throw bad_input("MJPEG frame: empty");
  Image image;
  try {
    image = formats::read_image(frame.bytes, formats::Format::jpeg);
  } catch (const Error& e) {
    throw bad_input("MJPEG frame of {} bytes: {}", frame.bytes.size(), e.what());
  }
  if (image.pixels.cols != frame.width || image.pixels.rows != frame.height)
    throw bad_input("MJPEG frame: {} x {} pixels, the format negotiated {} x {}", image.pixels.cols,
                    image.pixels.rows, frame.width, frame.height);
  if (image.pixels.channels() == 1) cv::merge(std::vector<cv::Mat>(3, image.pixels), image.pixels);
  return image;
}

}  // namespace fest::devices
