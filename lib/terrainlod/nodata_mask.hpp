#pragma once
// Holes where the DEM has no data (build --nodata hole, docs/terrainlod.md §5 "Holes").
//
// The pyramid's geometry stays the filled one (nodata samples take the nearest valid
// height, height_grid.hpp), so the error budgets, simplification and transitions are
// exactly those of a filled build. What is added is the mask of nodata samples, stored
// once per pyramid, and one rule applied to every triangle drawn:
//
//   a triangle is drawn only when no nodata sample lies inside it or on its edges
//   (its closed footprint in grid units).
//
// So nothing is drawn over a nodata sample, every drawn vertex is a measured sample, and
// since the kept triangles are a subset of a crack-free surface, two drawn triangles
// still meet edge to edge; an edge may border a hole (nothing drawn across it).
//
// The byte form (the .tlp archive's nodata section, a pyramid directory's nodata.bin;
// man5 terrainlod-pyramid): "FTNM", version u8 (1), width u32, height u32, nodata count
// u64 (little-endian), then per row from the south: the number of nodata runs, and per
// run the gap from the previous run's end (the first from column 0) and its length, all
// LEB128 varints. Runs are non-empty and separated by at least one valid sample.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "terrainlod/height_grid.hpp"
#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

struct NodataMask {
  int width = 0, height = 0;               // DEM samples
  std::vector<std::uint32_t> row_begin;    // height + 1 entries: runs of row j are [row_begin[j], row_begin[j + 1])
  std::vector<std::array<int, 2>> runs;    // [x0, x1): columns x0 .. x1 - 1 are nodata
  std::size_t samples = 0;                 // nodata samples in all

  // Whether any sample of row j, columns x0 .. x1 (closed), is nodata. Beyond the last
  // column or row the pyramid's padding repeats the edge samples, so their validity is the
  // edge sample's (coordinates are clamped); negative coordinates are never asked.
  bool any_in_row(std::int64_t j, std::int64_t x0, std::int64_t x1) const;
  bool at(std::int64_t i, std::int64_t j) const { return any_in_row(j, i, i); }
};

// The smallest grid box {i0, j0, i1, j1} holding every valid sample (the automatic camera
// frames only what can be drawn); false when no sample is valid.
bool valid_bounds(const NodataMask& mask, std::array<int, 4>& box);

// The mask of a conditioned grid (its `valid` flags; none = no nodata).
NodataMask nodata_mask(const HeightGrid& grid);

std::string encode_nodata_mask(const NodataMask& mask);
// Throws bad_input in the section's terms for anything malformed or truncated.
NodataMask decode_nodata_mask(std::string_view bytes);

// The rule: whether a nodata sample lies in the closed triangle (grid units, any
// orientation). Exact in integers: per grid row the triangle's span is bounded by
// rationals whose ceiling and floor are taken exactly.
bool covers_nodata(const NodataMask& mask, const std::array<std::array<std::int64_t, 2>, 3>& v);

// Drops the triangles of a tile's triangulation that cover nodata and the vertices no
// kept triangle uses (the order of the rest is kept); returns how many triangles went.
std::size_t cut_holes(const NodataMask& mask, TileTriangulation& tri);

}  // namespace fest::terrainlod
