#pragma once
// extract --clip (docs/terrainlod.md §5, clipping to the DEM): the pyramid covers a padded
// square larger than the DEM; clipping cuts every drawn triangle at the DEM's east and
// north edges (grid x = last_x, y = last_y) so that exactly the DEM rectangle remains.
//
// Dropping only the triangles entirely beyond an edge (what --clip first did) kept every
// triangle with one vertex inside: over flat ground (the sea, the padding's clamped
// heights) the simplified tiles have triangles that reach from inside the DEM far into
// the padding, so some of the padding stayed and some went, a ragged "bite" at the far
// corner. Cutting is exact: a triangle is planar, so its part inside the rectangle is a
// convex polygon on the same plane; heights at the cut points are interpolated linearly
// along the cut edge.

#include <array>
#include <cstdint>
#include <vector>

#include "terrainlod/tile.hpp"
#include "terrainlod/triangle_error.hpp"

namespace fest::terrainlod {

// The part of triangle (a, b, c) with x <= last_x and y <= last_y, as a fan of triangles
// (same orientation as the input); empty when nothing is inside. A cut point depends only
// on the edge it lies on, not on the triangle or the direction the edge is walked, so two
// triangles sharing an edge get bit-identical cut points (a crack-free mesh stays one).
std::vector<std::array<GridPoint, 3>> clip_to_dem(const std::array<TileTriangulation::Vertex, 3>& t, std::int64_t last_x,
                                                   std::int64_t last_y);

}  // namespace fest::terrainlod
