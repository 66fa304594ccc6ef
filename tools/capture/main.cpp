// capture: acquisition sessions on a turntable station (docs/capture.md).
// Flags only; the subcommands live in *_command.cpp.

#include "calib_commands.hpp"
#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::capture_tool;
  CLI::App app{"Drive an appearance-capture station: plans, runs with a journaled manifest, selftest,\n"
               "calibration of its camera, turntable and lights",
               "capture"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  PlanOptions plan;
  CLI::App* p = app.add_subcommand("plan", "Write a plan.json from flags");
  p->add_option("--angles", plan.angles, "Turntable angles: a count (24 = every 15 deg) or a list 0,15,30");
  p->add_option("--lights", plan.lights, "each (every light of role light) or a list L0,L1");
  p->add_option("--bracket", plan.bracket, "Exposures BASE:STOPS:COUNT (1/1000:1:12) or a list 0.001,0.002");
  p->add_option("--silhouette", plan.silhouette, "Backlight id(s) for one silhouette shot per view");
  p->add_option("--silhouette-exposure", plan.silhouette_exposure_s, "Exposure of the silhouette shot, s")
      ->check(CLI::PositiveNumber);
  p->add_option("--lightcal", plan.lightcal, "Light-calibration (mirror ball) shots per view")->check(CLI::Range(0, 100));
  p->add_option("--dark", plan.dark, "Dark frames (all lights off) per view")->check(CLI::Range(0, 100));
  p->add_option("--repeat", plan.repeat, "Takes of every exposure (hdrmerge averages them: less noise)")
      ->check(CLI::Range(1, 100));

  RunOptions run;
  CLI::App* r = app.add_subcommand("run", "Run a plan on the station; the manifest on standard output");
  r->add_option("--station", run.station, "station.json")->envname("CAPTURE_STATION");
  r->add_option("--plan", run.plan, "plan.json")->required();
  r->add_option("-o,--output", run.session, "Session folder");
  r->add_flag("--resume", run.resume, "Continue an interrupted session, keeping shots whose files hash as recorded");
  r->add_flag("--dry-run", run.dry_run, "Print the plan, its shots and a time estimate; touch no device");
  r->add_flag("--allow-jpeg", run.allow_jpeg, "Accept a station asking for JPEG (lossy: refused by default)");

  SelftestOptions self;
  CLI::App* s = app.add_subcommand("selftest", "Check every device of the station; a JSON report");
  s->add_option("--station", self.station, "station.json")->envname("CAPTURE_STATION");

  // calib-camera, calib-turntable, calib-lights (tools/capture/calib_commands.cpp).
  add_calib_commands(app);

  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error,\n"
             "5 device not found, 6 device error, 7 timeout, 8 permission denied. See capture(1).");
  // The outer frame reports errors thrown from CLI11 callbacks during parsing too.
  return fest::run_tool("capture", [&] {
    return fest::cli::run(app, argc, argv, [&] {
      if (p->parsed()) return plan_command(plan);
      if (r->parsed()) return run_command(run);
      if (s->parsed()) return selftest_command(self);
      return run_calib_command(app);
    });
  });
}
