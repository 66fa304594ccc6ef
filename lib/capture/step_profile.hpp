#pragma once
// Host-generated step timing for step/dir stepper drivers (docs/turntable.md §3): a
// trapezoidal velocity profile (constant acceleration, cruise at the maximum speed,
// constant deceleration; a triangle when the move is too short to reach it).

#include <cstdint>
#include <vector>

namespace fest::capture {

// Times (seconds after the start) at which each of `steps` STEP pulses is issued, for a
// motor starting and ending at rest: pulse k sits where the ideal profile has covered k
// steps (the first at t = 0). usage_error for speed or acceleration <= 0.
std::vector<double> trapezoid_step_times(std::uint32_t steps, double max_speed, double accel);

// Duration of such a move, the time the ideal profile takes to cover all `steps`:
// steps/v + v/a when the cruise speed is reached, 2 sqrt(steps/a) otherwise.
double trapezoid_duration(std::uint32_t steps, double max_speed, double accel);

}  // namespace fest::capture
