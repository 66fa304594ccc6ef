// Camera calibration on boards rendered through a known camera (with radial
// distortion): K and the distortion are recovered (docs/capture.md §6).

#include <gtest/gtest.h>

#include "calib_scenes.hpp"
#include "capture/calib_camera.hpp"
#include "capture/calib_synth.hpp"
#include "expect_error.hpp"

namespace {

using namespace fest;
using namespace fest::capture;

using test::calibration_poses;

TEST(CalibCamera, RecoversKnownIntrinsics) {
  const Intrinsics truth = test::camera(700, 640, 480, -0.15, 0.08);
  const BoardSpec board{9, 6, 25};
  std::vector<std::vector<cv::Point2f>> views;
  for (const Pose& p : calibration_poses()) {
    auto corners = find_board_corners(render_board(truth, board, p, 3), board);
    ASSERT_FALSE(corners.empty());
    views.push_back(corners);
  }
  CameraCalibOptions options;
  options.fix_k3 = true;  // the truth has k3 = 0; ten views cannot pin it down
  const CameraCalibration cal = calibrate_camera(views, board, {640, 480}, options);
  const Intrinsics& k = cal.intrinsics;
  // Tolerances: corners are found to ~0.05 px, which over ten views bounds the focal
  // length to a few tenths of a percent and the principal point to about a pixel.
  EXPECT_NEAR(k.K(0, 0), truth.K(0, 0), 0.003 * truth.K(0, 0));
  EXPECT_NEAR(k.K(1, 1), truth.K(1, 1), 0.003 * truth.K(1, 1));
  EXPECT_NEAR(k.K(0, 2), truth.K(0, 2), 1.5);
  EXPECT_NEAR(k.K(1, 2), truth.K(1, 2), 1.5);
  EXPECT_NEAR(k.dist[0], truth.dist[0], 0.01);
  EXPECT_NEAR(k.dist[1], truth.dist[1], 0.03);
  EXPECT_LT(cal.rms, 0.1);
  ASSERT_EQ(cal.view_rms.size(), views.size());
  for (double r : cal.view_rms) EXPECT_LT(r, 0.15);
  // The poses come back too: view 0's translation within 2 mm.
  EXPECT_LT(cv::norm(cal.poses[0].t - calibration_poses()[0].t), 2.0);
  std::printf("camera: fx %.3f (true %.3f) fy %.3f (%.3f) cx %.3f (%.3f) cy %.3f (%.3f) k1 %.5f k2 %.5f rms %.4f px\n",
              k.K(0, 0), truth.K(0, 0), k.K(1, 1), truth.K(1, 1), k.K(0, 2), truth.K(0, 2), k.K(1, 2), truth.K(1, 2),
              k.dist[0], k.dist[1], cal.rms);
}

TEST(CalibCamera, TooFewViews) {
  const std::vector<std::vector<cv::Point2f>> two(2, std::vector<cv::Point2f>(54));
  test::expect_bad_input([&] { calibrate_camera(two, BoardSpec{9, 6, 25}, {640, 480}); }, "at least 3");
}

TEST(CalibCamera, PoseOfAKnownView) {
  const Intrinsics cam = test::camera(700, 640, 480);
  const BoardSpec board{9, 6, 25};
  const Pose truth = calibration_poses()[5];
  const auto corners = find_board_corners(render_board(cam, board, truth, 3), board);
  ASSERT_FALSE(corners.empty());
  const Pose p = board_pose(corners, board, cam);
  EXPECT_LT(cv::norm(p.t - truth.t), 1.0);
  EXPECT_LT(cv::norm(cv::Mat(p.R - truth.R)), 2e-3);
  EXPECT_LT(reprojection_rms(corners, board, cam, p), 0.1);
}

}  // namespace
