#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "compare/dataset_compare.hpp"

namespace fest::compare {

namespace {

double value_difference(double x, double y) {
  if (std::isnan(x) || std::isnan(y))
    return (std::isnan(x) && std::isnan(y)) ? 0.0 : std::numeric_limits<double>::infinity();
  return x == y ? 0.0 : std::abs(x - y);
}

// Arrays are matched by name; string arrays and unnamed arrays are not numeric data
// and are left out, as VTK's vtkFieldData::GetArray(name) would.
const DataArray* numeric_named(const std::vector<DataArray>& arrays, const std::string& name) {
  for (const DataArray& a : arrays)
    if (a.numeric() && !a.name.empty() && a.name == name) return &a;
  return nullptr;
}

void compare_arrays(const std::vector<DataArray>& fa, const std::vector<DataArray>& fb, const std::string& prefix,
                    DatasetDifference& d) {
  for (const DataArray& a : fa) {
    if (!a.numeric() || a.name.empty()) continue;
    const DataArray* b = numeric_named(fb, a.name);
    if (b == nullptr || b->tuples() != a.tuples() || b->components != a.components) {
      ++d.missing_arrays;
      continue;
    }
    double worst = 0;
    for (std::size_t i = 0; i < a.value_count; ++i) worst = std::max(worst, value_difference(a.value(i), b->value(i)));
    d.array_max_abs[prefix + a.name] = worst;
    d.array_max_abs_all = std::max(d.array_max_abs_all, worst);
  }
  for (const DataArray& b : fb)
    if (b.numeric() && !b.name.empty() && numeric_named(fa, b.name) == nullptr) ++d.missing_arrays;
}

}  // namespace

DatasetDifference dataset_difference(const Dataset& a, const Dataset& b) {
  DatasetDifference d;
  d.points_a = a.point_count();
  d.points_b = b.point_count();
  d.cells_a = a.cell_count();
  d.cells_b = b.cell_count();
  const std::size_t points = std::min(d.points_a, d.points_b);
  for (std::size_t i = 0; i < points; ++i) {
    const auto pa = a.point(i), pb = b.point(i);
    for (int k = 0; k < 3; ++k) d.point_max_abs = std::max(d.point_max_abs, value_difference(pa[k], pb[k]));
  }
  const std::size_t cells = std::min(d.cells_a, d.cells_b);
  std::vector<int64_t> ia, ib;
  for (std::size_t i = 0; i < cells; ++i) {
    a.cell_points(i, ia);
    b.cell_points(i, ib);
    if (a.cell_type(i) != b.cell_type(i) || ia != ib) ++d.cell_diffs;
  }
  if (d.points_a == d.points_b) compare_arrays(a.point_data, b.point_data, "point:", d);
  if (d.cells_a == d.cells_b) compare_arrays(a.cell_data, b.cell_data, "cell:", d);
  return d;
}

}  // namespace fest::compare
