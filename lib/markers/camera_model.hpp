#pragma once
// The calibrated camera markerpose measures with: OpenCV's pinhole model with the five
// distortion coefficients k1, k2, p1, p2, k3, at one image size (the camera.json of
// `capture calib-camera`).

#include <opencv2/core.hpp>

namespace fest::markers {

struct CameraModel {
  cv::Matx33d K = cv::Matx33d::eye();
  cv::Vec<double, 5> dist = cv::Vec<double, 5>::all(0);
  int width = 0, height = 0;

  bool has_distortion() const { return cv::norm(dist) != 0; }
};

// X_c = R X_m + t: marker (or model) frame to camera frame. The marker frame has its
// origin at the marker's centre, x to the right and y up on the printed marker, z out of
// the paper towards the viewer (OpenCV ArUco's convention).
struct Pose {
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d t = cv::Vec3d(0, 0, 0);
};

}  // namespace fest::markers
