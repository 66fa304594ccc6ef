#pragma once
// The shape of the tile pyramid for a DEM (docs/terrainlod.md §1): number of levels, tiles
// per level and the per-level error budget eps_l = f * S_l / T (one texel by default).

#include <vector>

namespace fest::terrainlod {

struct PyramidParams {
  int tile = 64;          // B: leaf tile size in DEM cells, a power of two in [4, 4096]
  int texels = 0;         // T: texels per tile side, a power of two >= B (0 = B)
  double error_fraction = 1.0;  // f: allowed error in texels
};

struct LevelPlan {
  int level = 0;
  int tiles_x = 0, tiles_y = 0;  // tiles that cover the DEM (not the padding)
  double side_x = 0, side_y = 0; // tile side S_l in world units
  double eps = 0;                // eps_l (0 at the leaves)
  double bound = 0;              // (4/3) eps_l: guaranteed error against the DEM
};

struct PyramidPlan {
  int levels = 0;       // L (leaves are level L)
  int padded = 0;       // 2^L B + 1 samples per side after padding
  std::vector<LevelPlan> level;
};

// Checks the parameters (usage_error naming the bad parameter) and lays out the levels
// for a W x H-sample DEM with cell sizes dx, dy. eps_l uses the smaller tile side, so the
// budget holds along both axes when dx != dy.
PyramidPlan plan_pyramid(int width, int height, double dx, double dy, const PyramidParams& params);

bool is_power_of_two(int n);

}  // namespace fest::terrainlod
