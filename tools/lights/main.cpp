// lights: switch a capture station's point lights (specs/capture.md §2.4, §4): GPIO output
// lines through libgpiod, or simulated lights, as listed in station.json's "lights".
//
// Wiring only: flags -> station (devices/station_lights) -> devices/open_devices.
// SIGINT/SIGTERM/SIGHUP are blocked from the start and only ever received by
// sigtimedwait, so no signal can end the process between switching a light on and
// switching it off again.

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "devices/gpio_lights.hpp"
#include "devices/open_devices.hpp"
#include "devices/station_lights.hpp"
#include "devices/usb_aux_lights.hpp"

namespace {

using namespace fest;
using devices::LightConfig;

struct Args {
  std::string station;
  std::vector<std::string> ids;
  bool all = false;
  long ms = 0;
  double time_s = 0;
};

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

std::vector<LightConfig> station_lights(const Args& a) {
  const std::string path = devices::station_path(a.station);
  if (path.empty()) throw usage_error("no station: give --station station.json or set CAPTURE_STATION");
  return devices::lights_from_station(devices::read_station(path), path);
}

// The station's lights named in ids, in the order given; usage_error for an unknown id.
std::vector<LightConfig> select(const std::vector<LightConfig>& all, const std::vector<std::string>& ids) {
  std::vector<LightConfig> out;
  for (const std::string& id : ids) {
    auto it = std::find_if(all.begin(), all.end(), [&](const LightConfig& l) { return l.id == id; });
    if (it == all.end()) throw usage_error("no light '{}' in the station", id);
    if (std::none_of(out.begin(), out.end(), [&](const LightConfig& l) { return l.id == id; })) out.push_back(*it);
  }
  return out;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

int cmd_list(const std::vector<LightConfig>& lights) {
  // Looks without requesting: requesting a GPIO output would switch it.
  std::string text = "id,uri,state\n";
  for (const LightConfig& l : lights) {
    const std::string scheme = l.uri.substr(0, l.uri.find(':'));
    std::string state;
    if (scheme == "gpio") {
      devices::GpioLineRef ref = devices::parse_gpio_uri(l.uri);
      state = devices::probe_gpio_line(ref);
    } else if (scheme == "sim") {
      state = "off";
    } else if (scheme == "usb-aux") {
      devices::parse_usb_aux_uri(l.uri);
      state = "unknown";  // TTP/1 has no request that reads the aux outputs back
    } else {
      throw usage_error("light {}: URI scheme '{}:' is not supported by this build (gpio:, usb-aux:, sim:)", l.id, scheme);
    }
    text += csv_field(l.id) + "," + csv_field(l.uri) + "," + csv_field(state) + "\n";
  }
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Blocked before any line is requested (see the header comment).
  const sigset_t set = stop_signals();
  sigprocmask(SIG_BLOCK, &set, nullptr);

  CLI::App app{"Switch a capture station's lights (GPIO lines or simulated) as listed in station.json.", "lights"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.fallthrough();
  app.footer("Exit status: 0 ok, 2 usage, 3 bad station file, 4 I/O, 5 chip or line not found,\n"
             "6 device error (line busy: the holder is named), 8 permission denied. See lights(1).");
  Args a;
  app.add_option("--station", a.station, "station.json with a \"lights\" array (default $CAPTURE_STATION)");

  auto* list = app.add_subcommand("list", "id,uri,state of every light as CSV (state of GPIO lines: free / used by ...)");
  auto* on = app.add_subcommand("on", "Switch these lights on and leave them on (see hold)");
  on->add_option("ids", a.ids, "Light ids")->required();
  auto* off = app.add_subcommand("off", "Switch these lights (or --all) off");
  off->add_option("ids", a.ids, "Light ids");
  off->add_flag("--all", a.all, "Every light of the station");
  auto* only = app.add_subcommand("only", "This light on, every other light of the station off");
  only->add_option("id", a.ids, "Light id")->required()->expected(1);
  auto* pulse = app.add_subcommand("pulse", "Switch a light on for --ms milliseconds, then off");
  pulse->add_option("id", a.ids, "Light id")->required()->expected(1);
  pulse->add_option("--ms", a.ms, "Duration in milliseconds")->required()->check(CLI::Range(1L, 86400000L));
  auto* hold = app.add_subcommand("hold", "Keep lights on until --time passes or SIGINT/SIGTERM/SIGHUP, then off");
  hold->add_option("ids", a.ids, "Light ids")->required();
  hold->add_option("--time", a.time_s, "Seconds (default: until a signal)")->check(CLI::PositiveNumber);

  return fest::cli::run(app, argc, argv, [&] {
    const std::vector<LightConfig> lights = station_lights(a);
    if (*list) return cmd_list(lights);
    if (*off) {
      if (a.all == !a.ids.empty()) throw usage_error("off needs light ids or --all (not both)");
      auto bank = devices::open_lights(a.all ? lights : select(lights, a.ids));  // requested off
      bank->keep_state_on_release();
      return 0;
    }
    if (*on) {
      auto bank = devices::open_lights(select(lights, a.ids), a.ids);
      bank->keep_state_on_release();
      return 0;
    }
    if (*only) {
      select(lights, a.ids);  // the id must exist
      auto bank = devices::open_lights(lights, a.ids);
      bank->keep_state_on_release();
      return 0;
    }
    // pulse, hold: lit while requested, off before release (also after a signal).
    auto bank = devices::open_lights(select(lights, a.ids), a.ids);
    wait_or_signal(*pulse ? double(a.ms) / 1000.0 : (a.time_s > 0 ? a.time_s : -1));
    bank->all_off();
    (void)hold;
    return 0;
  });
}
