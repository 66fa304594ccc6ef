// Pixel-centre inclusion in a screen-mask polygon (docs/volrender.md "--screen-mask").

#include "raycast/screen_polygon.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace fest::raycast {

bool inside(const std::vector<ScreenPoint>& polygon, double x, double y) {
  bool in = false;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    // Each edge ordered by y (lower endpoint first), so that two polygons sharing it
    // evaluate the same arithmetic and agree on which side a point lies.
    ScreenPoint a = polygon[k], b = polygon[(k + 1) % n];
    if (b.y < a.y) std::swap(a, b);
    // Half-open in y: the edge spans a.y <= y < b.y (a horizontal edge spans nothing), as if
    // y were moved an infinitesimal towards +y; vertices are never counted twice.
    if (!(a.y <= y && y < b.y)) continue;
    // The rightward ray from (x, y) crosses the edge when the point is strictly left of it
    // (orientation > 0 with a below b); a point on the edge is treated as moved to +x.
    const double orient = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
    if (orient > 0) in = !in;
  }
  return in;
}

std::vector<std::uint8_t> polygon_pixel_mask(const std::vector<ScreenPoint>& polygon, int width, int height) {
  if (polygon.size() < 3) throw std::invalid_argument("a screen polygon needs at least 3 vertices");
  double twice_area = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const ScreenPoint& a = polygon[k];
    const ScreenPoint& b = polygon[(k + 1) % polygon.size()];
    if (!std::isfinite(a.x) || !std::isfinite(a.y)) throw std::invalid_argument("a screen polygon vertex is not finite");
    twice_area += a.x * b.y - b.x * a.y;
  }
  if (twice_area == 0) throw std::invalid_argument("the screen polygon has zero area");
  if (width < 0 || height < 0) throw std::invalid_argument("negative image size");
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) mask[static_cast<std::size_t>(j) * width + i] = inside(polygon, i + 0.5, j + 0.5);
  return mask;
}

}  // namespace fest::raycast
