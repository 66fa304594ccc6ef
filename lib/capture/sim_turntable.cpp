#include "capture/sim_turntable.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "capture/device_uri.hpp"
#include "core/error.hpp"

namespace fest::capture {
namespace {

double number(const std::string& key, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v) || v < 0)
    throw usage_error("sim turntable: {}={} is not a non-negative number", key, text);
  return v;
}

}  // namespace

SimTurntableConfig parse_sim_turntable_uri(const std::string& uri) {
  if (uri.rfind("sim:", 0) != 0 && uri != "sim") throw usage_error("not a sim: device URI: {}", uri);
  SimTurntableConfig c;
  for (const DeviceOption& o : split_device_options(uri.size() > 4 ? uri.substr(4) : "")) {
    if (!o.has_value) throw usage_error("sim turntable: '{}' is not key=value", o.item);
    const std::string& key = o.key;
    const double v = number(key, o.value);
    if (key == "steps") c.steps_per_rev = std::uint32_t(v);
    else if (key == "speed") c.speed_deg_s = v;
    else if (key == "backlash") c.backlash_deg = v;
    else if (key == "fail_at") c.fail_at = int(v);
    else if (key == "unplug_at") c.unplug_at = int(v);
    else throw usage_error("sim turntable: unknown key '{}' (steps, speed, backlash, fail_at, unplug_at)", key);
  }
  if (c.steps_per_rev == 0 || c.speed_deg_s <= 0) throw usage_error("sim turntable: steps and speed must be positive");
  return c;
}

SimTurntable::SimTurntable(SimTurntableConfig config) : config_(config) {}

void SimTurntable::count_command() {
  ++commands_;
  if (config_.unplug_at > 0 && commands_ >= config_.unplug_at) unplugged_ = true;
  if (unplugged_) throw make_error(Status::device_not_found, "sim turntable: device unplugged (command {})", commands_);
}

TurntableInfo SimTurntable::info() {
  count_command();
  TurntableInfo i;
  i.steps_per_rev = config_.steps_per_rev;
  i.max_speed = std::uint32_t(std::lround(config_.speed_deg_s / 360.0 * config_.steps_per_rev));
  i.has_home = true;
  i.name = "fest sim turntable";
  return i;
}

TurntableStatus SimTurntable::status() {
  count_command();
  TurntableStatus s;
  s.position = std::int32_t(std::lround(motor_));
  s.target = target_;
  s.state = motor_ == double(target_) ? MotionState::idle : MotionState::moving;
  s.homed = true;
  s.home_switch = s.position == 0;
  s.driver_enabled = enabled_;
  return s;
}

void SimTurntable::move_abs(std::int32_t target, std::uint32_t speed_steps_s) {
  count_command();
  target_ = target;
  speed_ = speed_steps_s ? double(speed_steps_s) : config_.speed_deg_s / 360.0 * config_.steps_per_rev;
  // A move that never completes: the motor stalls where it is, the host must time out.
  stuck_ = ++moves_ == config_.fail_at && motor_ != double(target);
}

void SimTurntable::stop(bool) {
  count_command();
  target_ = std::int32_t(std::lround(motor_));
  motor_ = target_;
  stuck_ = false;
}

void SimTurntable::home(bool, std::uint32_t speed_steps_s) { move_abs(0, speed_steps_s); }

void SimTurntable::set_zero() {
  count_command();
  // Shift every coordinate so that the motor's current position becomes 0.
  const double shift = std::round(motor_);
  motor_ -= shift;
  table_ -= shift;
  target_ -= std::int32_t(shift);
}

void SimTurntable::enable(bool on) {
  count_command();
  enabled_ = on;
}

void SimTurntable::wait_ms(unsigned ms) {
  clock_s_ += ms / 1000.0;
  if (stuck_) return;
  const double before = motor_;
  const double step = speed_ * ms / 1000.0;
  motor_ = target_ > motor_ ? std::min(double(target_), motor_ + step) : std::max(double(target_), motor_ - step);
  // The motor's dog sits in a slot `play` wide: moving up it drags the table at
  // motor - play, moving down at motor; inside the slot the table does not move.
  const double play = config_.backlash_deg / 360.0 * config_.steps_per_rev;
  if (motor_ > before) table_ = std::max(table_, motor_ - play);
  if (motor_ < before) table_ = std::min(table_, motor_);
}

}  // namespace fest::capture
