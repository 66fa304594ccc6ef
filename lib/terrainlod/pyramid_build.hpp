#pragma once
// Building the tile pyramid (docs/terrainlod.md §2-§3): pad the DEM, choose every level's
// lattice and height quantum, and simplify every tile with the collapse engine, from the
// leaves up. By default (the seed's reference, docs/terrainlod.md §1) level l is measured against the
// finished base triangulations of level l+2 (level L for l = L-1), so the work per tile
// does not grow with the DEM and the error against the DEM stays within (4/3) eps_l; the
// DEM itself (`original`, eps_l) and level l+1 (2 eps_l) are there for validation. Level L
// with --leaf-error 0 is the DEM's own surface (only collapses that change nothing), so
// levels measured against it use the DEM's grid, whose exact overlay is cheaper. Each tile
// is measured with all its transition variants, so every one of its 16 triangulations
// keeps the bound. Tiles of a level are independent, so they are built in parallel and the
// result does not depend on the thread count.

#include <functional>
#include <string>
#include <vector>

#include "terrainlod/height_grid.hpp"
#include "terrainlod/pyramid_plan.hpp"
#include "terrainlod/reference_surface.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod/tile.hpp"

namespace fest::terrainlod {

// What level l is measured against while it is simplified (docs/terrainlod.md §1).
enum class Reference {
  level_plus_2,  // the seed's: the finished level l+2 (level L for l = L-1); <= (4/3) eps_l vs the DEM
  level_plus_1,  // the finished level l+1; <= 2 eps_l vs the DEM
  original,      // the DEM itself; <= eps_l (every level costs as much as the leaves)
};

struct BuildParams {
  PyramidParams pyramid;
  double height_quantum = 0.25;  // q: interior height quantum as a fraction of eps_l
  double z_quantum = 1;          // delta_min: finest height quantum (world units)
  double leaf_error = 0;         // tolerance of the leaf level
  DiagonalRule diagonal = DiagonalRule::shortest;
  Reference reference = Reference::level_plus_2;
  StartRule start = StartRule::rtin;  // what each tile's engine decimates from
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

// Receives the finished tiles with their coding (tile_codec.hpp), level by level from the
// leaves (L) up to the root, each level in transmission order (rows from the south, then
// columns), on the calling thread.
using TileSink = std::function<void(Tile&&, std::string&&)>;

// `grid` must be conditioned (no NaN); dx, dy only shape eps (docs/terrainlod.md §1). `progress` is
// called with (tiles done, tiles total) from the calling thread. The returned pyramid
// has its levels but no tiles: they went to `sink` as they were finished.
Pyramid build_pyramid_streaming(const HeightGrid& grid, double dx, double dy, const BuildParams& params,
                                const TileSink& sink,
                                const std::function<void(std::size_t, std::size_t)>& progress = {});

// The same with every tile kept, in transmission order (small DEMs, tests).
Pyramid build_pyramid(const HeightGrid& grid, double dx, double dy, const BuildParams& params,
                      const std::function<void(std::size_t, std::size_t)>& progress = {});

// Largest vertical distance of a tile's triangulation (any mask) from the reference, in
// height units, measured triangle by triangle on the overlay.
double triangulation_error(const ReferenceSurface& ref, const TileTriangulation& t);

// Largest error over all triangulations of a tile (every mask of its refinable sides) and
// its height range; a triangle shared by several triangulations is measured once.
struct TileErrorRange {
  double err = 0, z_min = 0, z_max = 0;
  std::size_t triangulations = 0;
};
TileErrorRange tile_error(const ReferenceSurface& ref, const Tile& tile, const TileGeometry& geometry);

}  // namespace fest::terrainlod
