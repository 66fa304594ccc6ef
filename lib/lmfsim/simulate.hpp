#pragma once
// The run loop (docs/lmfsim.md §6): fixed steps of `dt` (rk45 adapts inside each), events
// at the first step boundary at or after their time, a frame every `every` steps, and
// the run-time checks of lmfsim(1) EXIT STATUS (non-finite state, |C| above the limit).

#include <functional>

#include <Eigen/Core>

#include "core/error.hpp"
#include "lmfsim/integrators.hpp"
#include "lmfsim/system.hpp"

namespace fest::lmfsim {

struct RunSummary {
  long steps = 0, evals = 0;
  double wall_s = 0;
  double max_C = 0;  // over steps
};

using FrameCallback = std::function<void(int frame, double t, const Eigen::VectorXd& s)>;

// |C| above SimSettings::max_violation at time t (Status::failure), with the figures, so
// that a tool can name its own setting of the limit.
class ViolationLimitExceeded : public Error {
 public:
  ViolationLimitExceeded(double violation, double limit, double t);
  double violation, limit, t;
};

// Throws runtime_failure when the state becomes non-finite, ViolationLimitExceeded when a
// holonomic constraint is violated by more than settings().max_violation.
RunSummary simulate(System& sys, const FrameCallback& on_frame);

}  // namespace fest::lmfsim
