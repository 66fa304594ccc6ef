#pragma once
// Synthetic calibration images with known geometry, the ground truth of the calibration
// tests (docs/capture.md §6): a chessboard and chrome spheres rendered through a
// pinhole camera with OpenCV's distortion model, anti-aliased by supersampling.

#include <vector>

#include <opencv2/core.hpp>

#include "capture/calib_board.hpp"

namespace fest::capture {

// Unit-depth ray directions (x, y, 1) of a regular grid of sub-pixel sample positions,
// undistorted: row-major, `samples` x `samples` per pixel.
class PixelRays {
 public:
  PixelRays(const Intrinsics& camera, int samples);
  cv::Vec3d ray(int x, int y, int sx, int sy) const;
  int samples() const { return samples_; }

 private:
  int samples_, width_, height_;
  cv::Mat corners_;  // CV_64FC2, (height+1) x (width+1): undistorted pixel corners
};

// The board at pose board -> camera, 8-bit grey: squares 0.1 (dark) and 0.9, the cell
// between inner corners 0, 1, cols, cols+1 dark, a white margin one square wide, the
// rest mid grey. The printed side faces -z of the board frame.
cv::Mat render_board(const Intrinsics& camera, const BoardSpec& board, const Pose& pose, int samples = 4);

struct Sphere {
  cv::Vec3d centre;
  double radius = 25;
};

// Chrome spheres lit by a point light, 16-bit grey: background 0.02, sphere 0.3 (the
// dark studio it mirrors), plus a highlight lobe exp(-theta^2 / 2 sigma^2) * 0.65 where
// theta is the angle between the mirrored viewing ray and the direction to the light.
cv::Mat render_spheres(const Intrinsics& camera, const std::vector<Sphere>& spheres, const cv::Vec3d& light,
                       double lobe_sigma_deg = 2.0, int samples = 4);

// Where the mirror reflection of `light` appears on the sphere: the point h with
// normal bisecting the directions to the camera (origin) and to the light.
cv::Vec3d mirror_point(const Sphere& sphere, const cv::Vec3d& light);

}  // namespace fest::capture
