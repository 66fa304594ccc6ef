// lights off: these lights (or --all) off, left off after release (docs/lights.md §2).

#include "commands.hpp"
#include "core/error.hpp"
#include "devices/open_devices.hpp"
#include "station.hpp"

namespace fest::lights_tool {

int off_command(const StationOptions& s, const OffOptions& o) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  if (o.all == !o.ids.empty()) throw usage_error("off needs light ids or --all (not both)");
  auto bank = devices::open_lights(o.all ? lights : select(lights, o.ids));  // requested off
  bank->keep_state_on_release();
  return 0;
}

}  // namespace fest::lights_tool
