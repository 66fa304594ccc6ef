// fcompare on VTK datasets: counts, cells, points and arrays.

#include <cmath>

#include <nlohmann/json.hpp>

#include "compare/dataset_compare.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

using namespace fest::formats;
using fest::compare::Metrics;

void compare_datasets(const Input& ia, const Input& ib, const CompareOptions& opt, Metrics& m) {
  const auto [a, b] = parse_both(ia, ib, read_dataset);
  const auto d = compare::dataset_difference(a, b);
  m.set("point_count_diff", std::abs(static_cast<double>(d.points_a) - static_cast<double>(d.points_b)));
  m.set("cell_count_diff", std::abs(static_cast<double>(d.cells_a) - static_cast<double>(d.cells_b)));
  m.set("cell_diffs", static_cast<double>(d.cell_diffs));
  m.set("missing_arrays", static_cast<double>(d.missing_arrays));
  m.set("point_max_abs", d.point_max_abs);
  m.set("max_abs", d.array_max_abs_all);
  nlohmann::json arrays = nlohmann::json::object();
  for (const auto& [name, value] : d.array_max_abs) arrays[name] = compare::json_number(value);
  m.details["arrays"] = arrays;
  m.details["dataset_type"] = {a.class_name(), b.class_name()};
  for (const char* k : {"point_count_diff", "cell_count_diff", "cell_diffs", "missing_arrays"}) m.require(k, "<=", 0);
  require_main(m, "point_max_abs", opt);
  require_main(m, "max_abs", opt);
}

}  // namespace fest::fcompare_tool
