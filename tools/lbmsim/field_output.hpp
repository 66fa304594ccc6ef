#pragma once
// Writing lbmsim's fields: VTK XML ImageData (.vti) with a ParaView series (.pvd), one
// NRRD per field, or a frame of fest's frame stream (fest-frame(5), as fluidsim writes).

#include <string>
#include <utility>
#include <vector>

#include "lbm/fields.hpp"

namespace fest::lbmsim_tool {

struct FieldFrame {
  long index = 0;     // output frame number (the step)
  double time = 0.0;
  int dim = 2;
  std::array<int, 3> size{1, 1, 1};
  double spacing = 1.0;
  std::vector<lbm::Field> fields;
};

std::string encode_vti(const FieldFrame& f, bool float64, bool zlib);
// One file per field: {stem}_{field}.nrrd -> bytes.
std::vector<std::pair<std::string, std::string>> encode_nrrd(const FieldFrame& f, const std::string& path, bool float64);
std::string encode_stream_frame(const FieldFrame& f, bool float64);
// ParaView collection of (time, file name) pairs.
std::string encode_pvd(const std::vector<std::pair<double, std::string>>& entries);

// Output names from a pattern with one printf-style integer conversion (%d, %05d).
bool has_index_conversion(const std::string& pattern);
std::string expand_pattern(const std::string& pattern, long index);

}  // namespace fest::lbmsim_tool
