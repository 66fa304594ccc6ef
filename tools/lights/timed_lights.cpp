// Lights lit for a while: on, then off when the time is up or a stop signal arrives
// (pulse and hold, docs/lights.md §2), and the signals blocked so that they are waited
// for rather than fatal.

#include <signal.h>

#include <cerrno>
#include <ctime>

#include "commands.hpp"
#include "devices/open_devices.hpp"
#include "station.hpp"
#include "timed_lights.hpp"

namespace fest::lights_tool {

namespace {

sigset_t stop_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
}

// Waits for `seconds` (forever when negative) or until a stop signal arrives.
void wait_or_signal(double seconds) {
  const sigset_t set = stop_signals();
  if (seconds < 0) {
    int sig = 0;
    sigwait(&set, &sig);
    return;
  }
  timespec end{};
  clock_gettime(CLOCK_MONOTONIC, &end);
  const double until = double(end.tv_sec) + end.tv_nsec * 1e-9 + seconds;
  for (;;) {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    const double left = until - (double(now.tv_sec) + now.tv_nsec * 1e-9);
    if (left <= 0) return;
    timespec ts{};
    ts.tv_sec = time_t(left);
    ts.tv_nsec = long((left - double(ts.tv_sec)) * 1e9);
    if (sigtimedwait(&set, nullptr, &ts) >= 0) return;  // a stop signal
    if (errno != EINTR && errno != EAGAIN) return;
  }
}

}  // namespace

int lit_for(const StationOptions& s, const std::vector<std::string>& ids, double seconds) {
  const std::vector<devices::LightConfig> lights = station_lights(s);
  auto bank = devices::open_lights(select(lights, ids), ids);
  wait_or_signal(seconds);
  bank->all_off();
  return 0;
}

void block_stop_signals() {
  const sigset_t set = stop_signals();
  sigprocmask(SIG_BLOCK, &set, nullptr);
}

}  // namespace fest::lights_tool
