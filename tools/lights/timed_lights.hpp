#pragma once
// Lights lit for a while (lights pulse and hold): see timed_lights.cpp.

#include <string>
#include <vector>

#include "commands.hpp"

namespace fest::lights_tool {

// The lights `ids` on for `seconds` (until a stop signal when negative), then all off.
int lit_for(const StationOptions& s, const std::vector<std::string>& ids, double seconds);

}  // namespace fest::lights_tool
