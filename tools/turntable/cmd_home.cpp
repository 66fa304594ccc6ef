// turntable home: run to the home switch and wait, within a timeout.

#include <fmt/format.h>

#include "capture/ttp1.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int home_command(const DeviceOptions& d, const HomeOptions& o) {
  const OpenTurntable t(d);
  if (!(o.timeout_s > 0)) throw usage_error("--timeout must be positive");
  const capture::TurntableInfo info = t->info();
  t->home(o.clockwise, speed_steps(o.speed_deg_s, info.steps_per_rev));
  const unsigned poll_ms = 20;
  for (double waited = 0;; waited += poll_ms) {
    const capture::TurntableStatus s = t->status();
    if (s.state == capture::MotionState::fault)
      throw make_error(Status::device_error, "turntable fault {} ({}) while homing", s.fault, capture::ttp1::fault_name(s.fault));
    if (s.state == capture::MotionState::idle && s.homed) {
      print(d, status_json(s, info.steps_per_rev), fmt::format("homed at step {}\n", s.position));
      return 0;
    }
    if (waited >= o.timeout_s * 1000) {
      t->stop(true);
      throw make_error(Status::timeout, "turntable did not find home within {} s", o.timeout_s);
    }
    t->wait_ms(poll_ms);
  }
}

}  // namespace fest::turntable_tool
