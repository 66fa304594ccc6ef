#pragma once
// Triangles of one polygon face for formats and measures that need triangles (STL,
// Draco, surface distances). A convex polygon gives the fan around its first corner,
// as before; a concave one (assimp's concave_polygon.obj, a slit polygon that visits
// vertices twice) is cut into ears (ear clipping in the polygon's plane), so the
// triangles cover the polygon and nothing outside it, which a fan does not.

#include <array>
#include <cstddef>
#include <vector>

namespace fest {

// `corners` are the polygon's corner positions in order. Returns triangles as indices
// into `corners`, n - 2 of them for n >= 3 corners (none for fewer). Degenerate input
// (all corners on a line, or no ear found) and polygons of more than
// max_ear_clipped_corners corners fall back to the fan.
inline constexpr std::size_t max_ear_clipped_corners = 4096;
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<std::array<double, 3>>& corners);

}  // namespace fest
