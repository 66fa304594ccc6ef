#include "markers/quads.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace fest::markers {

namespace {

double side_length(const Corners& c, int i) { return cv::norm(c[(i + 1) % 4] - c[i]); }

bool near_duplicate(const Corners& a, const Corners& b) {
  // Same quad whatever its starting corner: mean distance under a tenth of the side.
  const double side = 0.25 * (side_length(a, 0) + side_length(a, 1) + side_length(a, 2) + side_length(a, 3));
  for (int shift = 0; shift < 4; ++shift) {
    double d = 0;
    for (int i = 0; i < 4; ++i) d += cv::norm(a[i] - b[(i + shift) % 4]);
    if (d / 4 < 0.1 * side) return true;
  }
  return false;
}

}  // namespace

std::vector<Corners> find_quads(const cv::Mat& grey8, const QuadOptions& options) {
  CV_Assert(grey8.type() == CV_8UC1);
  std::vector<Corners> quads;
  const double max_side = options.max_side_fraction * std::max(grey8.cols, grey8.rows);
  cv::Mat half;  // large windows work on the half-resolution image: 4x fewer pixels, less noise
  cv::Mat dark;
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  std::vector<cv::Point> poly;
  for (int window : options.windows) {
    const bool downscale = window >= options.half_resolution_window;
    if (downscale && half.empty()) cv::pyrDown(grey8, half);
    const cv::Mat& src = downscale ? half : grey8;
    const int w = downscale ? (window / 2) | 1 : window | 1;
    const double scale = downscale ? 2.0 : 1.0;
    if (w >= std::min(src.cols, src.rows)) continue;
    // Dark = below local mean - offset: the marker's border and black cells are foreground.
    cv::adaptiveThreshold(src, dark, 255, cv::ADAPTIVE_THRESH_MEAN_C, cv::THRESH_BINARY_INV, w,
                          options.threshold_offset);
    contours.clear();
    hierarchy.clear();
    // Two-level hierarchy: outer boundaries of dark components (parent -1) are where a
    // black border meets the white around it; holes are skipped.
    cv::findContours(dark, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_NONE);
    const double min_side = options.min_side_px / scale, longest_side = max_side / scale;
    for (std::size_t i = 0; i < contours.size(); ++i) {
      if (hierarchy[i][3] >= 0) continue;
      const std::vector<cv::Point>& c = contours[i];
      if (c.size() < 4 * min_side || c.size() > 4 * longest_side) continue;
      const double perimeter = static_cast<double>(c.size());
      cv::approxPolyDP(c, poly, std::max(1.0, options.polygon_epsilon * perimeter), true);
      if (poly.size() != 4 || !cv::isContourConvex(poly)) continue;
      bool at_edge = false;
      for (const cv::Point& p : poly)
        at_edge |= p.x <= 1 || p.y <= 1 || p.x >= src.cols - 2 || p.y >= src.rows - 2;
      if (at_edge) continue;
      Corners q;
      // A half-resolution pixel i covers full-resolution pixels 2i and 2i+1.
      for (int k = 0; k < 4; ++k) q[k] = cv::Point2d(scale * poly[k].x + (scale - 1) / 2, scale * poly[k].y + (scale - 1) / 2);
      // Clockwise on screen (y down) means positive signed area in these coordinates.
      double area = 0;
      for (int k = 0; k < 4; ++k) area += q[k].x * q[(k + 1) % 4].y - q[(k + 1) % 4].x * q[k].y;
      if (area < 0) std::swap(q[1], q[3]);
      double shortest = 1e300, longest = 0;
      for (int k = 0; k < 4; ++k) {
        shortest = std::min(shortest, side_length(q, k));
        longest = std::max(longest, side_length(q, k));
      }
      if (shortest < options.min_side_px || longest > max_side || shortest < 0.15 * longest) continue;
      // The contour runs along the outermost dark pixels: move the corners half a pixel
      // outwards (pixel centres vs. the edge between dark and light).
      const cv::Point2d centre = 0.25 * (q[0] + q[1] + q[2] + q[3]);
      for (cv::Point2d& p : q) {
        const cv::Point2d d = p - centre;
        p += d * (0.5 * scale / std::max(1e-9, cv::norm(d)));
      }
      bool duplicate = false;
      for (const Corners& other : quads) duplicate = duplicate || near_duplicate(other, q);
      if (!duplicate) quads.push_back(q);
    }
  }
  return quads;
}

}  // namespace fest::markers
