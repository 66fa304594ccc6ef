#include "capture/turntable.hpp"

#include <cmath>
#include <cstdlib>

#include "core/error.hpp"

namespace fest::capture {
namespace {

void run_leg(Turntable& table, std::int32_t target, std::uint32_t speed, const MotionPolicy& policy) {
  const TurntableStatus start = table.status();
  table.move_abs(target, speed);
  const double distance = std::fabs(double(target) - double(start.position));
  const double limit_ms = 1000.0 * (distance / double(speed) + policy.extra_timeout_s);
  for (double waited = 0;; waited += policy.poll_ms) {
    const TurntableStatus s = table.status();
    if (s.state == MotionState::fault)
      throw make_error(Status::device_error, "turntable fault {} while moving to step {}", s.fault, target);
    if (s.state == MotionState::idle && s.position == target) return;
    if (waited >= limit_ms) {
      table.stop(true);
      throw make_error(Status::timeout, "turntable did not reach step {} within {:.1f} s (at step {})", target,
                       limit_ms / 1000, s.position);
    }
    table.wait_ms(policy.poll_ms);
  }
}

}  // namespace

void Turntable::home(bool, std::uint32_t) {
  throw make_error(Status::device_error, "this turntable has no home switch");
}
void Turntable::set_zero() { throw make_error(Status::device_error, "this turntable cannot set its zero"); }
void Turntable::enable(bool) { throw make_error(Status::device_error, "this turntable has no driver enable"); }

std::int32_t steps_for_angle(double degrees, std::uint32_t steps_per_rev) {
  if (steps_per_rev == 0) throw make_error(Status::device_error, "turntable reports 0 steps per revolution");
  const double steps = std::round(degrees / 360.0 * double(steps_per_rev));
  if (!(std::fabs(steps) < 2147483647.0)) throw usage_error("angle {} deg is out of range", degrees);
  return std::int32_t(steps);
}

double angle_for_steps(std::int32_t steps, std::uint32_t steps_per_rev) {
  return double(steps) * 360.0 / double(steps_per_rev);
}

MoveResult move_to_angle(Turntable& table, double degrees, const MotionPolicy& policy) {
  if (!std::isfinite(degrees)) throw usage_error("angle must be finite");
  if (!(policy.backlash_deg >= 0)) throw usage_error("backlash must not be negative");
  const TurntableInfo info = table.info();
  const std::uint32_t speed = policy.speed ? policy.speed : info.max_speed;
  if (speed == 0) throw make_error(Status::device_error, "turntable reports a maximum speed of 0");
  MoveResult r;
  r.angle_cmd_deg = degrees;
  r.steps = steps_for_angle(degrees, info.steps_per_rev);
  const std::int32_t here = table.status().position;
  // Counter-clockwise = increasing steps: a ccw approach must end moving up, so a target
  // below (or at) the current position is first passed by the backlash margin.
  const std::int32_t margin = steps_for_angle(policy.backlash_deg, info.steps_per_rev);
  const int sign = policy.approach == Approach::ccw ? 1 : -1;
  const bool wrong_side = sign * (r.steps - here) <= 0 && r.steps != here;
  if (margin > 0 && wrong_side) {
    r.overshoot = true;
    run_leg(table, r.steps - sign * margin, speed, policy);
  }
  if (r.steps != table.status().position || table.status().state != MotionState::idle)
    run_leg(table, r.steps, speed, policy);
  r.angle_deg = angle_for_steps(r.steps, info.steps_per_rev);
  return r;
}

}  // namespace fest::capture
