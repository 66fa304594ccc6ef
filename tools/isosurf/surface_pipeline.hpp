#pragma once
// The pipeline isosurf exact and adaptive share (docs/isosurf.md sections 2-5).

#include "commands.hpp"

namespace fest::isosurf_tool {

// Reads the volume, extracts the surface (full resolution, or adaptive when `adaptive` is
// given), post-processes and writes it and the report. Returns the exit status.
int extract_surface(const ExactOptions& options, const AdaptiveArgs* adaptive);

}  // namespace fest::isosurf_tool
