// lib/markers/overlay: a unit cube drawn at a marker pose covers exactly the projection
// of the cube (its 8 corners' convex hull) to within 1 px, with and without distortion.
#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "markers/overlay.hpp"
#include "markers_scenes.hpp"

using namespace fest::markers;

namespace {

// Projected hull of the cube in ideal pixels (no distortion).
std::vector<cv::Point2f> ideal_hull(const CameraModel& cam, const Pose& pose, double side) {
  std::vector<cv::Point3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(i & 1 ? side / 2 : -side / 2, i & 2 ? side / 2 : -side / 2, i & 4 ? side : 0.0);
  std::vector<cv::Point2d> p;
  cv::projectPoints(corners, rotation_vector(pose.R), pose.t, cv::Mat(cam.K), cv::noArray(), p);
  std::vector<cv::Point2f> pf(p.begin(), p.end()), hull;
  cv::convexHull(pf, hull);
  return hull;
}

void check_cube(const CameraModel& cam, const Pose& pose, double side) {
  const std::vector<std::uint8_t> mask = overlay_mask(marker_cube(side), cam, pose);
  const std::vector<cv::Point2f> hull = ideal_hull(cam, pose, side);
  std::vector<cv::Point2d> px, ideal;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) px.emplace_back(x, y);
  if (cam.has_distortion())
    cv::undistortPoints(px, ideal, cv::Mat(cam.K), cv::Mat(cam.dist), cv::noArray(), cv::Mat(cam.K),
                        cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-12));
  else
    ideal = px;
  int covered = 0, wrong = 0;
  for (std::size_t i = 0; i < px.size(); ++i) {
    // Signed distance of the pixel's ray to the hull edge, in ideal pixels (the lens
    // changes the scale by a few per cent at most here).
    const double d = cv::pointPolygonTest(hull, cv::Point2f(ideal[i]), true);
    covered += mask[i];
    if ((d > 1 && !mask[i]) || (d < -1 && mask[i])) ++wrong;
  }
  EXPECT_GT(covered, 500);
  EXPECT_EQ(wrong, 0);
}

}  // namespace

TEST(MarkersOverlay, UnitCubeCoversItsProjection) {
  const CameraModel cam = fest::test::camera640();
  check_cube(cam, pose_facing(cam, 300, 260, 0.3, 35, 20, 15), 0.05);
  check_cube(cam, pose_facing(cam, 150, 100, 0.4, 55, 200, 70), 0.05);
}

TEST(MarkersOverlay, UnitCubeCoversItsProjectionThroughTheLens) {
  const CameraModel cam = fest::test::camera640(true);
  check_cube(cam, pose_facing(cam, 520, 400, 0.3, 35, 20, 15), 0.05);
}

TEST(MarkersOverlay, DrawsOnlyWhereTheMaskIs) {
  const CameraModel cam = fest::test::camera640();
  const Pose pose = pose_facing(cam, 320, 240, 0.3, 30, 0, 0);
  cv::Mat img(cam.height, cam.width, CV_8UC3, cv::Scalar(10, 20, 30));
  draw_overlay(img, marker_cube(0.05), cam, {pose});
  const std::vector<std::uint8_t> mask = overlay_mask(marker_cube(0.05), cam, pose);
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const bool changed = img.at<cv::Vec3b>(y, x) != cv::Vec3b(10, 20, 30);
      ASSERT_EQ(changed, mask[static_cast<std::size_t>(y) * cam.width + x] != 0) << x << "," << y;
    }
}
