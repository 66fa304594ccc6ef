#include "device.hpp"

#include <cmath>
#include <cstdio>
#include <exception>

#include "capture/ttp1.hpp"
#include "core/error.hpp"
#include "core/tool_main.hpp"
#include "devices/gpio_stepper.hpp"
#include "devices/open_devices.hpp"
#include "devices/station_lights.hpp"

namespace fest::turntable_tool {

std::string device_uri(const DeviceOptions& d) {
  if (!d.device.empty()) return d.device;
  const std::string station = devices::station_path(d.station);
  if (!station.empty()) {
    const nlohmann::json s = devices::read_station(station);
    const auto t = s.find("turntable");
    if (t != s.end() && t->is_object() && t->contains("uri")) {
      if (!(*t)["uri"].is_string()) throw bad_input("turntable.uri must be a string ({}: /turntable/uri)", station);
      return (*t)["uri"].get<std::string>();
    }
  }
  return "usb:";
}

OpenTurntable::OpenTurntable(const DeviceOptions& d) : t_(devices::open_turntable(device_uri(d))), quiet_(d.quiet) {}

OpenTurntable::~OpenTurntable() {
  // A host-generated step train without real-time priority may jitter (docs/turntable.md §3).
  if (auto* g = dynamic_cast<devices::GpioStepper*>(t_.get()); g && !g->realtime() && !quiet_ && std::uncaught_exceptions() == 0)
    fest::warn("turntable", "SCHED_FIFO not permitted: step timing may jitter (grant CAP_SYS_NICE or an rtprio limit)");
}

void print(const DeviceOptions& d, const nlohmann::json& j, const std::string& text) {
  const std::string s = d.json ? j.dump() + "\n" : text;
  std::fwrite(s.data(), 1, s.size(), stdout);
}

const char* state_name(capture::MotionState s) {
  switch (s) {
    case capture::MotionState::idle: return "idle";
    case capture::MotionState::moving: return "moving";
    case capture::MotionState::homing: return "homing";
    case capture::MotionState::fault: return "fault";
  }
  return "?";
}

nlohmann::json status_json(const capture::TurntableStatus& s, std::uint32_t spr) {
  return {{"position_steps", s.position},
          {"target_steps", s.target},
          {"angle_deg", capture::angle_for_steps(s.position, spr)},
          {"state", state_name(s.state)},
          {"homed", s.homed},
          {"home_switch", s.home_switch},
          {"stalled", s.stalled},
          {"driver_enabled", s.driver_enabled},
          {"fault", s.fault},
          {"fault_name", capture::ttp1::fault_name(s.fault)},
          {"seq", s.seq}};
}

std::uint32_t speed_steps(double deg_s, std::uint32_t spr) {
  if (!(deg_s >= 0) || !std::isfinite(deg_s)) throw usage_error("--speed must be a non-negative number of deg/s");
  return std::uint32_t(std::lround(deg_s / 360.0 * spr));
}

}  // namespace fest::turntable_tool
