#pragma once
// Key poses from CSV/TSV (t,x,y,z,qw,qx,qy,qz [,way] [,tension,continuity,bias]) or JSON
// Lines ({"t":..,"pos":[x,y,z],"quat":[w,x,y,z],"way":"long"}); frames out as CSV, JSON
// Lines, or a camera path (one terrainlod camera per line).

#include <string>
#include <vector>

#include "motionpath/path.hpp"

namespace fest::quatpath_tool {

struct CameraOptions {
  double distance = 100.0;
  double fovy_deg = 60.0;
  int width = 1920, height = 1080;
  double tau_px = -1;  // < 0: not written
};

std::vector<motionpath::Key> read_keys(const std::string& bytes, const std::string& name, motionpath::Way default_way,
                                       int& dropped_columns);
std::string write_csv(const std::vector<motionpath::Pose>& poses);
std::string write_jsonl(const std::vector<motionpath::Pose>& poses);
std::string write_cameras(const std::vector<motionpath::Pose>& poses, const CameraOptions& cam);
// One line of look-at flags per frame, "--eye X,Y,Z --look-at X,Y,Z --up X,Y,Z", for a
// shell loop around volrender (its look-at camera).
std::string write_camera_args(const std::vector<motionpath::Pose>& poses, const CameraOptions& cam);

}  // namespace fest::quatpath_tool
