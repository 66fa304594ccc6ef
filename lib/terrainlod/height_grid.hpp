#pragma once
// The DEM as the algorithms see it: W x H samples on a regular grid, counted from the
// south-west (i east, j north), with the validity of every sample. NaN marks nodata on
// input; condition_grid() replaces it by the nearest valid height (geometry needs a value
// everywhere, docs/terrainlod.md §1) and keeps the mask.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fest::terrainlod {

struct HeightGrid {
  int width = 0;   // samples east-west (columns)
  int height = 0;  // samples north-south (rows)
  std::vector<double> h;        // h[j * width + i], j = 0 is the southern row
  std::vector<std::uint8_t> valid;  // 1 = measured, 0 = nodata (filled); empty = all valid

  double at(int i, int j) const { return h[static_cast<std::size_t>(j) * width + i]; }
  std::size_t size() const { return static_cast<std::size_t>(width) * height; }
};

struct ConditionReport {
  std::size_t nodata = 0;   // samples that were NaN (filled)
  double z_min = 0;         // over valid samples
  double z_max = 0;
};

// Checks the grid (at least 2 x 2 samples, at least one valid sample, no infinities) and
// fills every NaN with the height of the nearest valid sample (breadth-first over the
// 4-neighbourhood, ties broken by scan order, so the result is deterministic). Throws
// bad_input with the reason; `where` names the input in messages.
ConditionReport condition_grid(HeightGrid& grid);

}  // namespace fest::terrainlod
