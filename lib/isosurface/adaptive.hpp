#pragma once
// Focus-adaptive, crack-free isosurfaces (docs/isosurf.md "Adaptive mode"; the chapter's
// fig. 4.3a after Westermann, Kobbelt & Ertl 1999; selection, closure and transition faces
// reconstructed): octree leaves of coarser levels far from a focus point and where the
// data is smooth, a closure loop (2:1 balance, edge consistency) and leaves whose faces
// towards finer neighbours are split into 2x2 sub-faces, so that both sides of every
// (sub-)face produce the same segments and the surface has no holes between levels.
// Vertices sit on finest-level voxel edges (the same keys and positions as exact mode).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "isosurface/cell_loops.hpp"
#include "isosurface/surface.hpp"
#include "isosurface/triangulate_loop.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::isosurface {

// Where the closure loop demands that a leaf edge has at most its one finest crossing
// (docs/isosurf.md 5.2): `transitions` only on edges that a finer active leaf also touches
// (what crack-freeness needs: the two views of the edge must agree); `all` on every edge
// of every leaf (keeps each thin feature that crosses a leaf edge, at many more leaves).
enum class EdgeRule { transitions, all };

struct AdaptiveOptions {
  std::optional<std::array<double, 3>> focus;  // world units; none = no distance rule
  double focus_radius = 0;   // r0 (world units); <= 0: diagonal / 32
  double max_error = 0;      // eps0 in data units; +inf = distance rule only
  double error_growth = 1;   // eps = eps0 (1 + d / r0)^P
  int max_level = -1;        // coarsest leaf level; -1 = the root's
  EdgeRule edge_rule = EdgeRule::transitions;
  FaceRule face_rule = FaceRule::decider;
  Triangulation triangulation = Triangulation::minarea;
  int threads = 1;
};

struct Leaf {
  std::uint8_t level;
  std::uint32_t i, j, k;  // node index at its level (cells i*2^level ...)
};

struct AdaptiveResult {
  Surface surface;
  std::vector<Leaf> leaves;                 // active leaves, sorted by (k, j, i) of their first cell, then level
  std::vector<std::size_t> leaves_per_level;
  std::size_t closure_splits = 0;
  std::size_t centroid_vertices = 0;
  double max_error_bound = 0;               // largest eps(n) of a selected leaf of level >= 1 (when errors were computed)
};

// `pyramid` must have been built from `grid` with finest level 3.
AdaptiveResult extract_adaptive(const volume_pyramid::ScalarGrid& grid, float iso, const AdaptiveOptions& options,
                                const volume_pyramid::MinMaxPyramid& pyramid);

}  // namespace fest::isosurface
