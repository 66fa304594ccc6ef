// turntable status: where the device stands (position, target, state, homed, fault).

#include <fmt/format.h>

#include "capture/ttp1.hpp"
#include "commands.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int status_command(const DeviceOptions& d) {
  const OpenTurntable t(d);
  const std::uint32_t spr = t->info().steps_per_rev;
  const capture::TurntableStatus s = t->status();
  print(d, status_json(s, spr),
        fmt::format("position: {} steps ({:.4f} deg)\ntarget: {} steps\nstate: {}\nhomed: {}\nfault: {} ({})\n", s.position,
                    capture::angle_for_steps(s.position, spr), s.target, state_name(s.state), s.homed ? "yes" : "no",
                    s.fault, capture::ttp1::fault_name(s.fault)));
  return 0;
}

}  // namespace fest::turntable_tool
