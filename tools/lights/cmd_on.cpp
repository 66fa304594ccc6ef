// lights on: these lights on, left on after release (docs/lights.md §2: the line keeps its level).

#include "commands.hpp"
#include "devices/open_devices.hpp"
#include "station.hpp"

namespace fest::lights_tool {

int on_command(const StationOptions& s, const std::vector<std::string>& ids) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  auto bank = devices::open_lights(select(lights, ids), ids);
  bank->keep_state_on_release();
  return 0;
}

}  // namespace fest::lights_tool
