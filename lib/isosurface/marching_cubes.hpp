#pragma once
// Exact marching cubes by loop construction (docs/isosurf.md "Exact mode"), accelerated by
// the min-max pyramid: only cells of active 8^3 blocks are visited, and the result is the
// same, byte for byte, as the brute-force scan.
//
// Vertices: one per crossed voxel edge, numbered in the order of the edge key
// 3*lin(lower sample) + axis, so every cell (and every thread) that meets a crossing
// names the same vertex; after them, in cell order, the centroid vertices of the rare
// loops that need one (triangulate_loop.hpp). Triangles: slab k, then 8^3 blocks (j, i),
// then cells (j, i) within a block, loops in table order.
// Deterministic for any thread count.

#include <cstddef>

#include "core/progress_callback.hpp"
#include "isosurface/cell_loops.hpp"
#include "isosurface/surface.hpp"
#include "isosurface/triangulate_loop.hpp"
#include "volume_pyramid/minmax_pyramid.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::isosurface {

struct ExtractOptions {
  FaceRule face_rule = FaceRule::decider;
  Triangulation triangulation = Triangulation::minarea;
  int threads = 1;
  ProgressFn progress;  // slab jobs done
};

struct ExtractStats {
  std::size_t cells_visited = 0;   // cells whose case was computed
  std::size_t blocks_active = 0;   // 8^3 blocks visited
  std::size_t blocks_total = 0;
  std::size_t centroid_vertices = 0;  // loops fanned around a new vertex (see triangulate_loop.hpp)
};

// `pyramid` may be null (brute-force scan); when given it must have been built from
// `grid` with finest level 3. Throws nothing for valid grids (dims >= 2 each).
Surface extract_isosurface(const volume_pyramid::ScalarGrid& grid, float iso, const ExtractOptions& options,
                           const volume_pyramid::MinMaxPyramid* pyramid, ExtractStats* stats = nullptr);

}  // namespace fest::isosurface
