// lights on / off / only: one-shot commands that leave the lights as switched
// (docs/lights.md §2: the line keeps its level after release).

#include "commands.hpp"
#include "core/error.hpp"
#include "devices/open_devices.hpp"
#include "station.hpp"

namespace fest::lights_tool {

int on_command(const StationOptions& s, const std::vector<std::string>& ids) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  auto bank = devices::open_lights(select(lights, ids), ids);
  bank->keep_state_on_release();
  return 0;
}

int off_command(const StationOptions& s, const OffOptions& o) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  if (o.all == !o.ids.empty()) throw usage_error("off needs light ids or --all (not both)");
  auto bank = devices::open_lights(o.all ? lights : select(lights, o.ids));  // requested off
  bank->keep_state_on_release();
  return 0;
}

int only_command(const StationOptions& s, const std::string& id) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  select(lights, {id});  // the id must exist
  auto bank = devices::open_lights(lights, {id});
  bank->keep_state_on_release();
  return 0;
}

}  // namespace fest::lights_tool
