#include "capture/step_profile.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::capture {
namespace {

// Time at which the ideal profile over `total` steps has covered distance s (0 <= s <= total).
double time_at(double s, double total, double v, double a) {
  const double ramp = v * v / (2 * a);  // distance to reach v
  if (2 * ramp >= total) {              // triangle: accelerate to the middle, then brake
    const double half = total / 2, t_half = std::sqrt(2 * half / a);
    if (s <= half) return std::sqrt(2 * s / a);
    return 2 * t_half - std::sqrt(2 * (total - s) / a);
  }
  const double t_ramp = v / a, cruise = total - 2 * ramp, t_cruise = cruise / v;
  if (s <= ramp) return std::sqrt(2 * s / a);
  if (s <= ramp + cruise) return t_ramp + (s - ramp) / v;
  return 2 * t_ramp + t_cruise - std::sqrt(2 * (total - s) / a);
}

}  // namespace

std::vector<double> trapezoid_step_times(std::uint32_t steps, double max_speed, double accel) {
  if (!(max_speed > 0) || !(accel > 0)) throw usage_error("step profile: speed and acceleration must be positive");
  std::vector<double> t(steps);
  for (std::uint32_t k = 0; k < steps; ++k) t[k] = time_at(double(k), double(steps), max_speed, accel);
  return t;
}

double trapezoid_duration(std::uint32_t steps, double max_speed, double accel) {
  if (!(max_speed > 0) || !(accel > 0)) throw usage_error("step profile: speed and acceleration must be positive");
  return time_at(double(steps), double(steps), max_speed, accel);
}

}  // namespace fest::capture
