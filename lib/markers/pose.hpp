#pragma once
// 6-DoF pose of a square marker from its four corners (docs/markerpose.md §4):
// Infinitesimal Plane-based Pose Estimation (IPPE, Collins & Bartoli, IJCV 2014) gives
// the two poses that explain the homography's first-order behaviour at the square's
// centre in closed form; each is refined by Levenberg-Marquardt on the reprojection
// error, and the better one is kept, the other reported as the alternative (the
// planar ambiguity that a sequence resolves, tracker.hpp).

#include <array>

#include <opencv2/core.hpp>

#include "markers/camera_model.hpp"

namespace fest::markers {

using Corners = std::array<cv::Point2d, 4>;  // top-left, top-right, bottom-right, bottom-left of the marker

// The corners in the marker frame, z = 0: (-s/2, s/2), (s/2, s/2), (s/2, -s/2), (-s/2, -s/2).
std::array<cv::Point3d, 4> square_object_points(double side);

// Corners in normalised (undistorted, K removed) image coordinates.
Corners normalise_corners(const CameraModel& camera, const Corners& pixels);

// The two IPPE poses of a square of side `side` seen at normalised corners `image`
// (Collins & Bartoli eqs. 11-17 for the rotation, least squares for t).
std::array<Pose, 2> ippe_square(const Corners& image, double side);

// Levenberg-Marquardt on the reprojection error in ideal pixels (normalised residuals
// times fx, fy); rotation updated on the manifold (R <- exp([w]x) R).
Pose refine_pose(const Pose& start, const std::array<cv::Point3d, 4>& object, const Corners& image, double fx,
                 double fy, int iterations = 20);

// RMS pixel distance between `pixels` and the object points projected at `pose`
// through the camera's distortion (cv::projectPoints).
double reprojection_rms_px(const CameraModel& camera, const Pose& pose, const std::array<cv::Point3d, 4>& object,
                           const Corners& pixels);

struct SquarePose {
  Pose pose;              // the lower-error solution
  Pose alternative;       // the other IPPE branch, refined
  double rms_px = 0;      // reprojection RMS of `pose` (distorted pixels)
  double alternative_rms_px = 0;
};

SquarePose estimate_square_pose(const CameraModel& camera, const Corners& pixels, double side);

// Angle of R_a^T R_b in degrees.
double rotation_angle_deg(const cv::Matx33d& a, const cv::Matx33d& b);
// Rodrigues vector of R.
cv::Vec3d rotation_vector(const cv::Matx33d& R);
cv::Matx33d rotation_from_vector(const cv::Vec3d& w);

}  // namespace fest::markers
