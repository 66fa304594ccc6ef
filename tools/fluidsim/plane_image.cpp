// Rendered planes -> OpenCV images (row 0 at the top, as Plane stores them).
#include "plane_image.hpp"

#include <cmath>
#include <cstdint>

namespace fest::fluidsim_tool {

using namespace fest::fluidsim;

cv::Mat plane_to_rgb(const Plane& p, double lo, double hi, Colormap map, int depth) {
  cv::Mat m(p.height, p.width, depth == 16 ? CV_16UC3 : CV_8UC3);
  const double top = depth == 16 ? 65535.0 : 255.0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const double t = (p.values[static_cast<std::size_t>(y) * p.width + x] - lo) / (hi - lo);
      const auto rgb = colour(map, t);
      for (int k = 0; k < 3; ++k) {
        const double v = std::lround(rgb[k] * top);
        if (depth == 16)
          m.ptr<std::uint16_t>(y)[3 * x + k] = static_cast<std::uint16_t>(v);
        else
          m.ptr<std::uint8_t>(y)[3 * x + k] = static_cast<std::uint8_t>(v);
      }
    }
  return m;
}

cv::Mat plane_to_float(const Plane& p) {
  cv::Mat m(p.height, p.width, CV_32FC1);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) m.ptr<float>(y)[x] = static_cast<float>(p.values[static_cast<std::size_t>(y) * p.width + x]);
  return m;
}

}  // namespace fest::fluidsim_tool
