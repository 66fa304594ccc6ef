#pragma once
// EXR with more than the pixels: extra named float channels (hdrmerge's "valid") and
// header attributes (docs/hdrmerge.md §5: chromaticities, exposures, responseSha256,
// turntableAngleDeg, lightId). read_image() reads such a file's R,G,B and skips a
// "valid" channel; read_exr_channel() reads one named channel.

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace fest::formats {

struct ExrExtras {
  std::vector<std::pair<std::string, cv::Mat>> channels;  // CV_32FC1, the image's size
  std::map<std::string, std::string> strings;
  std::map<std::string, double> doubles;
  std::map<std::string, std::vector<float>> float_vectors;
  bool srgb_chromaticities = true;  // the standard "chromaticities" attribute (Rec. 709 / sRGB primaries)
};

// rgb: CV_32FC3 (R,G,B order). Throws bad_input for other types or mismatched channels.
std::string write_exr_with_extras(const cv::Mat& rgb, const ExrExtras& extras, bool half);

// One channel as CV_32FC1; bad_input when the file has no channel of that name.
cv::Mat read_exr_channel(std::string_view bytes, const std::string& name);
// String, double/float and float-vector attributes of the header (others are left out).
ExrExtras read_exr_attributes(std::string_view bytes);

}  // namespace fest::formats
