// lib/markers/tracker: over a sequence, the IPPE branch nearer the previous rotation is
// kept when the two explain the corners about equally well, which removes the flips of
// near-frontal markers that a single image cannot decide.
#include <gtest/gtest.h>

#include "markers/tracker.hpp"
#include "markers_scenes.hpp"

using namespace fest::markers;

TEST(MarkersTracker, RemovesFlipsOfANearFrontalMarker) {
  const CameraModel cam = fest::test::camera640();
  fest::Rng rng(4);
  PoseTracker tracker;
  int single_flips = 0, tracked_flips = 0;
  Pose prev_single, prev_tracked;
  for (int frame = 0; frame < 200; ++frame) {
    // A 15 px marker (2 m away) 20 degrees off frontal, turning slowly; corners with
    // 0.3 px noise: the two IPPE poses explain the corners about equally well.
    const Pose truth = pose_facing(cam, 320, 240, 2.0, 20, 40, frame * 0.5);
    Corners c = project_corners(cam, truth, 0.05);
    for (cv::Point2d& p : c) p += cv::Point2d(0.3 * rng.normal(), 0.3 * rng.normal());
    const SquarePose e = estimate_square_pose(cam, c, 0.05);
    const Pose tracked = tracker.update(7, e);
    if (frame > 0) {
      // A flip turns the pose by about twice the tilt; the motion is 0.5 degree a frame.
      single_flips += rotation_angle_deg(prev_single.R, e.pose.R) > 20;
      tracked_flips += rotation_angle_deg(prev_tracked.R, tracked.R) > 20;
    }
    prev_single = e.pose;
    prev_tracked = tracked;
  }
  EXPECT_GT(single_flips, 10);  // the ambiguity is real here
  EXPECT_LT(tracked_flips, single_flips / 5);
}

TEST(MarkersTracker, MarkersAreTrackedSeparately) {
  PoseTracker tracker;
  SquarePose a;
  a.pose.R = rotation_from_vector(cv::Vec3d(0.1, 0, 0));
  a.alternative.R = rotation_from_vector(cv::Vec3d(-0.1, 0, 0));
  a.rms_px = a.alternative_rms_px = 0.1;
  SquarePose b = a;
  std::swap(b.pose, b.alternative);
  tracker.update(1, a);
  // Marker 2 has no history: its own best is kept, whatever marker 1 did.
  EXPECT_LT(rotation_angle_deg(tracker.update(2, b).R, b.pose.R), 1e-9);
  // Marker 1 keeps its branch.
  EXPECT_LT(rotation_angle_deg(tracker.update(1, b).R, a.pose.R), 1e-9);
}
