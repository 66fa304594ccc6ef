#pragma once
// VTK datasets: XML .vtu/.vti/.vtp/.vts and legacy .vtk, read into fest::Dataset and
// written from it. The parsing and writing is VTK's, inside fest's VTK plugin
// (libfest_vtk_plugin.so), which is opened on the first call: a tool that never reads or
// writes a dataset never maps VTK.

#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "core/dataset.hpp"
#include "formats/detect.hpp"

namespace fest::formats {

struct DatasetWriteOptions {
  bool ascii = false;  // legacy: ASCII instead of BINARY; XML: ascii data arrays
  bool zlib = false;   // .vti: zlib-compressed appended data (lbmsim's default)
};

// Throws fest::Error(Status::bad_input) for malformed input; VTK's own error output is
// captured and becomes the message. Throws Status::io when VTK cannot be loaded.
Dataset read_dataset(std::string_view bytes, Format format);
// Throws Status::bad_input when the dataset type does not fit the format (a vtu
// written as .vti).
std::string write_dataset(const Dataset& dataset, Format format, const DatasetWriteOptions& options = {});
nlohmann::json describe_dataset(const Dataset& dataset);

}  // namespace fest::formats
