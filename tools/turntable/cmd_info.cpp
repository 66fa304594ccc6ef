// turntable info: what the device is (name, serial, steps per revolution, limits).

#include <fmt/format.h>

#include "capture/ttp1.hpp"
#include "commands.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int info_command(const DeviceOptions& d) {
  const OpenTurntable t(d);
  const capture::TurntableInfo i = t->info();
  const nlohmann::json j = {{"name", i.name},           {"serial", i.serial},       {"steps_per_rev", i.steps_per_rev},
                            {"max_speed", i.max_speed}, {"max_accel", i.max_accel}, {"has_home", i.has_home}};
  print(d, j,
        fmt::format("name: {}\nserial: {}\nsteps per revolution: {}\nmax speed: {} steps/s\nmax acceleration: {} steps/s^2\n"
                    "home switch: {}\n",
                    i.name, i.serial.empty() ? "-" : i.serial, i.steps_per_rev, i.max_speed, i.max_accel,
                    i.has_home ? "yes" : "no"));
  return 0;
}

}  // namespace fest::turntable_tool
