// turntable: rotate a capture station's turntable (docs/turntable.md) through a TTP/1 USB
// controller, a GPIO step/dir driver or the simulator, with the host's backlash-cancelling
// approach. Flags only; the subcommands live in cmd_*.cpp (fest_turntable_app).

#include <string>

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::turntable_tool;
  CLI::App app{"Rotate a capture station's turntable: a TTP/1 USB controller (usb:) or the simulator (sim:).",
               "turntable"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.fallthrough();
  app.footer("Device URIs: usb:[VID:PID][#SERIAL] (default usb:1209:0001), sim:[steps=N,speed=DEG_S,...].\n"
             "Exit status: 0 ok, 2 usage, 3 bad station file, 4 I/O, 5 device not found or unplugged,\n"
             "6 device error (stall, fault), 7 timeout, 8 permission denied. See turntable(1), ttp(7).");
  DeviceOptions dev;
  app.add_option("--device", dev.device, "Device URI (default: the station's turntable.uri, else usb:)");
  app.add_option("--station", dev.station, "station.json whose turntable.uri is used (default $CAPTURE_STATION)");
  app.add_flag("--json", dev.json, "Print one JSON object instead of text");

  auto* info = app.add_subcommand("info", "Name, serial, steps per revolution, speed limits");
  auto* status = app.add_subcommand("status", "Position, target, state, homed, fault");
  auto* list = app.add_subcommand("list", "TTP/1 devices with the URI's VID:PID and their serials");
  HomeOptions hm;
  auto* home = app.add_subcommand("home", "Run to the home switch and wait");
  home->add_option("--timeout", hm.timeout_s, "Give up (STOP, exit 7) after this many seconds")->default_val(60);
  home->add_flag("--cw", hm.clockwise, "Search clockwise (default counter-clockwise)");
  home->add_option("--speed", hm.speed_deg_s, "Speed in deg/s (0 = the device's default)")->default_val(0);
  MoveOptions mv;
  std::string approach = "ccw";
  auto* move = app.add_subcommand("move", "Move to an angle in degrees, approaching from one side");
  move->add_option("degrees", mv.degrees, "Target angle (deg; counter-clockwise seen from above is positive)")->required();
  move->add_flag("--relative", mv.relative, "DEG is relative to the current position");
  move->add_option("--speed", mv.speed_deg_s, "Speed in deg/s (0 = the device's maximum)")->default_val(0);
  move->add_option("--approach", approach, "Final direction: ccw, cw, or shortest (nearest equivalent angle)")
      ->check(CLI::IsMember({"ccw", "cw", "shortest"}))
      ->default_val("ccw");
  move->add_option("--backlash-deg", mv.backlash_deg, "Overshoot before coming back from the other side")
      ->check(fest::cli::non_negative)
      ->default_val(2.0);
  move->add_option("--settle-ms", mv.settle_ms, "Wait after arrival (vibrations)")->default_val(500)->check(fest::cli::range(0, 86400000));
  move->add_flag("--no-wait", mv.no_wait, "Send the move and return at once (no approach policy)");
  bool stop_now = false;
  auto* stop = app.add_subcommand("stop", "Stop (decelerating; --now: at once)");
  stop->add_flag("--now", stop_now, "Stop immediately (may lose steps)");
  auto* zero = app.add_subcommand("zero", "Declare the current position 0");
  auto* enable = app.add_subcommand("enable", "Power the motor driver");
  auto* disable = app.add_subcommand("disable", "Unpower the motor driver (the table turns by hand)");

  return fest::cli::run(app, argc, argv, [&] {
    dev.quiet = common.quiet;
    if (*list) return list_command(dev);
    if (*info) return info_command(dev);
    if (*status) return status_command(dev);
    if (*home) return home_command(dev, hm);
    if (*move) {
      mv.approach = approach == "cw" ? Approach::cw : approach == "shortest" ? Approach::shortest : Approach::ccw;
      return move_command(dev, mv);
    }
    if (*stop) return stop_command(dev, stop_now);
    if (*zero) return zero_command(dev);
    if (*enable) return enable_command(dev, true);
    if (*disable) return enable_command(dev, false);
    return 0;
  });
}
