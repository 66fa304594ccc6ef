#pragma once
// Input volume -> float grid for isosurf: reading (formats/), NaN policy, --label,
// --cap padding, --index-space.

#include <string>

#include "commands.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::isosurf_tool {

struct LoadedGrid {
  volume_pyramid::ScalarGrid grid;
  float iso = 0;
  float data_min = 0, data_max = 0;
  std::string source;   // input name for messages and the report
};

// Throws bad_input for empty/unreadable input, dims < 2, NaN samples without
// --nan-outside; usage for a missing --iso/--label.
LoadedGrid load_grid(const ExactOptions& o);

}  // namespace fest::isosurf_tool
