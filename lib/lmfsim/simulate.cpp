#include "lmfsim/simulate.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/stopwatch.hpp"

namespace fest::lmfsim {

ViolationLimitExceeded::ViolationLimitExceeded(double violation_, double limit_, double t_)
    : Error(Status::failure,
            fmt::format("constraint violation {:.3g} exceeds the limit {:.3g} (t={:.6g})", violation_, limit_, t_)),
      violation(violation_),
      limit(limit_),
      t(t_) {}

RunSummary simulate(System& sys, const FrameCallback& on_frame) {
  const auto start = SteadyClock::now();
  const SimSettings& sim = sys.settings();
  std::vector<Event> events = sys.scene().events;
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
  std::size_t next_event = 0;
  const long n_steps = std::lround(sim.t_end / sim.dt);
  Eigen::VectorXd s = sys.initial_state();
  StepCounters counters;
  double h_try = sim.dt;
  RunSummary sum;
  auto apply_events = [&](double t) {
    while (next_event < events.size() && events[next_event].t <= t + 1e-9 * sim.dt) {
      sys.apply_event(events[next_event], s);
      ++next_event;
    }
  };
  apply_events(0);
  on_frame(0, 0.0, s);
  for (long k = 0; k < n_steps; ++k) {
    const double t = static_cast<double>(k) * sim.dt;
    if (k > 0) apply_events(t);
    advance(sys, sim.integrator, t, sim.dt, s, counters, h_try);
    const double t1 = static_cast<double>(k + 1) * sim.dt;
    if (sim.stab == Stabilization::project) sys.project(t1, s);
    if (!s.allFinite()) throw runtime_failure("state became non-finite (t={:.6g}, step {})", t1, k + 1);
    const double v = sys.max_violation(t1, s);
    sum.max_C = std::max(sum.max_C, v);
    if (v > sim.max_violation)
      throw ViolationLimitExceeded(v, sim.max_violation, t1);
    if ((k + 1) % sim.every == 0) on_frame(static_cast<int>((k + 1) / sim.every), t1, s);
  }
  sum.steps = counters.steps;
  sum.evals = counters.evals;
  sum.wall_s = seconds_since(start);
  return sum;
}

}  // namespace fest::lmfsim
