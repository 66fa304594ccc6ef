#pragma once
// The dataset tests build and check their samples with VTK; these adapters run them
// through fest's dataset I/O (and so through the VTK plugin) as VTK objects.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>
#include <vtkDataSet.h>
#include <vtkSmartPointer.h>

#include "formats/dataset/dataset_io.hpp"
#include "formats/dataset/vtk_convert.hpp"
#include "lib/core/error.hpp"

namespace fest::formats {

inline vtkSmartPointer<vtkDataSet> read_vtk(std::string_view bytes, Format format) {
  return to_vtk(read_dataset(bytes, format));
}
inline std::string write_dataset(vtkDataSet* dataset, Format format, const DatasetWriteOptions& options = {}) {
  if (dataset == nullptr) throw bad_input("no dataset to write");
  return write_dataset(from_vtk(dataset), format, options);
}
inline nlohmann::json describe_dataset(vtkDataSet* dataset) {
  if (dataset == nullptr) throw bad_input("no dataset to describe");
  return describe_dataset(from_vtk(dataset));
}

}  // namespace fest::formats
