#include "terrainlod/height_grid.hpp"

#include <cmath>
#include <deque>

#include "core/error.hpp"

namespace fest::terrainlod {

ConditionReport condition_grid(HeightGrid& grid) {
  if (grid.width < 2 || grid.height < 2)
    throw bad_input("DEM has {} column{} and {} row{}; at least 2 x 2 samples needed", grid.width,
                    grid.width == 1 ? "" : "s", grid.height, grid.height == 1 ? "" : "s");
  if (grid.h.size() != grid.size())
    throw bad_input("DEM has {} heights for {} x {} samples", grid.h.size(), grid.width, grid.height);

  ConditionReport report;
  grid.valid.assign(grid.size(), 1);
  std::deque<std::size_t> frontier;  // valid samples first, then filled ones: a multi-source BFS
  bool first = true;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const double z = grid.h[k];
    if (std::isnan(z)) {
      grid.valid[k] = 0;
      ++report.nodata;
      continue;
    }
    if (!std::isfinite(z))
      throw bad_input("DEM height at column {}, row {} from the south is infinite", k % grid.width, k / grid.width);
    if (first || z < report.z_min) report.z_min = z;
    if (first || z > report.z_max) report.z_max = z;
    first = false;
    frontier.push_back(k);
  }
  if (frontier.empty()) throw bad_input("all samples are nodata");

  // Breadth-first from every valid sample at once: each nodata sample takes the height of
  // the sample that reached it first (a nearest valid one in 4-neighbour steps).
  std::vector<std::uint8_t> done(grid.valid);
  const int w = grid.width, hgt = grid.height;
  while (!frontier.empty()) {
    const std::size_t k = frontier.front();
    frontier.pop_front();
    const int i = static_cast<int>(k % w), j = static_cast<int>(k / w);
    const int ni[4] = {i - 1, i + 1, i, i};
    const int nj[4] = {j, j, j - 1, j + 1};
    for (int n = 0; n < 4; ++n) {
      if (ni[n] < 0 || ni[n] >= w || nj[n] < 0 || nj[n] >= hgt) continue;
      const std::size_t m = static_cast<std::size_t>(nj[n]) * w + ni[n];
      if (done[m]) continue;
      done[m] = 1;
      grid.h[m] = grid.h[k];
      frontier.push_back(m);
    }
  }
  return report;
}

}  // namespace fest::terrainlod
