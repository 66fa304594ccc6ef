#pragma once
// Triangulating one closed loop of surface vertices (docs/isosurf.md "Loop construction",
// step 4). Every choice keeps the loop's edges as the boundary, so the mesh stays
// watertight whatever is chosen.

#include <array>
#include <cstdint>
#include <vector>

namespace fest::isosurface {

enum class Triangulation { minarea, fan, centroid };

// ids: the loop's vertex ids in loop order (3..64; longer loops return false); points: their positions (xyz);
// faces: per vertex a bit set of the cell faces on which a diagonal must be avoided (or
// null). Appends n - 2 triangles, oriented like the loop, and returns true; returns false
// (appending nothing) when no triangulation avoids those diagonals -- the caller then
// fans the loop around a new centroid vertex. Why: the neighbour across a face could
// choose the same diagonal between two crossings of that face, and the edge would belong
// to four triangles. The extractor forbids such diagonals on a cell's three lower faces
// only, so of two cells sharing a face exactly one may use them (docs/isosurf.md
// "Loop construction", step 4). The loop is first rotated to
// start at its smallest id (the first in key order), so the result does not depend on
// where the loop was entered; minarea ties keep the first minimum of that order.
bool triangulate_loop(const std::uint32_t* ids, const std::array<double, 3>* points, const std::uint8_t* faces, int n,
                      Triangulation how, std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace fest::isosurface
