#pragma once
// VTK datasets: XML .vtu/.vti/.vtp/.vts and legacy .vtk. Only code that includes this header
// pays for VTK (a forward declaration keeps vtkDataSet.h out).

#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>
#include <vtkSmartPointer.h>

#include "formats/detect.hpp"

class vtkDataSet;

namespace fest::formats {

struct DatasetWriteOptions {
  bool ascii = false;  // legacy: ASCII instead of BINARY; XML: ascii data arrays
  bool zlib = false;   // .vti: zlib-compressed appended data (lbmsim's default)
};

// Throws fest::Error(Status::bad_input) for malformed input; VTK's own error output is
// captured and becomes the message.
vtkSmartPointer<vtkDataSet> read_dataset(std::string_view bytes, Format format);
// Throws Status::bad_input when the dataset type does not fit the format (a vtu
// written as .vti).
std::string write_dataset(vtkDataSet* dataset, Format format, const DatasetWriteOptions& options = {});
nlohmann::json describe_dataset(vtkDataSet* dataset);

}  // namespace fest::formats
