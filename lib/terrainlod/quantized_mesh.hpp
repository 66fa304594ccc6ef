#pragma once
// Cesium quantized-mesh-1.0 coding of one tile triangulation (the format the tile sizes
// are compared against, docs/terrainlod.md §6): an 88-byte header, u/v/height as 15-bit values (0..32767) zig-zag
// delta coded, triangle indices high-water-mark coded (16 bit, 32 bit above 65,536
// vertices), and the west/south/east/north edge vertex lists. No extensions. The header's
// centre and bounding sphere are in the DEM's own world coordinates (fest pyramids are
// projected, not geocentric).

#include <string>

#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

struct QmFrame {
  std::int64_t gx0 = 0, gy0 = 0, cells = 1;  // tile square in grid units
  double origin_x = 0, origin_y = 0, dx = 1, dy = 1;
};

std::string encode_quantized_mesh(const TileTriangulation& tri, const QmFrame& frame);

}  // namespace fest::terrainlod
