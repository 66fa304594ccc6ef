// lights: switch a capture station's point lights (docs/lights.md): GPIO output lines
// through libgpiod, TTP/1 aux outputs or simulated lights, as listed in station.json's
// "lights". Flags only; the subcommands live in cmd_*.cpp (fest_lights_app).

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::lights_tool;
  // Blocked before any line is requested: only pulse and hold ever receive them.
  block_stop_signals();

  CLI::App app{"Switch a capture station's lights (GPIO lines or simulated) as listed in station.json.", "lights"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.fallthrough();
  app.footer("Exit status: 0 ok, 2 usage, 3 bad station file, 4 I/O, 5 chip or line not found,\n"
             "6 device error (line busy: the holder is named), 8 permission denied. See lights(1).");
  StationOptions st;
  app.add_option("--station", st.station, "station.json with a \"lights\" array (default $CAPTURE_STATION)");

  std::vector<std::string> ids;
  OffOptions of;
  PulseOptions pu;
  HoldOptions ho;
  auto* list = app.add_subcommand("list", "id,uri,state of every light as CSV (state of GPIO lines: free / used by ...)");
  auto* on = app.add_subcommand("on", "Switch these lights on and leave them on (see hold)");
  on->add_option("ids", ids, "Light ids")->required();
  auto* off = app.add_subcommand("off", "Switch these lights (or --all) off");
  off->add_option("ids", ids, "Light ids");
  off->add_flag("--all", of.all, "Every light of the station");
  auto* only = app.add_subcommand("only", "This light on, every other light of the station off");
  only->add_option("id", ids, "Light id")->required()->expected(1);
  auto* pulse = app.add_subcommand("pulse", "Switch a light on for --ms milliseconds, then off");
  pulse->add_option("id", ids, "Light id")->required()->expected(1);
  pulse->add_option("--ms", pu.ms, "Duration in milliseconds")->required()->check(fest::cli::range(1L, 86400000L));
  auto* hold = app.add_subcommand("hold", "Keep lights on until --time passes or SIGINT/SIGTERM/SIGHUP, then off");
  hold->add_option("ids", ids, "Light ids")->required();
  hold->add_option("--time", ho.seconds, "Seconds (default: until a signal)")->check(fest::cli::positive);

  return fest::cli::run(app, argc, argv, [&] {
    if (*list) return list_command(st);
    if (*on) return on_command(st, ids);
    if (*off) {
      of.ids = ids;
      return off_command(st, of);
    }
    if (*only) return only_command(st, ids.front());
    if (*pulse) {
      pu.id = ids.front();
      return pulse_command(st, pu);
    }
    ho.ids = ids;
    (void)hold;
    return hold_command(st, ho);
  });
}
