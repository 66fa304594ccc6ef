#pragma once
// quatpath: key poses in, per-frame poses out (docs/quatpath.md).

#include <string>

namespace fest::quatpath_tool {

struct PathArgs {
  std::string input = "-";
  std::string output = "-";
  std::string to;                    // csv, jsonl, camera (default: by extension, else csv)
  double fps = 30.0;
  std::string orientation = "slerp";
  std::string position = "catmull-rom";
  std::string way = "short";         // default for segments whose key gives none
  bool constant_speed = false;
  bool no_end = false;
  double camera_distance = 100.0;
  double fovy_deg = 60.0;
  int width = 1920, height = 1080;
  double tau_px = -1;
  std::string report;
  bool quiet = false;
};

int cmd_path(const PathArgs& a);

}  // namespace fest::quatpath_tool
