// Board specs and corner detection on rendered boards: every corner where the
// projection of the known pose puts it, in the canonical order even for a board turned
// by half a revolution (the turntable depends on it).

#include <gtest/gtest.h>

#include "calib_scenes.hpp"
#include "capture/calib_board.hpp"
#include "capture/calib_camera.hpp"
#include "capture/calib_synth.hpp"
#include "core/error.hpp"

namespace {

using namespace fest;
using namespace fest::capture;

TEST(CalibBoard, ParsesSpecs) {
  const BoardSpec b = parse_board_spec("9x6x25mm");
  EXPECT_EQ(b.cols, 9);
  EXPECT_EQ(b.rows, 6);
  EXPECT_DOUBLE_EQ(b.square, 25);
  EXPECT_DOUBLE_EQ(parse_board_spec("7x5x2.5cm").square, 25);
  EXPECT_DOUBLE_EQ(parse_board_spec("7x5x0.03m").square, 30);
  EXPECT_DOUBLE_EQ(parse_board_spec("9x6x20").square, 20);
  for (const char* bad : {"9x6", "9x6x0mm", "1x6x25mm", "9x6x25in", "6x6x25mm", "axbxc", "9x6x25mmm"}) {
    try {
      parse_board_spec(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::usage) << bad;
    }
  }
}

TEST(CalibBoard, ObjectPointsRowMajor) {
  const auto p = board_object_points(BoardSpec{4, 3, 10});
  ASSERT_EQ(p.size(), 12u);
  EXPECT_FLOAT_EQ(p[1].x, 10);
  EXPECT_FLOAT_EQ(p[4].y, 10);
  EXPECT_FLOAT_EQ(p[11].x, 30);
  EXPECT_FLOAT_EQ(p[11].z, 0);
}

// Detected corners against the projection of the true pose, in order.
double worst_corner_error(const Intrinsics& cam, const BoardSpec& board, const Pose& pose) {
  const cv::Mat image = render_board(cam, board, pose, 4);
  const auto corners = find_board_corners(image, board);
  if (corners.empty()) return 1e9;
  cv::Mat rvec;
  cv::Rodrigues(cv::Mat(pose.R), rvec);
  std::vector<cv::Point2f> truth;
  cv::projectPoints(board_object_points(board), rvec, cv::Mat(pose.t), cv::Mat(cam.K), cv::Mat(cam.dist), truth);
  double worst = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) worst = std::max(worst, double(cv::norm(truth[i] - corners[i])));
  return worst;
}

TEST(CalibBoard, CornersInCanonicalOrderAtAnyTurn) {
  const test::TurntableScene scene;
  const Intrinsics cam = test::camera(900, 800, 600);
  for (double theta : {0.0, 90.0, 180.0, 270.0}) {
    const double worst = worst_corner_error(cam, scene.board, scene.board_pose(theta));
    EXPECT_LT(worst, 0.15) << "turn " << theta;
  }
}

TEST(CalibBoard, NoBoardNoCorners) {
  const Intrinsics cam = test::camera(900, 320, 240);
  EXPECT_TRUE(find_board_corners(cv::Mat(240, 320, CV_8U, cv::Scalar(128)), BoardSpec{9, 6, 25}).empty());
  // Board pose behind the camera: nothing rendered, nothing found.
  const Pose behind{cv::Matx33d::eye(), cv::Vec3d(-100, -60, -500)};
  EXPECT_TRUE(find_board_corners(render_board(cam, BoardSpec{9, 6, 25}, behind, 1), BoardSpec{9, 6, 25}).empty());
}

TEST(CalibBoard, GreyConversions) {
  cv::Mat rgb16(2, 2, CV_16UC3, cv::Scalar(65535, 65535, 65535));
  EXPECT_EQ(to_gray8(rgb16).at<std::uint8_t>(0, 0), 255);
  EXPECT_NEAR(to_gray_float(rgb16).at<float>(1, 1), 1.0f, 1e-6);
  cv::Mat f(2, 2, CV_32FC1, cv::Scalar(0.5));
  EXPECT_EQ(to_gray8(f).type(), CV_8U);
  EXPECT_NEAR(to_gray8(f).at<std::uint8_t>(0, 0), 128, 1);
}

}  // namespace
