#pragma once
// One marker as JSON: {"id", "corners", "rvec", "tvec", "R", "reproj_rms_px", ...}
// (man markerpose(1), OUTPUT).

#include <nlohmann/json.hpp>

#include "markers/detector.hpp"
#include "markers/pose.hpp"

namespace fest::markerpose_tool {

struct MarkerResult {
  markers::Detection detection;
  markers::SquarePose estimate;
  markers::Pose pose;  // the chosen pose (the tracker's over a sequence)
  bool switched = false;
};

nlohmann::ordered_json marker_json(const MarkerResult& m, bool pattern, double size);

}  // namespace fest::markerpose_tool
