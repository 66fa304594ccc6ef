#include "terrainlod/pyramid_plan.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::terrainlod {

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

PyramidPlan plan_pyramid(int width, int height, double dx, double dy, const PyramidParams& params) {
  if (!is_power_of_two(params.tile) || params.tile < 4 || params.tile > 4096)
    throw usage_error("tile size {} is not a power of two between 4 and 4096", params.tile);
  const int texels = params.texels == 0 ? params.tile : params.texels;
  if (!is_power_of_two(texels) || texels > 65536)
    throw usage_error("texels per tile side {} is not a power of two up to 65536", texels);
  if (texels < params.tile) throw usage_error("texels per tile side ({}) are fewer than the tile's cells ({})", texels, params.tile);
  if (!(params.error_fraction > 0) || !std::isfinite(params.error_fraction))
    throw usage_error("error fraction must be a positive number (got {})", params.error_fraction);
  if (width < 2 || height < 2) throw bad_input("DEM has {} x {} samples; at least 2 x 2 needed", width, height);

  PyramidPlan plan;
  const int cells = std::max(width, height) - 1;
  while ((static_cast<long long>(params.tile) << plan.levels) < cells) ++plan.levels;
  plan.padded = (params.tile << plan.levels) + 1;
  for (int l = 0; l <= plan.levels; ++l) {
    LevelPlan lp;
    lp.level = l;
    const int cells_per_tile = params.tile << (plan.levels - l);
    lp.tiles_x = (width - 1 + cells_per_tile - 1) / cells_per_tile;
    lp.tiles_y = (height - 1 + cells_per_tile - 1) / cells_per_tile;
    lp.side_x = cells_per_tile * dx;
    lp.side_y = cells_per_tile * dy;
    lp.eps = l == plan.levels ? 0.0 : params.error_fraction * std::min(lp.side_x, lp.side_y) / texels;
    lp.bound = lp.eps * 4.0 / 3.0;
    plan.level.push_back(lp);
  }
  return plan;
}

}  // namespace fest::terrainlod
