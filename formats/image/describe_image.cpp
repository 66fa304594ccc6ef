// describe_image: size, depth, colour space and per-channel range of an image as JSON.
#include <cmath>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/image/image_io.hpp"

namespace fest::formats {
namespace {

const char* depth_name(int depth) {
  switch (depth) {
    case CV_8U: return "uint8";
    case CV_16U: return "uint16";
    case CV_32F: return "float32";
    default: return "other";
  }
}

// Per-channel minimum and maximum, ignoring NaN; a channel with no number gives null.
template <typename Sample>
void channel_ranges(const cv::Mat& m, nlohmann::json& mins, nlohmann::json& maxs) {
  const int n = m.channels();
  std::vector<double> lo(std::size_t(n), std::numeric_limits<double>::infinity());
  std::vector<double> hi(std::size_t(n), -std::numeric_limits<double>::infinity());
  std::vector<bool> seen(std::size_t(n), false);
  for (int y = 0; y < m.rows; ++y) {
    const Sample* row = m.ptr<Sample>(y);
    for (int x = 0; x < m.cols; ++x)
      for (int c = 0; c < n; ++c) {
        const double v = static_cast<double>(row[x * n + c]);
        if (std::isnan(v)) continue;
        const auto i = std::size_t(c);
        seen[i] = true;
        if (v < lo[i]) lo[i] = v;
        if (v > hi[i]) hi[i] = v;
      }
  }
  for (std::size_t c = 0; c < std::size_t(n); ++c) {
    mins.push_back(seen[c] ? nlohmann::json(lo[c]) : nlohmann::json());
    maxs.push_back(seen[c] ? nlohmann::json(hi[c]) : nlohmann::json());
  }
}

}  // namespace

nlohmann::json describe_image(const Image& image) {
  const cv::Mat& m = image.pixels;
  nlohmann::json j;
  j["width"] = m.cols;
  j["height"] = m.rows;
  j["channels"] = m.channels();
  j["depth"] = depth_name(m.depth());
  j["color_space"] = color_space_name(image.color_space);
  nlohmann::json mins = nlohmann::json::array(), maxs = nlohmann::json::array();
  if (m.dims == 2 && !m.empty()) {
    switch (m.depth()) {
      case CV_8U: channel_ranges<std::uint8_t>(m, mins, maxs); break;
      case CV_16U: channel_ranges<std::uint16_t>(m, mins, maxs); break;
      case CV_32F: channel_ranges<float>(m, mins, maxs); break;
      default: break;
    }
  }
  j["min"] = mins;
  j["max"] = maxs;
  return j;
}

}  // namespace fest::formats
