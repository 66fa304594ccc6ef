#pragma once
// The .tlt tile coding (spec terrainlod 2.9, our version 1; man5 terrainlod-pyramid):
// a byte-aligned header, then three bit-packed sections.
//
// - vertices: the 4n border lattice points are implicit (counter-clockwise from the
//   south-west corner); only their heights G are sent, deltas along the border. Interior
//   vertices follow in order of first use by the connectivity: X, Y, H as residuals from a
//   parallelogram prediction over the strip's shared edge. All residuals Rice coded.
// - connectivity: generalized triangle strips. Per triangle one bit (continue the strip /
//   restart); continuing, one bit names the shared edge of the previous triangle, (b, c)
//   or (a, c), then the third vertex; restarting, three vertices. A vertex is one bit
//   "the next interior vertex not used yet", or an index among the known neighbours of the
//   shared edge, or a distance back. Orientation comes from geometry (counter-clockwise).
// - refinement: per refinable border the finer neighbours' inserted points (G deltas);
//   the transitions themselves are implied (tile.hpp), so the 16 triangulations come
//   from the one stream with no stored conditions.

#include <cstdint>
#include <string>
#include <string_view>

#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

constexpr std::size_t kTileHeaderBytes = 62;

struct TileSizes {
  std::size_t header = 0, vertices = 0, connectivity = 0, refinement = 0;
  std::size_t total() const { return header + vertices + connectivity + refinement; }
};

// Encodes a tile (its vertex order is free: the coding picks its own). The tile's
// vertices must include every border lattice point.
std::string encode_tile(const Tile& tile, TileSizes* sizes = nullptr);

// Decodes a tile; throws bad_input naming the tile for anything malformed or truncated.
Tile decode_tile(std::string_view bytes);

// The header figures of an encoded tile, read without decoding its sections: view
// selection examines many more tiles than it draws and needs only their height range.
struct TileHeader {
  TileId id;
  float eps = 0, err = 0, z_min = 0, z_max = 0;
};
TileHeader read_tile_header(std::string_view bytes);

}  // namespace fest::terrainlod
