// turntable: rotate a capture station's turntable (specs/capture.md §2.1-2.3, §4) through
// a TTP/1 USB controller or the simulator, with the host's backlash-cancelling approach.
//
// Wiring only: flags -> devices/open_devices (backend) -> lib/capture motion policy.

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include <nlohmann/json.hpp>

#include "capture/ttp1.hpp"
#include "capture/turntable.hpp"
#include "cli/cli.hpp"
#include "core/error.hpp"
#include "devices/open_devices.hpp"
#include "devices/gpio_stepper.hpp"
#include "devices/station_lights.hpp"
#include "devices/usb_turntable.hpp"

namespace {

using namespace fest;
using capture::MotionState;

struct Args {
  std::string device, station;
  bool json = false;
  // move
  double degrees = 0;
  bool relative = false, no_wait = false;
  double speed_deg_s = 0;
  std::string approach = "ccw";
  double backlash_deg = 2.0;
  int settle_ms = 500;
  // home
  double timeout_s = 60;
  bool clockwise = false;
  // stop
  bool now = false;
};

const char* state_name(MotionState s) {
  switch (s) {
    case MotionState::idle: return "idle";
    case MotionState::moving: return "moving";
    case MotionState::homing: return "homing";
    case MotionState::fault: return "fault";
  }
  return "?";
}

// --device, else the station's turntable.uri, else the TTP/1 default.
std::string device_uri(const Args& a) {
  if (!a.device.empty()) return a.device;
  const std::string station = devices::station_path(a.station);
  if (!station.empty()) {
    const nlohmann::json s = devices::read_station(station);
    const auto t = s.find("turntable");
    if (t != s.end() && t->is_object() && t->contains("uri")) {
      if (!(*t)["uri"].is_string()) throw bad_input("turntable.uri must be a string ({}: /turntable/uri)", station);
      return (*t)["uri"].get<std::string>();
    }
  }
  return "usb:";
}

void print(const Args& a, const nlohmann::json& j, const std::string& text) {
  const std::string s = a.json ? j.dump() + "\n" : text;
  std::fwrite(s.data(), 1, s.size(), stdout);
}

std::uint32_t speed_steps(double deg_s, std::uint32_t spr) {
  if (!(deg_s >= 0) || !std::isfinite(deg_s)) throw usage_error("--speed must be a non-negative number of deg/s");
  return std::uint32_t(std::lround(deg_s / 360.0 * spr));
}

int cmd_list(const Args& a) {
  const std::string uri = device_uri(a);
  nlohmann::json j = nlohmann::json::array();
  std::string text;
  if (uri.rfind("usb", 0) == 0) {
    for (const auto& l : devices::list_usb_turntables(devices::parse_usb_uri(uri))) {
      j.push_back({{"uri", l.uri}, {"product", l.product}, {"bus", l.bus}, {"address", l.address}, {"problem", l.problem}});
      text += l.problem.empty() ? fmt::format("{}\t{}\tbus {} device {}\n", l.uri, l.product, l.bus, l.address)
                                : fmt::format("{}\t(unusable: {})\n", l.uri, l.problem);
    }
  } else {
    devices::open_turntable(uri);  // a simulator is always there; just check the URI
    j.push_back({{"uri", uri}, {"product", "fest sim turntable"}});
    text = uri + "\tfest sim turntable\n";
  }
  print(a, j, text);
  return 0;
}

nlohmann::json status_json(const capture::TurntableStatus& s, std::uint32_t spr) {
  return {{"position_steps", s.position},
          {"target_steps", s.target},
          {"angle_deg", capture::angle_for_steps(s.position, spr)},
          {"state", state_name(s.state)},
          {"homed", s.homed},
          {"home_switch", s.home_switch},
          {"stalled", s.stalled},
          {"driver_enabled", s.driver_enabled},
          {"fault", s.fault},
          {"fault_name", capture::ttp1::fault_name(s.fault)},
          {"seq", s.seq}};
}

int cmd_info(const Args& a, capture::Turntable& t) {
  const capture::TurntableInfo i = t.info();
  const nlohmann::json j = {{"name", i.name},           {"serial", i.serial},       {"steps_per_rev", i.steps_per_rev},
                            {"max_speed", i.max_speed}, {"max_accel", i.max_accel}, {"has_home", i.has_home}};
  print(a, j,
        fmt::format("name: {}\nserial: {}\nsteps per revolution: {}\nmax speed: {} steps/s\nmax acceleration: {} steps/s^2\n"
                    "home switch: {}\n",
                    i.name, i.serial.empty() ? "-" : i.serial, i.steps_per_rev, i.max_speed, i.max_accel,
                    i.has_home ? "yes" : "no"));
  return 0;
}

int cmd_status(const Args& a, capture::Turntable& t) {
  const std::uint32_t spr = t.info().steps_per_rev;
  const capture::TurntableStatus s = t.status();
  print(a, status_json(s, spr),
        fmt::format("position: {} steps ({:.4f} deg)\ntarget: {} steps\nstate: {}\nhomed: {}\nfault: {} ({})\n", s.position,
                    capture::angle_for_steps(s.position, spr), s.target, state_name(s.state), s.homed ? "yes" : "no",
                    s.fault, capture::ttp1::fault_name(s.fault)));
  return 0;
}

int cmd_home(const Args& a, capture::Turntable& t) {
  if (!(a.timeout_s > 0)) throw usage_error("--timeout must be positive");
  const capture::TurntableInfo info = t.info();
  t.home(a.clockwise, speed_steps(a.speed_deg_s, info.steps_per_rev));
  const unsigned poll_ms = 20;
  for (double waited = 0;; waited += poll_ms) {
    const capture::TurntableStatus s = t.status();
    if (s.state == MotionState::fault)
      throw make_error(Status::device_error, "turntable fault {} ({}) while homing", s.fault, capture::ttp1::fault_name(s.fault));
    if (s.state == MotionState::idle && s.homed) {
      print(a, status_json(s, info.steps_per_rev), fmt::format("homed at step {}\n", s.position));
      return 0;
    }
    if (waited >= a.timeout_s * 1000) {
      t.stop(true);
      throw make_error(Status::timeout, "turntable did not find home within {} s", a.timeout_s);
    }
    t.wait_ms(poll_ms);
  }
}

int cmd_move(const Args& a, capture::Turntable& t) {
  if (!std::isfinite(a.degrees)) throw usage_error("the angle must be a finite number of degrees");
  if (a.settle_ms < 0) throw usage_error("--settle-ms must not be negative");
  const capture::TurntableInfo info = t.info();
  capture::MotionPolicy p;
  p.backlash_deg = a.backlash_deg;
  p.speed = speed_steps(a.speed_deg_s, info.steps_per_rev);
  // Move timeout = distance / speed + acceleration time + 2 s (spec §2.3).
  const double v = p.speed ? p.speed : info.max_speed;
  if (info.max_accel > 0) p.extra_timeout_s += v / info.max_accel;
  double target = a.degrees;
  if (a.relative || a.approach == "shortest") {
    const double here = capture::angle_for_steps(t.status().position, info.steps_per_rev);
    if (a.relative) target += here;
    if (a.approach == "shortest") {
      // The same table angle modulo 360 nearest to here, reached in its direction of travel.
      target -= 360.0 * std::round((target - here) / 360.0);
      p.approach = target >= here ? capture::Approach::ccw : capture::Approach::cw;
    }
  }
  if (a.approach == "cw") p.approach = capture::Approach::cw;
  if (a.no_wait) {
    const std::int32_t steps = capture::steps_for_angle(target, info.steps_per_rev);
    t.move_abs(steps, p.speed);
    const double got = capture::angle_for_steps(steps, info.steps_per_rev);
    print(a, {{"angle_cmd_deg", target}, {"angle_deg", got}, {"steps", steps}, {"waited", false}},
          fmt::format("moving to {:.4f} deg ({} steps)\n", got, steps));
    return 0;
  }
  const capture::MoveResult r = capture::move_to_angle(t, target, p);
  if (a.settle_ms > 0) t.wait_ms(unsigned(a.settle_ms));
  print(a, {{"angle_cmd_deg", r.angle_cmd_deg}, {"angle_deg", r.angle_deg}, {"steps", r.steps}, {"overshoot", r.overshoot}},
        fmt::format("{:.4f} deg ({} steps)\n", r.angle_deg, r.steps));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Rotate a capture station's turntable: a TTP/1 USB controller (usb:) or the simulator (sim:).",
               "turntable"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.fallthrough();
  app.footer("Device URIs: usb:[VID:PID][#SERIAL] (default usb:1209:0001), sim:[steps=N,speed=DEG_S,...].\n"
             "Exit status: 0 ok, 2 usage, 3 bad station file, 4 I/O, 5 device not found or unplugged,\n"
             "6 device error (stall, fault), 7 timeout, 8 permission denied. See turntable(1), ttp(7).");
  Args a;
  app.add_option("--device", a.device, "Device URI (default: the station's turntable.uri, else usb:)");
  app.add_option("--station", a.station, "station.json whose turntable.uri is used (default $CAPTURE_STATION)");
  app.add_flag("--json", a.json, "Print one JSON object instead of text");

  auto* info = app.add_subcommand("info", "Name, serial, steps per revolution, speed limits");
  auto* status = app.add_subcommand("status", "Position, target, state, homed, fault");
  auto* list = app.add_subcommand("list", "TTP/1 devices with the URI's VID:PID and their serials");
  auto* home = app.add_subcommand("home", "Run to the home switch and wait");
  home->add_option("--timeout", a.timeout_s, "Give up (STOP, exit 7) after this many seconds")->default_val(60);
  home->add_flag("--cw", a.clockwise, "Search clockwise (default counter-clockwise)");
  home->add_option("--speed", a.speed_deg_s, "Speed in deg/s (0 = the device's default)")->default_val(0);
  auto* move = app.add_subcommand("move", "Move to an angle in degrees, approaching from one side");
  move->add_option("degrees", a.degrees, "Target angle (deg; counter-clockwise seen from above is positive)")->required();
  move->add_flag("--relative", a.relative, "DEG is relative to the current position");
  move->add_option("--speed", a.speed_deg_s, "Speed in deg/s (0 = the device's maximum)")->default_val(0);
  move->add_option("--approach", a.approach, "Final direction: ccw, cw, or shortest (nearest equivalent angle)")
      ->check(CLI::IsMember({"ccw", "cw", "shortest"}))
      ->default_val("ccw");
  move->add_option("--backlash-deg", a.backlash_deg, "Overshoot before coming back from the other side")
      ->check(CLI::NonNegativeNumber)
      ->default_val(2.0);
  move->add_option("--settle-ms", a.settle_ms, "Wait after arrival (vibrations)")->default_val(500);
  move->add_flag("--no-wait", a.no_wait, "Send the move and return at once (no approach policy)");
  auto* stop = app.add_subcommand("stop", "Stop (decelerating; --now: at once)");
  stop->add_flag("--now", a.now, "Stop immediately (may lose steps)");
  auto* zero = app.add_subcommand("zero", "Declare the current position 0");
  auto* enable = app.add_subcommand("enable", "Power the motor driver");
  auto* disable = app.add_subcommand("disable", "Unpower the motor driver (the table turns by hand)");

  return fest::cli::run(app, argc, argv, [&] {
    if (*list) return cmd_list(a);
    const std::unique_ptr<capture::Turntable> t = devices::open_turntable(device_uri(a));
    // A host-generated step train without real-time priority may jitter (spec §2.4).
    // Said after a command that worked: a failure keeps its one diagnostic line.
    struct JitterWarning {
      capture::Turntable* t;
      bool quiet;
      ~JitterWarning() {
        if (auto* g = dynamic_cast<devices::GpioStepper*>(t); g && !g->realtime() && !quiet && std::uncaught_exceptions() == 0)
          fest::warn("turntable", "SCHED_FIFO not permitted: step timing may jitter (grant CAP_SYS_NICE or an rtprio limit)");
      }
    } jitter_warning{t.get(), common.quiet};
    if (*info) return cmd_info(a, *t);
    if (*status) return cmd_status(a, *t);
    if (*home) return cmd_home(a, *t);
    if (*move) return cmd_move(a, *t);
    if (*stop) t->stop(a.now);
    if (*zero) t->set_zero();
    if (*enable) t->enable(true);
    if (*disable) t->enable(false);
    return 0;
  });
}
