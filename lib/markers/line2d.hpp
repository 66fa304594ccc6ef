#pragma once
// A straight line in the image and the point where two meet: the marker's corners are
// the intersections of its four fitted sides (docs/markerpose.md §2.3, §2.4).

#include <cmath>

#include <opencv2/core.hpp>

namespace fest::markers {

struct Line {
  cv::Point2d point, dir;  // a point on the line and its unit direction
};

// The intersection of a and b; false when they are (nearly) parallel.
inline bool intersect(const Line& a, const Line& b, cv::Point2d& out) {
  const double det = a.dir.x * (-b.dir.y) - a.dir.y * (-b.dir.x);
  if (std::abs(det) < 1e-9) return false;
  const cv::Point2d d = b.point - a.point;
  const double s = (d.x * (-b.dir.y) - d.y * (-b.dir.x)) / det;
  out = a.point + s * a.dir;
  return true;
}

}  // namespace fest::markers
