#pragma once
// Pose over a sequence (docs/markerpose.md §4.3): a square seen nearly frontally or
// from far away has two poses of almost equal reprojection error (the IPPE pair, a
// flip about an axis in the marker plane). On a single image the lower error wins; in a
// sequence the branch nearer to the marker's previous rotation wins whenever the two
// errors are within the ambiguity ratio, which removes the frame-to-frame flips.

#include <map>

#include "markers/pose.hpp"

namespace fest::markers {

class PoseTracker {
 public:
  explicit PoseTracker(double ambiguity_ratio = 1.5) : ratio_(ambiguity_ratio) {}
  // Returns the chosen pose of marker `id` in the next frame; remembers it. The
  // returned flag says whether the sequence changed the single-image choice.
  Pose update(int id, const SquarePose& estimate, bool* switched = nullptr);

 private:
  double ratio_;
  std::map<int, Pose> last_;
};

}  // namespace fest::markers
