// describe_dataset: what a person (or a test) wants to know about a dataset without
// opening ParaView: its type, sizes, bounding box, grid geometry and arrays.

#include <nlohmann/json.hpp>
#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include "formats/dataset/dataset_io.hpp"
#include "formats/dataset/vtk_messages.hpp"
#include "lib/core/error.hpp"

namespace fest::formats {
namespace {

nlohmann::json triple(const double v[3]) { return nlohmann::json::array({v[0], v[1], v[2]}); }

// One entry per array. "range" is over the values for one-component arrays and over
// the tuple magnitudes (Euclidean norm) for vectors and tensors; "range_of" says which.
nlohmann::json describe_arrays(vtkDataSetAttributes* data) {
  nlohmann::json arrays = nlohmann::json::array();
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    if (array == nullptr) continue;
    nlohmann::json entry;
    entry["name"] = array->GetName() ? array->GetName() : "";
    entry["components"] = array->GetNumberOfComponents();
    entry["tuples"] = array->GetNumberOfTuples();
    entry["type"] = array->GetDataTypeAsString();
    auto* numeric = vtkDataArray::SafeDownCast(array);
    if (numeric != nullptr && numeric->GetNumberOfTuples() > 0) {
      bool magnitude = numeric->GetNumberOfComponents() > 1;
      double range[2];
      numeric->GetRange(range, magnitude ? -1 : 0);
      entry["range"] = {range[0], range[1]};
      entry["range_of"] = magnitude ? "magnitude" : "values";
    }
    arrays.push_back(std::move(entry));
  }
  return arrays;
}

}  // namespace

nlohmann::json describe_dataset(vtkDataSet* dataset) {
  if (dataset == nullptr) throw bad_input("no dataset to describe");
  // Range and bounds computations may report problems too; keep them off the console.
  auto messages = vtkSmartPointer<detail::MessageCollector>::New();
  detail::MessageCapture capture(messages);

  nlohmann::json d;
  d["dataset_type"] = dataset->GetClassName();
  d["points"] = dataset->GetNumberOfPoints();
  d["cells"] = dataset->GetNumberOfCells();
  if (dataset->GetNumberOfPoints() > 0) {
    double b[6];
    dataset->GetBounds(b);
    d["bbox"] = {{"min", {b[0], b[2], b[4]}}, {"max", {b[1], b[3], b[5]}}};
  }
  if (auto* image = vtkImageData::SafeDownCast(dataset)) {
    int dims[3];
    image->GetDimensions(dims);
    d["dimensions"] = {dims[0], dims[1], dims[2]};
    d["spacing"] = triple(image->GetSpacing());
    d["origin"] = triple(image->GetOrigin());
  }
  d["point_arrays"] = describe_arrays(dataset->GetPointData());
  d["cell_arrays"] = describe_arrays(dataset->GetCellData());
  return d;
}

}  // namespace fest::formats
