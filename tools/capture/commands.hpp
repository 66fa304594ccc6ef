#pragma once
// capture's subcommands: options as main.cpp parses them, one function per subcommand.

#include <string>

namespace fest::capture_tool {

struct PlanOptions {
  std::string angles = "24";
  std::string lights = "each";
  std::string bracket = "1/1000:1:12";
  std::string silhouette;  // backlight id(s), comma-separated; empty = no silhouette shot
  double silhouette_exposure_s = 0.01;
  int lightcal = 0, dark = 0;
  int repeat = 1;  // takes of every exposure
};

struct RunOptions {
  std::string station, plan, session;
  bool resume = false, dry_run = false, allow_jpeg = false;
};

struct SelftestOptions {
  std::string station;
};

int plan_command(const PlanOptions& o);
int run_command(const RunOptions& o);
int selftest_command(const SelftestOptions& o);

}  // namespace fest::capture_tool
