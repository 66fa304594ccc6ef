#pragma once
// The "lights" array of a station.json (fest-capture(5)):
//   "lights": [ {"id": "L0", "uri": "gpio:chip=gpiochip0,line=GPIO17", "active_low": false,
//                "position_mm": [...], "intensity": [...], "warmup_ms": 300, "max_on_s": 120,
//                "role": "backlight"}, ... ]
// Only id, uri and active_low matter to the backends; the other known keys belong to
// capture and are accepted; an unknown key is an error (a typo must not pass silently).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "devices/open_devices.hpp"

namespace fest::devices {

// --station FILE, else $CAPTURE_STATION, else "" (no station).
std::string station_path(const std::string& flag);

// Reads and parses a station.json ("-" = standard input); bad_input with the line on a
// parse error, io_error when it cannot be read.
nlohmann::json read_station(const std::string& path);

// bad_input naming `where` (the file) and the JSON path of the offending value.
std::vector<LightConfig> lights_from_station(const nlohmann::json& station, const std::string& where);

}  // namespace fest::devices
