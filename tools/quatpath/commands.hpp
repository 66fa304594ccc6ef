#pragma once
// quatpath: key poses in, per-frame poses out (docs/quatpath.md).

#include <optional>
#include <string>

#include "motionpath/path.hpp"

namespace fest::quatpath_tool {

// What the poses are written as (--to).
enum class PoseFormat {
  csv,
  jsonl,
  camera,       // terrainlod --path JSON Lines
  camera_args,  // volrender look-at flags, one line per frame
};

struct PathArgs {
  std::string input = "-";
  std::string output = "-";
  std::optional<PoseFormat> to;      // none: by -o's extension (.jsonl, .json), else csv
  double fps = 30.0;
  motionpath::OrientationMode orientation = motionpath::OrientationMode::slerp;
  motionpath::PositionMode position = motionpath::PositionMode::catmull_rom;
  motionpath::Way way = motionpath::Way::shortest;  // default for segments whose key gives none
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
