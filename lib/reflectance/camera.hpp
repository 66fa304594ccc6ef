#pragma once
// The calibrated pinhole camera of docs/brdffit.md §1 and fest-capture(5) (cam.json):
// intrinsics K (fx, fy, cx, cy), OpenCV distortion (k1, k2, p1, p2, k3), extrinsics R, t
// mapping world to camera (x_cam = R x + t), image size. Pixel centres lie at integer
// coordinates (OpenCV's convention): pixel (i, j) covers [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5].
// The camera looks along +z_cam; x right, y down.

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::reflectance {

struct PinholeCamera {
  double fx = 1, fy = 1, cx = 0, cy = 0;
  std::array<double, 5> dist{};  // k1, k2, p1, p2, k3
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  int width = 0, height = 0;

  Eigen::Vector3d to_camera(const Eigen::Vector3d& world) const { return R * world + t; }
  // c = -R^T t, the centre of projection in world coordinates.
  Eigen::Vector3d centre() const { return -R.transpose() * t; }
  // Ideal (undistorted) projection of a camera-frame point with z > 0.
  Eigen::Vector2d project_camera(const Eigen::Vector3d& xc) const {
    return {fx * xc.x() / xc.z() + cx, fy * xc.y() / xc.z() + cy};
  }
  // Projection of a world point as the real lens images it (distortion applied): where to
  // read a photograph. Rendering uses the ideal projection (the images of docs/brdffit.md §1 are
  // "pinhole after distortion correction"; with dist = 0 both agree).
  Eigen::Vector2d project_distorted(const Eigen::Vector3d& world) const;
  // World direction (unit) of the ray through ideal pixel coordinates (u, v).
  Eigen::Vector3d ray_direction(double u, double v) const;
  bool has_distortion() const;
};

// A camera of the same pose whose image is scaled by `s` (image pyramids): focal lengths
// and principal point follow the pixel-centre convention, size rounds up.
PinholeCamera scaled_camera(const PinholeCamera& cam, double s);

// Rotation looking from `eye` towards `target` with `up` roughly up in the image
// (image y points down, so camera y = -up projected).
Eigen::Matrix3d look_at_rotation(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up);

}  // namespace fest::reflectance
