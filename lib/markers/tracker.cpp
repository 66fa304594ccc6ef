#include "markers/tracker.hpp"

#include <algorithm>

namespace fest::markers {

Pose PoseTracker::update(int id, const SquarePose& e, bool* switched) {
  Pose chosen = e.pose;
  bool sw = false;
  const auto it = last_.find(id);
  // Ambiguous: the alternative explains the corners nearly as well (within the ratio,
  // or within a tenth of a pixel when both are tiny).
  const bool ambiguous = e.alternative_rms_px <= std::max(ratio_ * e.rms_px, e.rms_px + 0.1);
  if (it != last_.end() && ambiguous &&
      rotation_angle_deg(it->second.R, e.alternative.R) < rotation_angle_deg(it->second.R, e.pose.R)) {
    chosen = e.alternative;
    sw = true;
  }
  last_[id] = chosen;
  if (switched) *switched = sw;
  return chosen;
}

}  // namespace fest::markers
