#pragma once
// What a child tile knows from its decoded parent (docs/terrainlod.md §4, our version; man5
// terrainlod-pyramid "Progressive coding"). Used by the progressive tile coding.
//
// Lattices nest: a level's lattice has at least half as many cells per side as its
// parent's (the lattice refinement of pyramid_build.cpp), and the child covers half the
// parent's side, so one parent lattice step is r = 2 n_child / n_parent >= 1 child steps
// (both powers of two). A parent vertex (Xp, Yp) in quadrant (qx, qy) is therefore the
// child lattice point (Xp r - qx n, Yp r - qy n) exactly: it needs no xy bits (a coder that
// rounds positions onto non-nesting lattices would spend two xy bits per inherited vertex).
//
// Heights: every level derives its codes from the same finest-lattice height G of a DEM
// sample, so an inherited interior vertex has H_child = (H_parent << (k_p - k_c)) + low
// bits, and a parent interior vertex on the child's border (the lines that split the
// parent into quadrants) has G = (H_parent << k_p) + low bits. Parent border points carry
// G already, and the parent's refinement section holds the G of the child lattice points on
// its refinable sides: the child gets those border heights for free.

#include <cstdint>
#include <limits>
#include <vector>

#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

constexpr std::int64_t kUnknownHeight = std::numeric_limits<std::int64_t>::min();

struct InheritedVertex {
  int X = 0, Y = 0;          // child lattice coordinates
  std::int64_t code = 0;     // the parent's code: G on the parent's border, H_parent inside
  bool parent_border = false;
  bool child_border = false;
};

struct ParentView {
  int n = 0;                 // child lattice cells per side
  int ratio = 1;             // child lattice steps per parent lattice step
  int parent_k = 0;
  // Parent vertices in the child's closed square, in the parent's lattice order (rows from
  // the south, then columns from the west): the seed's "parent order", independent of how
  // the parent's stream ordered them.
  std::vector<InheritedVertex> inherited;
  // Per child border loop index (tile_codec's numbering): G where the parent gives it
  // (parent border points, the parent's refinement points), else kUnknownHeight.
  std::vector<std::int64_t> border_G;
  // floor(2 P) at each child lattice point (row-major, (n+1)^2), P the parent's base
  // triangulation at that point in finest height units (delta_min), interpolated exactly
  // in integers; kUnknownHeight where no parent triangle covers the point.
  std::vector<std::int64_t> surface2;

  std::int64_t surface_at(int X, int Y) const { return surface2[static_cast<std::size_t>(Y) * (n + 1) + X]; }
};

// Position of lattice point (X, Y) on the border loop of an n x n lattice
// (counter-clockwise from the south-west corner), or -1 inside; and back.
int border_index(int X, int Y, int n);
std::pair<int, int> border_point(int index, int n);

// The view of `parent` from its child `child` (level + 1, x / 2 and y / 2 equal to the
// parent's) whose lattice has 2^child_lattice_bits cells per side. Throws bad_input when
// the two do not nest (wrong parent, lattices that do not refine each other).
ParentView parent_view(const Tile& parent, const TileId& child, int child_lattice_bits);

}  // namespace fest::terrainlod
