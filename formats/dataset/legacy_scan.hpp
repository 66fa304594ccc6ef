#pragma once
// A walk over a legacy .vtk file that checks its structure before VTK reads it.
//
// vtkDataReader trusts the counts in the file: it allocates "POINTS 1000000000000
// float" before reading a single value, and copies legacy cell lists into buffers
// sized by the declared total without checking the per-cell counts. So this walk
// follows the same grammar, checks every count against the bytes that remain, and
// checks that cell lists add up, before VTK sees the bytes.

#include <string>
#include <string_view>

namespace fest::formats::detail {

struct LegacyHeader {
  int major_version = 0;
  int minor_version = 0;
  bool binary = false;
  std::string dataset_type;  // lower case: "unstructured_grid", "polydata", ...
  int dimensions[3] = {0, 0, 0};  // from DIMENSIONS, for the three grid types
};

// Throws bad_input naming the section and the byte offset where the file goes wrong.
LegacyHeader scan_legacy_vtk(std::string_view bytes);

}  // namespace fest::formats::detail
