#pragma once
// View-dependent extraction (docs/terrainlod.md §5, seed 7.3): select the tiles a camera
// needs (frustum culling of each tile's box, the distance rule s_l f_px / d <= tau),
// close the quadtree so that edge neighbours differ by at most one level, and give every
// drawn tile its neighbour mask (which sides face a finer tile).

#include <array>
#include <functional>
#include <map>
#include <vector>

#include "terrainlod/tile.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {

struct Camera {
  std::array<double, 3> eye{}, target{}, up{0, 0, 1};
  double fovy_deg = 60;
  int width = 0, height = 0;
  double near = 1, far = 1e9;
  double tau_px = 1;
};

// Throws bad_input saying which camera parameter is wrong (zero-length view direction, looks
// along its up vector, fovy outside (0, 180), empty image, near/far order, tau <= 0).
void check_camera(const Camera& camera);

// What the selection needs to know about the pyramid, in world units.
struct PyramidLayout {
  int levels = 0;
  std::vector<int> tiles_x, tiles_y;  // per level
  std::vector<int> cells;             // DEM cells per tile side, per level
  int texels = 0;
  double origin_x = 0, origin_y = 0, dx = 1, dy = 1;
  bool exists(const TileId& t) const {
    return t.level >= 0 && t.level <= levels && t.x >= 0 && t.y >= 0 && t.x < tiles_x[static_cast<std::size_t>(t.level)] &&
           t.y < tiles_y[static_cast<std::size_t>(t.level)];
  }
};

struct SelectedTile {
  TileId id;
  unsigned mask = 0;          // bit per Side: that neighbour is one level finer
  bool closing_only = false;  // split only to close the quadtree
  // The tile whose texture it is drawn with: itself, or for a closing-only tile the
  // ancestor the distance rule chose (seed footnote 3: the parent's texture, mapped to
  // the sub-square).
  TileId texture;
};

struct Selection {
  std::vector<SelectedTile> tiles;  // sorted by id
  std::size_t visited = 0;          // tiles whose box was examined
};

// `z_range(id)` gives a tile's height range (loading its header); tiles outside the
// frustum are dropped.
Selection select_tiles(const PyramidLayout& layout, const Camera& camera,
                       const std::function<std::array<double, 2>(const TileId&)>& z_range);

// Whether the drawn tiles of a selection meet without cracks or T-junctions: every edge
// used by one triangle only must lie where no drawn tile continues the surface. Returns
// the number of offending edges. Triangles are in grid units (gx, gy) with their tile.
struct DrawnTriangle {
  std::array<TileTriangulation::Vertex, 3> v;
  TileId tile;
};
std::size_t count_open_edges(const PyramidLayout& layout, const Selection& selection,
                             const std::vector<DrawnTriangle>& triangles);

// The same check for a view with holes (build --nodata hole): `drawn` and `holes` (the
// triangles left out over nodata) together must be crack-free as above, and an edge of a
// drawn triangle with nothing drawn across it is accepted only where a hole's triangle
// lies across it. `open` counts the offending edges, `hole_edges` the accepted ones.
struct HoleEdgeCount {
  std::size_t open = 0, hole_edges = 0;
};
HoleEdgeCount count_open_edges(const PyramidLayout& layout, const Selection& selection,
                               const std::vector<DrawnTriangle>& drawn, const std::vector<DrawnTriangle>& holes);

}  // namespace fest::terrainlod
