#pragma once
// Known geometry for the calibration tests (docs/capture.md §6): cameras, a turntable
// with a board lying on it, chrome spheres and a light. Lengths in mm.

#include <cmath>
#include <iterator>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "capture/calib_board.hpp"
#include "capture/calib_synth.hpp"

namespace fest::test {

constexpr double kPi = 3.14159265358979323846;
inline double rad(double deg) { return deg * kPi / 180; }

inline capture::Intrinsics camera(double f, int w, int h, double k1 = 0, double k2 = 0) {
  capture::Intrinsics c;
  c.K = cv::Matx33d(f, 0, w / 2.0 + 3.5, 0, f * 0.995, h / 2.0 - 2.5, 0, 0, 1);
  c.dist = cv::Vec<double, 5>(k1, k2, 0, 0, 0);
  c.width = w;
  c.height = h;
  return c;
}

inline cv::Matx33d rot(const cv::Vec3d& axis, double deg) {
  cv::Mat R;
  cv::Rodrigues(cv::Mat(cv::normalize(axis) * rad(deg)), R);
  return cv::Matx33d(R);
}

// A turntable seen from 40 degrees above the table plane, axis slightly tilted.
struct TurntableScene {
  cv::Matx33d R_T0;
  cv::Vec3d t_T0{15, 30, 550};
  cv::Matx33d R_BT;  // board -> table: lying flat, printed side up, turned 10 degrees
  cv::Vec3d t_BT;
  capture::BoardSpec board{9, 6, 25};

  TurntableScene() {
    const double e = rad(40);
    const cv::Vec3d a = cv::normalize(cv::Vec3d(0.03, -std::cos(e), -std::sin(e)));
    const cv::Vec3d x = cv::normalize(cv::Vec3d(1, 0, 0) - a * a[0]);
    const cv::Vec3d y = a.cross(x);
    R_T0 = cv::Matx33d(x[0], y[0], a[0], x[1], y[1], a[1], x[2], y[2], a[2]);
    R_BT = rot({0, 0, 1}, 10) * cv::Matx33d(1, 0, 0, 0, -1, 0, 0, 0, -1);
    const cv::Vec3d centre(4 * 25, 2.5 * 25, 0);
    t_BT = cv::Vec3d(20, 10, 0) - R_BT * centre;
  }
  cv::Vec3d axis() const { return cv::Vec3d(R_T0(0, 2), R_T0(1, 2), R_T0(2, 2)); }
  capture::Pose board_pose(double theta_deg) const {
    const cv::Matx33d Rz = rot({0, 0, 1}, theta_deg);
    return capture::Pose{R_T0 * Rz * R_BT, R_T0 * (Rz * t_BT) + t_T0};
  }
};

// Ten views of a 9x6x25mm board about 0.5 m away, tilted up to 35 degrees about both
// image axes: what a camera calibration session looks like.
inline std::vector<capture::Pose> calibration_poses() {
  std::vector<capture::Pose> poses;
  const cv::Vec3d centre(4 * 25, 2.5 * 25, 0);
  const double tilts[][2] = {{0, 0}, {30, 0}, {-30, 0}, {0, 30}, {0, -30}, {25, 25}, {-25, 20}, {20, -25}, {-20, -30}, {35, 10}};
  for (std::size_t i = 0; i < std::size(tilts); ++i) {
    const cv::Matx33d R = rot({1, 0, 0}, tilts[i][0]) * rot({0, 1, 0}, tilts[i][1]) * rot({0, 0, 1}, 5.0 * double(i) - 20);
    const cv::Vec3d where(15.0 * double(i % 3) - 15, 10.0 * double(i % 2) - 5, 480 + 12.0 * double(i));
    poses.push_back(capture::Pose{R, where - R * centre});
  }
  return poses;
}

// Three chrome spheres of radius 25 mm about 0.5 m from the camera and the light.
struct SphereScene {
  std::vector<capture::Sphere> spheres{{{-110, -60, 520}, 25}, {{110, -50, 540}, 25}, {{-20, 90, 560}, 25}};
  cv::Vec3d light{200, -250, 180};
};

}  // namespace fest::test
