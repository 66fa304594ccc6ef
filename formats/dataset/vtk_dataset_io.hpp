#pragma once
// VTK's readers and writers for the dataset formats, guarded: the code inside the VTK
// plugin (vtk_plugin.cpp) that dataset_io.hpp's functions reach through dlopen.

#include <string>
#include <string_view>

#include <vtkSmartPointer.h>

#include "formats/dataset/dataset_io.hpp"

class vtkDataSet;

namespace fest::formats::detail {

// Throws fest::Error(Status::bad_input) for malformed input; VTK's own error output is
// captured and becomes the message.
vtkSmartPointer<vtkDataSet> read_vtk_dataset(std::string_view bytes, Format format);
// Throws Status::bad_input when the dataset type does not fit the format (a vtu
// written as .vti).
std::string write_vtk_dataset(vtkDataSet* dataset, Format format, const DatasetWriteOptions& options);

}  // namespace fest::formats::detail
