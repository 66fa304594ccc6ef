#pragma once
// Wall-clock timing for reports and traces: one steady clock and one way to read it, so
// that every "ms" in a --report means the same thing.

#include <chrono>

namespace fest {

using SteadyClock = std::chrono::steady_clock;

inline double ms_since(SteadyClock::time_point t0) {
  return std::chrono::duration<double, std::milli>(SteadyClock::now() - t0).count();
}

inline double seconds_since(SteadyClock::time_point t0) {
  return std::chrono::duration<double>(SteadyClock::now() - t0).count();
}

// Started when made; ms()/seconds() read the time since then, restart() starts again.
class Stopwatch {
 public:
  double ms() const { return ms_since(start_); }
  double seconds() const { return seconds_since(start_); }
  void restart() { start_ = SteadyClock::now(); }

 private:
  SteadyClock::time_point start_ = SteadyClock::now();
};

}  // namespace fest
