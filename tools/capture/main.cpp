// capture: acquisition sessions and station calibration (specs/capture.md §2.5-2.7, §4).
//
// Wiring only: each group of subcommands registers itself on the app.

#include "calib_commands.hpp"
#include "cli/cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Drive an appearance-capture station: calibrate its camera, turntable and lights.", "capture"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  fest::capture_tool::add_calib_commands(app);
  return fest::cli::run(app, argc, argv, [&] { return fest::capture_tool::run_calib_command(app); });
}
