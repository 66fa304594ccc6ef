#pragma once
// Building the tile pyramid (spec terrainlod 2.3-2.6): pad the DEM, choose every level's
// lattice and height quantum, and simplify every tile with the collapse engine against the
// DEM surface. Each tile is measured with all its transition variants, so every one of its
// 16 triangulations stays within eps_l (including height quantization) of the DEM -- the
// spec's `--reference original`, which gives eps_l where the seed's level-(l+2) reference
// gives 4/3 eps_l. Tiles are independent, so they are built in parallel and the result
// does not depend on the thread count.

#include <functional>
#include <vector>

#include "terrainlod/height_grid.hpp"
#include "terrainlod/pyramid_plan.hpp"
#include "terrainlod/reference_surface.hpp"
#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

struct BuildParams {
  PyramidParams pyramid;
  double height_quantum = 0.25;  // q: interior height quantum as a fraction of eps_l
  double z_quantum = 1;          // delta_min: finest height quantum (world units)
  double leaf_error = 0;         // tolerance of the leaf level
  DiagonalRule diagonal = DiagonalRule::shortest;
  int threads = 1;
};

struct LevelInfo {
  int level = 0;
  int tiles_x = 0, tiles_y = 0;
  int cells = 0;          // DEM cells per tile side
  int lattice_bits = 0;   // n = 2^bits lattice cells per tile side
  int k = 0;              // interior height quantum exponent
  double eps = 0;         // budget eps_l (height units)
  double limit = 0;       // what the engine allows before quantization: eps_l - delta_l / 2
};

struct Pyramid {
  int levels = 0;         // L
  int padded = 0;         // samples per side after padding
  int width = 0, height = 0;  // DEM samples
  double delta_min = 1;
  std::vector<LevelInfo> level;
  std::vector<Tile> tiles;    // transmission order: by level, then row (south first), then column

  TileGeometry geometry(int l) const { return {level[static_cast<std::size_t>(l)].cells, delta_min}; }
};

// Edge replication to padded x padded samples.
HeightGrid pad_grid(const HeightGrid& grid, int padded);

// `grid` must be conditioned (no NaN); dx, dy only shape eps (spec 2.1). `progress` is
// called with (tiles done, tiles total) from the calling thread.
Pyramid build_pyramid(const HeightGrid& grid, double dx, double dy, const BuildParams& params,
                      const std::function<void(std::size_t, std::size_t)>& progress = {});

// Largest vertical distance of a tile's triangulation (any mask) from the reference, in
// height units, measured triangle by triangle on the overlay.
double triangulation_error(const ReferenceSurface& ref, const TileTriangulation& t);

}  // namespace fest::terrainlod
