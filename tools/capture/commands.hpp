#pragma once
// capture's subcommands (docs/capture.md): the typed options main.cpp fills from flags,
// and one function per subcommand; everything else in this folder is the library
// fest_capture_app. Each function returns the exit status or throws fest::Error.

#include <string>
#include <vector>

#include "capture/calib_board.hpp"

namespace fest::capture_tool {

// capture plan (docs/capture.md §2).
struct PlanOptions {
  std::vector<double> angles_deg;   // empty: 24 equal steps
  bool each_light = true;           // every light whose role is "light"
  std::vector<std::string> lights;  // when not each_light
  std::vector<double> exposures_s;  // increasing; empty: 1/1000 s doubled 11 times (12 exposures)
  std::vector<std::string> silhouette_lights;  // backlight id(s); empty = no silhouette shot
  double silhouette_exposure_s = 0.01;
  int lightcal = 0, dark = 0;
  int repeat = 1;  // takes of every exposure
};
int plan_command(const PlanOptions& o);

// capture run (docs/capture.md §2-3).
struct RunOptions {
  std::string station, plan, session;
  bool resume = false, dry_run = false, allow_jpeg = false;
  bool progress = false;  // --progress: shots taken of the plan's
};
int run_command(const RunOptions& o);

// capture selftest (docs/capture.md §4).
struct SelftestOptions {
  std::string station;
};
int selftest_command(const SelftestOptions& o);

// capture calib-camera, calib-turntable, calib-lights (docs/capture.md §5): work on
// images already taken (by `capture run`, or any camera). `quiet` silences the notes on
// images left out.
struct CalibCameraOptions {
  capture::BoardSpec board;
  std::string board_name;  // as given, for the report
  std::vector<std::string> images;
  bool fix_k3 = false, zero_tangent = false;
  bool quiet = false;
};
int calib_camera_command(const CalibCameraOptions& o);

struct CalibTurntableOptions {
  std::string camera;
  capture::BoardSpec board;
  std::string board_name;  // as given, for the report
  std::vector<double> angles_deg;  // one per image; empty: angle_count equal steps
  int angle_count = 0;             // 0: as many steps as images
  std::vector<std::string> images;
  bool quiet = false;
};
int calib_turntable_command(const CalibTurntableOptions& o);

struct CalibLightsOptions {
  std::string camera, id = "L0";
  double ball_radius = 0;  // mm
  std::vector<std::string> images;
  bool quiet = false;
};
int calib_lights_command(const CalibLightsOptions& o);

}  // namespace fest::capture_tool
