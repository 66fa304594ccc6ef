#include "reflectance/camera.hpp"

#include <cmath>

namespace fest::reflectance {

Eigen::Vector2d PinholeCamera::project_distorted(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d xc = to_camera(world);
  const double x = xc.x() / xc.z(), y = xc.y() / xc.z();
  const double r2 = x * x + y * y;
  const double radial = 1 + dist[0] * r2 + dist[1] * r2 * r2 + dist[4] * r2 * r2 * r2;
  const double xd = x * radial + 2 * dist[2] * x * y + dist[3] * (r2 + 2 * x * x);
  const double yd = y * radial + dist[2] * (r2 + 2 * y * y) + 2 * dist[3] * x * y;
  return {fx * xd + cx, fy * yd + cy};
}

Eigen::Vector3d PinholeCamera::ray_direction(double u, double v) const {
  const Eigen::Vector3d dc((u - cx) / fx, (v - cy) / fy, 1.0);
  return (R.transpose() * dc).normalized();
}

bool PinholeCamera::has_distortion() const {
  for (double d : dist)
    if (d != 0) return true;
  return false;
}

PinholeCamera scaled_camera(const PinholeCamera& cam, double s) {
  PinholeCamera c = cam;
  c.fx = cam.fx * s;
  c.fy = cam.fy * s;
  // Pixel centres at integers: the continuous image coordinate x + 0.5 scales by s.
  c.cx = (cam.cx + 0.5) * s - 0.5;
  c.cy = (cam.cy + 0.5) * s - 0.5;
  c.width = static_cast<int>(std::ceil(cam.width * s));
  c.height = static_cast<int>(std::ceil(cam.height * s));
  return c;
}

Eigen::Matrix3d look_at_rotation(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d z = (target - eye).normalized();
  Eigen::Vector3d x = z.cross(up);  // right = forward x up; then y = forward x right = down
  if (x.norm() < 1e-12) x = z.unitOrthogonal();
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  return R;
}

}  // namespace fest::reflectance
