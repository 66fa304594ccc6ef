#pragma once
// capture's calibration subcommands (docs/capture.md §5):
//   calib-camera     chessboard images -> camera.json (K, dist, RMS; brdffit's cam.json)
//   calib-turntable  board on the table at known angles -> turntable_cal.json (R_T0, t_T0)
//   calib-lights     chrome spheres -> lights_cal.json (light position)
// All three work on images already taken (by `capture run`, or any camera).

#include <CLI/CLI.hpp>

namespace fest::capture_tool {

// Registers the three subcommands on `app`. Their work runs in run_calib_command, from
// inside cli::run's body (so that fest::Error becomes the design's message and status).
void add_calib_commands(CLI::App& app);

// Runs the calibration subcommand selected on the command line and returns its exit
// status; returns -1 when none of them was selected.
int run_calib_command(const CLI::App& app);

}  // namespace fest::capture_tool
