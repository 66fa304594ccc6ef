#include "pose_json.hpp"

#include <cmath>

namespace fest::markerpose_tool {

namespace {

// Fixed decimal resolutions keep the output short and byte-stable: 1e-4 px, 1e-7 for
// rotations, a power of ten near 1e-7 of the marker size for translations. Dividing by
// the inverse step (an exact integer) gives the double nearest to the decimal, which
// prints as the short decimal.
double round_to(double x, double step) {
  const double k = std::round(1.0 / step);
  return std::round(x * k) / k;
}

}  // namespace

nlohmann::ordered_json marker_json(const MarkerResult& m, bool pattern, double size) {
  using json = nlohmann::ordered_json;
  json corners = json::array();
  for (const cv::Point2d& p : m.detection.corners) corners.push_back({round_to(p.x, 1e-4), round_to(p.y, 1e-4)});
  const cv::Vec3d r = markers::rotation_vector(m.pose.R);
  json R = json::array();
  for (int i = 0; i < 9; ++i) R.push_back(round_to(m.pose.R.val[i], 1e-7));
  const double t_step = std::pow(10.0, std::floor(std::log10(size * 1e-7)));
  const bool alternative = m.switched;
  const double rms = alternative ? m.estimate.alternative_rms_px : m.estimate.rms_px;
  const double other = alternative ? m.estimate.rms_px : m.estimate.alternative_rms_px;
  json j = {{"id", m.detection.id},
            {"corners", corners},
            {"rvec", {round_to(r[0], 1e-7), round_to(r[1], 1e-7), round_to(r[2], 1e-7)}},
            {"tvec", {round_to(m.pose.t[0], t_step), round_to(m.pose.t[1], t_step), round_to(m.pose.t[2], t_step)}},
            {"R", R},
            {"reproj_rms_px", round_to(rms, 1e-4)},
            {"alternative_rms_px", round_to(other, 1e-4)}};
  if (pattern) j["ncc"] = round_to(m.detection.score, 1e-4);
  else j["bit_errors"] = m.detection.bit_errors;
  if (m.switched) j["sequence_choice"] = true;
  return j;
}

}  // namespace fest::markerpose_tool
