#pragma once
// The .tlt tile coding (docs/terrainlod.md §4, our version 1; man5 terrainlod-pyramid):
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
//
// Two codings (docs/terrainlod.md §4; the header's coding byte): standalone, every tile decodable alone,
// and progressive, a child tile relative to its decoded parent (tile_parent.hpp): the
// border heights the parent gives are not sent; the parent's interior vertices in the
// child's square are listed implicitly in parent order, one "present" bit each and, if
// present, only the k_parent - k_child low height bits (no xy bits: the lattices nest);
// parent interior vertices on the child's border send the k_parent low bits of G; new
// vertices' heights are predicted by the parent's surface or the parallelogram, whichever
// the tile's flag bit names. In the strips, run lengths (new vertices between two inherited
// ones) say where the kept inherited vertices enter, each named by its step in parent order.

#include <cstdint>
#include <string>
#include <string_view>

#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

constexpr std::size_t kTileHeaderBytes = 63;  // version 2; version 1 had 62 (no coding byte)

enum class TileCoding : std::uint8_t { standalone = 0, progressive = 1 };

struct TileSizes {
  std::size_t header = 0, vertices = 0, connectivity = 0, refinement = 0;
  TileCoding coding = TileCoding::standalone;
  std::size_t inherited_bits = 0;     // progressive: bits spent on the inherited vertices
  std::size_t inherited_present = 0;  // progressive: inherited interior vertices the tile keeps
  std::size_t total() const { return header + vertices + connectivity + refinement; }
};

// Encodes a tile standalone (its vertex order is free: the coding picks its own). The
// tile's vertices must include every border lattice point.
std::string encode_tile(const Tile& tile, TileSizes* sizes = nullptr);

// Encodes a tile progressively relative to its decoded parent (level - 1, x / 2, y / 2);
// the root, a null parent, or a tile that disagrees with its parent (a height the parent
// fixes differs) gets standalone coding.
std::string encode_tile_progressive(const Tile& tile, const Tile* parent, TileSizes* sizes = nullptr);

// Decodes a coded tile and codes it again in `coding`, keeping its strip order (cheaper
// than encoding: no strip search; the vertex numbering stays the same). `parent` is needed
// to decode a progressive tile and to code one.
std::string recode_tile(std::string_view bytes, TileCoding coding, const Tile* parent, TileSizes* sizes = nullptr);

// The coding named by a tile's header (version 1 tiles are standalone).
TileCoding tile_coding(std::string_view bytes);

// Decodes a tile; a progressive one needs its decoded parent. Throws bad_input naming the
// tile for anything malformed or truncated, or a progressive tile without its parent.
Tile decode_tile(std::string_view bytes, const Tile* parent = nullptr);

// The header figures of an encoded tile, read without decoding its sections: view
// selection examines many more tiles than it draws and needs only their height range.
struct TileHeader {
  TileId id;
  float eps = 0, err = 0, z_min = 0, z_max = 0;
};
TileHeader read_tile_header(std::string_view bytes);

}  // namespace fest::terrainlod
