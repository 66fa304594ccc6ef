#include "station.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fest::lights_tool {

using devices::LightConfig;

std::vector<LightConfig> station_lights(const StationOptions& s) {
  const std::string path = devices::station_path(s.station);
  if (path.empty()) throw usage_error("no station: give --station station.json or set CAPTURE_STATION");
  return devices::lights_from_station(devices::read_station(path), path);
}

std::vector<LightConfig> select(const std::vector<LightConfig>& all, const std::vector<std::string>& ids) {
  std::vector<LightConfig> out;
  for (const std::string& id : ids) {
    auto it = std::find_if(all.begin(), all.end(), [&](const LightConfig& l) { return l.id == id; });
    if (it == all.end()) throw usage_error("no light '{}' in the station", id);
    if (std::none_of(out.begin(), out.end(), [&](const LightConfig& l) { return l.id == id; })) out.push_back(*it);
  }
  return out;
}

}  // namespace fest::lights_tool
