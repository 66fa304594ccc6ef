// lights only: this light on and every other light of the station off, left so (docs/lights.md §2).

#include "commands.hpp"
#include "devices/open_devices.hpp"
#include "station.hpp"

namespace fest::lights_tool {

int only_command(const StationOptions& s, const std::string& id) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  select(lights, {id});  // the id must exist
  auto bank = devices::open_lights(lights, {id});
  bank->keep_state_on_release();
  return 0;
}

}  // namespace fest::lights_tool
