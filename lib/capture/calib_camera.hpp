#pragma once
// Camera intrinsics from chessboard views (Zhang's method through cv::calibrateCamera;
// docs/capture.md §5, seed 000 §8.3.3's [Zha99]): K, the 5 distortion coefficients and
// the RMS reprojection error, as brdffit's cam.json carries them.

#include <vector>

#include <opencv2/core.hpp>

#include "capture/calib_board.hpp"

namespace fest::capture {

struct CameraCalibOptions {
  bool fix_k3 = false;        // k3 = 0: few or frontal views cannot separate k3 from k1, k2
  bool zero_tangent = false;  // p1 = p2 = 0
};

struct CameraCalibration {
  Intrinsics intrinsics;
  double rms = 0;                  // RMS reprojection error over all corners, pixels
  std::vector<double> view_rms;    // the same per view
  std::vector<Pose> poses;         // board -> camera per view
};

// At least 3 views (Zhang: two views fix K only with zero skew and a known centre).
// Throws fest::Error: bad_input for too few views, failure when OpenCV's solver fails.
CameraCalibration calibrate_camera(const std::vector<std::vector<cv::Point2f>>& views, const BoardSpec& board,
                                   cv::Size image_size, const CameraCalibOptions& options = {});

// RMS distance, pixels, between detected corners and the board projected at `pose`.
double reprojection_rms(const std::vector<cv::Point2f>& corners, const BoardSpec& board, const Intrinsics& camera,
                        const Pose& pose);

// The board's pose from one view (cv::solvePnP, iterative, on the distortion-aware
// projection). Throws fest::Error (failure) when no pose is found.
Pose board_pose(const std::vector<cv::Point2f>& corners, const BoardSpec& board, const Intrinsics& camera);

}  // namespace fest::capture
