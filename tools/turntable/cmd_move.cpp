// turntable move: an angle reached from one side, the backlash-cancelling approach of
// docs/turntable.md §2 (lib/capture's move_to_angle), or a bare move with --no-wait.

#include <cmath>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "device.hpp"

namespace fest::turntable_tool {

int move_command(const DeviceOptions& d, const MoveOptions& o) {
  const OpenTurntable t(d);
  if (!std::isfinite(o.degrees)) throw usage_error("the angle must be a finite number of degrees");
  if (o.settle_ms < 0) throw usage_error("--settle-ms must not be negative");
  const capture::TurntableInfo info = t->info();
  capture::MotionPolicy p;
  p.backlash_deg = o.backlash_deg;
  p.speed = speed_steps(o.speed_deg_s, info.steps_per_rev);
  // Move timeout = distance / speed + acceleration time + 2 s (docs/turntable.md §2).
  const double v = p.speed ? p.speed : info.max_speed;
  if (info.max_accel > 0) p.extra_timeout_s += v / info.max_accel;
  double target = o.degrees;
  if (o.relative || o.approach == Approach::shortest) {
    const double here = capture::angle_for_steps(t->status().position, info.steps_per_rev);
    if (o.relative) target += here;
    if (o.approach == Approach::shortest) {
      // The same table angle modulo 360 nearest to here, reached in its direction of travel.
      target -= 360.0 * std::round((target - here) / 360.0);
      p.approach = target >= here ? capture::Approach::ccw : capture::Approach::cw;
    }
  }
  if (o.approach == Approach::cw) p.approach = capture::Approach::cw;
  if (o.no_wait) {
    const std::int32_t steps = capture::steps_for_angle(target, info.steps_per_rev);
    t->move_abs(steps, p.speed);
    const double got = capture::angle_for_steps(steps, info.steps_per_rev);
    print(d, {{"angle_cmd_deg", target}, {"angle_deg", got}, {"steps", steps}, {"waited", false}},
          fmt::format("moving to {:.4f} deg ({} steps)\n", got, steps));
    return 0;
  }
  const capture::MoveResult r = capture::move_to_angle(*t, target, p);
  if (o.settle_ms > 0) t->wait_ms(unsigned(o.settle_ms));
  print(d, {{"angle_cmd_deg", r.angle_cmd_deg}, {"angle_deg", r.angle_deg}, {"steps", r.steps}, {"overshoot", r.overshoot}},
        fmt::format("{:.4f} deg ({} steps)\n", r.angle_deg, r.steps));
  return 0;
}

}  // namespace fest::turntable_tool
