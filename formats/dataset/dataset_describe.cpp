// describe_dataset: what a person (or a test) wants to know about a dataset without
// opening ParaView: its type, sizes, bounding box, grid geometry and arrays. The
// figures are those VTK's vtkDataSet::GetBounds and vtkDataArray::GetRange give.

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/dataset/dataset_io.hpp"

namespace fest::formats {
namespace {

nlohmann::json triple(const std::array<double, 3>& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

// vtkDataArray::GetRange: NaN values are skipped; for several components the range
// of the squared Euclidean norm, square-rooted at the end.
std::array<double, 2> range_of(const DataArray& a, bool magnitude) {
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  const std::size_t tuples = a.tuples();
  for (std::size_t t = 0; t < tuples; ++t) {
    double v = 0;
    if (magnitude) {
      for (int c = 0; c < a.components; ++c) {
        const double x = a.component(t, c);
        v += x * x;
      }
    } else {
      v = a.component(t, 0);
    }
    if (std::isnan(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (magnitude && lo <= hi) return {std::sqrt(lo), std::sqrt(hi)};
  return {lo, hi};
}

// One entry per array. "range" is over the values for one-component arrays and over
// the tuple magnitudes (Euclidean norm) for vectors and tensors; "range_of" says which.
nlohmann::json describe_arrays(const std::vector<DataArray>& arrays) {
  nlohmann::json out = nlohmann::json::array();
  for (const DataArray& array : arrays) {
    nlohmann::json entry;
    entry["name"] = array.name;
    entry["components"] = array.components;
    entry["tuples"] = array.tuples();
    entry["type"] = array.type_name();
    if (array.numeric() && array.tuples() > 0) {
      const bool magnitude = array.components > 1;
      const auto range = range_of(array, magnitude);
      entry["range"] = {range[0], range[1]};
      entry["range_of"] = magnitude ? "magnitude" : "values";
    }
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace

nlohmann::json describe_dataset(const Dataset& dataset) {
  nlohmann::json d;
  d["dataset_type"] = dataset.class_name();
  d["points"] = dataset.point_count();
  d["cells"] = dataset.cell_count();
  if (dataset.point_count() > 0) {
    const auto b = dataset.bounds();
    d["bbox"] = {{"min", {b[0], b[2], b[4]}}, {"max", {b[1], b[3], b[5]}}};
  }
  if (dataset.kind == DatasetKind::image) {
    const auto dims = dataset.dimensions();
    d["dimensions"] = {dims[0], dims[1], dims[2]};
    d["spacing"] = triple(dataset.spacing);
    d["origin"] = triple(dataset.origin);
  }
  d["point_arrays"] = describe_arrays(dataset.point_data);
  d["cell_arrays"] = describe_arrays(dataset.cell_data);
  return d;
}

}  // namespace fest::formats
