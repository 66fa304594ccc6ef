#pragma once
// Datasets compared as data: counts, cell types and connectivity, point coordinates,
// and every point and cell array matched by name.

#include <cstddef>
#include <map>
#include <string>

#include "core/dataset.hpp"

namespace fest::compare {

struct DatasetDifference {
  std::size_t points_a = 0, points_b = 0;
  std::size_t cells_a = 0, cells_b = 0;
  std::size_t cell_diffs = 0;      // cells whose type or point ids differ (same index)
  double point_max_abs = 0;        // largest coordinate difference (same index)
  std::size_t missing_arrays = 0;  // arrays in one dataset only, or of other shape
  std::map<std::string, double> array_max_abs;  // "point:velocity", "cell:tet_id"
  double array_max_abs_all = 0;
};

DatasetDifference dataset_difference(const Dataset& a, const Dataset& b);

}  // namespace fest::compare
