#pragma once
// Turntable calibration (docs/capture.md §5): a chessboard lying on the table, seen
// at several commanded angles, gives the table's rotation axis and its centre, that is
// the pose (R_T0, t_T0) of the turntable frame T at angle 0 in the camera frame C
// (docs/capture.md §1: X_C = R_T0 Rz(theta) X_T + t_T0).

#include <vector>

#include <opencv2/core.hpp>

#include "capture/calib_board.hpp"

namespace fest::capture {

struct TurntableCalibration {
  cv::Matx33d R_T0 = cv::Matx33d::eye();  // columns: T's x, y, z (z = axis) in C
  cv::Vec3d t_T0 = cv::Vec3d(0, 0, 0);    // axis point at the table top (board plane), mm
  cv::Vec3d axis = cv::Vec3d(0, 0, 1);    // unit; positive angles turn counter-clockwise about it
  double axis_spread_deg = 0;             // RMS angle between the axes of single view pairs and `axis`
  double angle_rms_deg = 0;               // RMS of angle_residual_deg
  std::vector<double> measured_deg;       // rotation of each view about the axis, zero matched to the commands
  std::vector<double> angle_residual_deg; // measured - commanded
  std::vector<double> circle_rms_mm;      // per view: RMS distance of its corners from their fitted circles
  std::vector<double> height_rms_mm;      // per view: RMS distance of its corners from the table plane
};

// `poses`: board -> camera per view (board_pose); `angles_deg`: the angle commanded (or
// executed, from the manifest) for each view. Needs >= 3 views spanning >= 20 degrees.
// Throws fest::Error (bad_input) for too few or degenerate views.
TurntableCalibration calibrate_turntable(const std::vector<Pose>& poses, const std::vector<double>& angles_deg,
                                         const BoardSpec& board);

}  // namespace fest::capture
