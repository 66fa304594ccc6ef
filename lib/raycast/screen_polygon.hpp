#pragma once
// A screen-mask polygon in image pixel coordinates (docs/volrender.md "--screen-mask"): one
// viewer's part of a multi-mirror Virtual Showcase screen, e.g. a quadrant triangle of a
// four-mirror pyramid. x grows to the right, y downwards, row 0 at the top; pixel (i, j)
// covers [i, i+1] x [j, j+1] and is cast when its centre (i + 1/2, j + 1/2) is inside.

#include <cstdint>
#include <vector>

namespace fest::raycast {

struct ScreenPoint {
  double x = 0, y = 0;
};

// Even-odd rule (the same as nonzero for a simple polygon, convex or not). A centre on an
// edge counts as inside exactly when the point moved an infinitesimal step to +x (then +y)
// is, so polygons that share edges -- the four triangles of a screen's diagonals -- claim
// every pixel of their union exactly once. Vertices may lie outside the image.
bool inside(const std::vector<ScreenPoint>& polygon, double x, double y);

// The pixels whose centres are inside: width x height, row 0 at the top, 1 = cast
// (RenderOptions::pixel_mask). Throws std::invalid_argument for fewer than 3 vertices, a
// non-finite coordinate or a zero-area polygon.
std::vector<std::uint8_t> polygon_pixel_mask(const std::vector<ScreenPoint>& polygon, int width, int height);

}  // namespace fest::raycast
