// lib/markers/pose: IPPE against exact projections and against OpenCV's independent
// implementation (cv::solvePnPGeneric, SOLVEPNP_IPPE_SQUARE), LM against
// cv::solvePnPRefineLM.
#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>

#include "core/rng.hpp"
#include "markers/pose.hpp"
#include "markers/synth.hpp"

using namespace fest::markers;

namespace {

CameraModel camera640() {
  CameraModel c;
  c.K = cv::Matx33d(600, 0, 319.5, 0, 600, 239.5, 0, 0, 1);
  c.width = 640;
  c.height = 480;
  return c;
}

double translation_error(const Pose& a, const Pose& b) { return cv::norm(a.t - b.t); }

}  // namespace

TEST(MarkersPose, ExactCornersGiveTheExactPose) {
  const CameraModel cam = camera640();
  fest::Rng rng(3);
  for (int i = 0; i < 50; ++i) {
    const Pose truth = pose_facing(cam, rng.uniform(100, 540), rng.uniform(100, 380), rng.uniform(0.3, 2),
                                   rng.uniform(0, 60), rng.uniform(0, 360), rng.uniform(0, 360));
    const Corners px = project_corners(cam, truth, 0.1);
    const SquarePose p = estimate_square_pose(cam, px, 0.1);
    EXPECT_LT(rotation_angle_deg(p.pose.R, truth.R), 1e-4);  // acos resolution near 1
    EXPECT_LT(translation_error(p.pose, truth), 1e-9 * cv::norm(truth.t) + 1e-12);
    EXPECT_LT(p.rms_px, 1e-6);
  }
}

TEST(MarkersPose, IppeAgreesWithOpenCV) {
  const CameraModel cam = camera640();
  fest::Rng rng(5);
  for (int i = 0; i < 50; ++i) {
    const Pose truth = pose_facing(cam, rng.uniform(100, 540), rng.uniform(100, 380), rng.uniform(0.3, 2),
                                   rng.uniform(5, 60), rng.uniform(0, 360), rng.uniform(0, 360));
    Corners px = project_corners(cam, truth, 0.1);
    for (cv::Point2d& p : px) p += cv::Point2d(rng.normal() * 0.5, rng.normal() * 0.5);
    const Corners n = normalise_corners(cam, px);
    const std::array<Pose, 2> ours = ippe_square(n, 0.1);
    const auto obj = square_object_points(0.1);
    std::vector<cv::Point3d> o(obj.begin(), obj.end());
    std::vector<cv::Point2d> img(px.begin(), px.end());
    std::vector<cv::Mat> rvecs, tvecs;
    cv::solvePnPGeneric(o, img, cv::Mat(cam.K), cv::Mat(), rvecs, tvecs, false, cv::SOLVEPNP_IPPE_SQUARE);
    ASSERT_EQ(rvecs.size(), 2u);
    for (int k = 0; k < 2; ++k) {
      cv::Matx33d R;
      cv::Rodrigues(rvecs[k], R);
      const cv::Vec3d t(tvecs[k]);
      // Same pair, possibly in the other order.
      const double d0 = rotation_angle_deg(R, ours[0].R), d1 = rotation_angle_deg(R, ours[1].R);
      const Pose& match = d0 < d1 ? ours[0] : ours[1];
      EXPECT_LT(std::min(d0, d1), 1e-4);
      EXPECT_LT(cv::norm(match.t - t), 1e-6 * cv::norm(t));
    }
  }
}

TEST(MarkersPose, RefinementAgreesWithOpenCVsLM) {
  const CameraModel cam = camera640();
  fest::Rng rng(7);
  for (int i = 0; i < 30; ++i) {
    const Pose truth = pose_facing(cam, rng.uniform(100, 540), rng.uniform(100, 380), rng.uniform(0.3, 1.5),
                                   rng.uniform(10, 60), rng.uniform(0, 360), rng.uniform(0, 360));
    Corners px = project_corners(cam, truth, 0.1);
    for (cv::Point2d& p : px) p += cv::Point2d(rng.normal() * 0.3, rng.normal() * 0.3);
    const SquarePose ours = estimate_square_pose(cam, px, 0.1);
    const auto obj = square_object_points(0.1);
    std::vector<cv::Point3d> o(obj.begin(), obj.end());
    std::vector<cv::Point2d> img(px.begin(), px.end());
    cv::Mat rvec(rotation_vector(ours.pose.R)), tvec(ours.pose.t);
    rvec = rvec.clone();
    tvec = tvec.clone();
    cv::Mat r2 = rvec.clone(), t2 = tvec.clone();
    cv::solvePnPRefineLM(o, img, cv::Mat(cam.K), cv::Mat(), r2, t2,
                         cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-12));
    // Our optimum is OpenCV's: its LM started there does not move.
    EXPECT_LT(cv::norm(r2 - rvec), 1e-6);
    EXPECT_LT(cv::norm(t2 - tvec), 1e-6 * cv::norm(tvec));
    EXPECT_LE(ours.rms_px, ours.alternative_rms_px);
  }
}

TEST(MarkersPose, DistortedCornersAreUndistortedFirst) {
  CameraModel cam = camera640();
  cam.dist = cv::Vec<double, 5>(-0.25, 0.1, 0.001, -0.001, 0);
  const Pose truth = pose_facing(cam, 520, 400, 0.6, 30, 45, 10);
  const Corners px = project_corners(cam, truth, 0.08);
  const SquarePose p = estimate_square_pose(cam, px, 0.08);
  EXPECT_LT(rotation_angle_deg(p.pose.R, truth.R), 1e-5);
  EXPECT_LT(cv::norm(p.pose.t - truth.t), 1e-8);
}
