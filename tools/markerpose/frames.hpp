#pragma once
// The frames markerpose reads: image files, a list file, or standard input holding one
// image or a stream of them (formats/image/image_stream.hpp). Sizes are checked against
// the camera before any pixel is decoded.

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace fest::markerpose_tool {

struct FrameSource {
  std::string name;       // file name, or "-#k" for frame k of standard input
  std::string bytes;      // the encoded image
  int width = 0, height = 0;
};

// Throws fest::Error: io for unreadable files, bad_input for malformed images, an empty
// list, or frames whose size differs from width x height (naming the first such frame
// and how many there are).
std::vector<FrameSource> gather_frames(const std::vector<std::string>& inputs, const std::string& list, int width,
                                       int height, const std::string& camera_path);

// Decodes one frame to 8-bit grey (colour by luma, 16-bit scaled, float 0..1 scaled).
cv::Mat decode_grey(const FrameSource& f);
// Decodes one frame to 8-bit RGB (for the overlay).
cv::Mat decode_rgb(const FrameSource& f);

}  // namespace fest::markerpose_tool
