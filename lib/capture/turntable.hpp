#pragma once
// The turntable abstraction every backend implements (docs/capture.md §4), and the
// host's motion policy on top of it (docs/turntable.md §1-2): angles in degrees become integer motor
// steps, absolute targets are always approached from the same side to cancel gear
// backlash, moves are polled until idle or time out.

#include <cstdint>
#include <string>

namespace fest::capture {

struct TurntableInfo {
  std::uint32_t steps_per_rev = 0;  // motor full steps x microsteps x gear ratio
  std::uint32_t max_speed = 0;      // steps/s
  bool has_home = false;
  std::string name;
  std::uint32_t max_accel = 0;      // steps/s^2; 0 = not reported
  std::string serial;               // USB iSerialNumber; empty for backends without one
};

enum class MotionState { idle, moving, homing, fault };

struct TurntableStatus {
  std::int32_t position = 0, target = 0;
  MotionState state = MotionState::idle;
  bool homed = false;
  std::uint16_t fault = 0;
  bool home_switch = false, stalled = false, driver_enabled = true;
  std::uint32_t seq = 0;  // incremented by the device when a move completes
};

// Backends throw fest::Error with the device exit statuses (README "Conventions"): device_not_found (5)
// when the device is gone, device_error (6), timeout (7), permission (8).
class Turntable {
 public:
  virtual ~Turntable() = default;
  virtual TurntableInfo info() = 0;
  virtual TurntableStatus status() = 0;
  virtual void move_abs(std::int32_t target, std::uint32_t speed_steps_s) = 0;
  virtual void stop(bool immediate) = 0;
  // Start a homing run towards the home switch (returns at once; poll status() until
  // idle and homed). Backends without a switch throw device_error.
  virtual void home(bool clockwise, std::uint32_t speed_steps_s);
  // Declare the current position step 0 (the homed flag is unchanged).
  virtual void set_zero();
  // Switch the motor driver on or off (off: the table turns freely by hand).
  virtual void enable(bool on);
  // Host-side waiting: real backends sleep between polls, the simulator advances its
  // virtual clock instead, so tests run in no time.
  virtual void wait_ms(unsigned ms) = 0;
};

// steps = round(deg / 360 * S_rev); the angle actually reached is steps * 360 / S_rev.
std::int32_t steps_for_angle(double degrees, std::uint32_t steps_per_rev);
double angle_for_steps(std::int32_t steps, std::uint32_t steps_per_rev);

enum class Approach { ccw, cw };

struct MotionPolicy {
  Approach approach = Approach::ccw;  // the final leg always runs in this direction
  double backlash_deg = 2.0;          // overshoot before coming back; 0 = never
  std::uint32_t speed = 0;            // steps/s; 0 = the device's maximum
  unsigned poll_ms = 20;
  double extra_timeout_s = 2.0;       // timeout = distance / speed + this
};

struct MoveResult {
  double angle_cmd_deg = 0, angle_deg = 0;
  std::int32_t steps = 0;
  bool overshoot = false;  // the move went past the target first
};

// Moves to an absolute angle under the policy. Throws timeout (7) when a leg does not
// reach its target in time, device_error (6) with the fault when the device reports one.
MoveResult move_to_angle(Turntable& table, double degrees, const MotionPolicy& policy = {});

}  // namespace fest::capture
