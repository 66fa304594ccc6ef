#pragma once
// The station's lights, and a selection of them by id.

#include <string>
#include <vector>

#include "commands.hpp"
#include "devices/station_lights.hpp"

namespace fest::lights_tool {

// The lights of --station (else $CAPTURE_STATION); usage_error when neither names one.
std::vector<devices::LightConfig> station_lights(const StationOptions& s);

// The station's lights named in ids, in the order given; usage_error for an unknown id.
std::vector<devices::LightConfig> select(const std::vector<devices::LightConfig>& all, const std::vector<std::string>& ids);

}  // namespace fest::lights_tool
