#include "markers/pose.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>

namespace fest::markers {

std::array<cv::Point3d, 4> square_object_points(double side) {
  const double h = side / 2;
  return {cv::Point3d(-h, h, 0), cv::Point3d(h, h, 0), cv::Point3d(h, -h, 0), cv::Point3d(-h, -h, 0)};
}

Corners normalise_corners(const CameraModel& camera, const Corners& pixels) {
  std::vector<cv::Point2d> in(pixels.begin(), pixels.end()), out;
  cv::undistortPoints(in, out, cv::Mat(camera.K), cv::Mat(camera.dist), cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-12));
  Corners c;
  for (int i = 0; i < 4; ++i) c[i] = out[i];
  return c;
}

cv::Matx33d rotation_from_vector(const cv::Vec3d& w) {
  const double theta = cv::norm(w);
  const cv::Matx33d W(0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0);
  if (theta < 1e-12) return cv::Matx33d::eye() + W;
  const double a = std::sin(theta) / theta, b = (1 - std::cos(theta)) / (theta * theta);
  return cv::Matx33d::eye() + a * W + b * (W * W);
}

cv::Vec3d rotation_vector(const cv::Matx33d& R) {
  cv::Vec3d w;
  cv::Rodrigues(R, w);
  return w;
}

double rotation_angle_deg(const cv::Matx33d& a, const cv::Matx33d& b) {
  const cv::Matx33d d = a.t() * b;
  const double c = std::clamp((cv::trace(d) - 1) / 2, -1.0, 1.0);
  return std::acos(c) * 180.0 / M_PI;
}

namespace {

// Plane (x, y) -> normalised image homography through the 4 correspondences (DLT with
// h22 = 1; exact for four points in general position).
cv::Matx33d homography4(const std::array<cv::Point3d, 4>& object, const Corners& image) {
  cv::Matx<double, 8, 8> A;
  cv::Matx<double, 8, 1> b;
  for (int i = 0; i < 4; ++i) {
    const double x = object[i].x, y = object[i].y, u = image[i].x, v = image[i].y;
    const double r0[8] = {x, y, 1, 0, 0, 0, -u * x, -u * y};
    const double r1[8] = {0, 0, 0, x, y, 1, -v * x, -v * y};
    for (int j = 0; j < 8; ++j) {
      A(2 * i, j) = r0[j];
      A(2 * i + 1, j) = r1[j];
    }
    b(2 * i) = u;
    b(2 * i + 1) = v;
  }
  cv::Matx<double, 8, 1> h;
  cv::solve(A, b, h, cv::DECOMP_LU);
  return cv::Matx33d(h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), 1);
}

// Least-squares t for a known R: u_i (r3.X_i + tz) = r1.X_i + tx, likewise v.
cv::Vec3d translation_for(const cv::Matx33d& R, const std::array<cv::Point3d, 4>& object, const Corners& image) {
  cv::Matx<double, 8, 3> A;
  cv::Matx<double, 8, 1> b;
  for (int i = 0; i < 4; ++i) {
    const cv::Vec3d X = R * cv::Vec3d(object[i].x, object[i].y, object[i].z);
    const double u = image[i].x, v = image[i].y;
    A(2 * i, 0) = 1, A(2 * i, 1) = 0, A(2 * i, 2) = -u;
    A(2 * i + 1, 0) = 0, A(2 * i + 1, 1) = 1, A(2 * i + 1, 2) = -v;
    b(2 * i) = u * X[2] - X[0];
    b(2 * i + 1) = v * X[2] - X[1];
  }
  cv::Matx<double, 3, 1> t;
  cv::solve(A, b, t, cv::DECOMP_SVD);
  return {t(0), t(1), t(2)};
}

void residuals(const Pose& p, const std::array<cv::Point3d, 4>& object, const Corners& image, double fx, double fy,
               double r[8]) {
  for (int i = 0; i < 4; ++i) {
    const cv::Vec3d X = p.R * cv::Vec3d(object[i].x, object[i].y, object[i].z) + p.t;
    const double z = std::abs(X[2]) < 1e-12 ? 1e-12 : X[2];
    r[2 * i] = fx * (X[0] / z - image[i].x);
    r[2 * i + 1] = fy * (X[1] / z - image[i].y);
  }
}

double sum_sq(const double r[8]) {
  double s = 0;
  for (int i = 0; i < 8; ++i) s += r[i] * r[i];
  return s;
}

Pose apply(const Pose& p, const cv::Vec<double, 6>& d) {
  Pose q;
  q.R = rotation_from_vector(cv::Vec3d(d[0], d[1], d[2])) * p.R;
  q.t = p.t + cv::Vec3d(d[3], d[4], d[5]);
  return q;
}

}  // namespace

// IPPE (Collins & Bartoli 2014, §4): with the plane points centred on the origin, the
// homography H maps the origin to v = (h02, h12) / h22 and has the Jacobian J there
// (eq. 11). R_v turns the optical axis onto the ray through v (eq. 14), B = [I | -v] R_v
// restricted to two columns (eq. 15), A = B^-1 J; gamma, the largest singular value of
// A, is the inverse depth scale and R~ = A / gamma the upper-left 2x2 block of the
// rotation; the third row (b0, b1) is fixed up to one sign, giving the two solutions
// (eq. 17).
std::array<Pose, 2> ippe_square(const Corners& image, double side) {
  const std::array<cv::Point3d, 4> object = square_object_points(side);
  const cv::Matx33d H = homography4(object, image);
  const double v0 = H(0, 2), v1 = H(1, 2);  // h22 = 1
  const double j00 = H(0, 0) - H(2, 0) * v0, j01 = H(0, 1) - H(2, 1) * v0;
  const double j10 = H(1, 0) - H(2, 0) * v1, j11 = H(1, 1) - H(2, 1) * v1;

  // R_v: the rotation about the axis e3 x (v, 1) that takes e3 onto the unit ray.
  cv::Vec3d ray(v0, v1, 1);
  ray /= cv::norm(ray);
  const cv::Vec3d axis = cv::Vec3d(0, 0, 1).cross(ray);
  const double s = cv::norm(axis);
  cv::Matx33d Rv = cv::Matx33d::eye();
  if (s > 1e-15) Rv = rotation_from_vector(axis * (std::atan2(s, ray[2]) / s));

  const double b00 = Rv(0, 0) - v0 * Rv(2, 0), b01 = Rv(0, 1) - v0 * Rv(2, 1);
  const double b10 = Rv(1, 0) - v1 * Rv(2, 0), b11 = Rv(1, 1) - v1 * Rv(2, 1);
  const double det = b00 * b11 - b01 * b10;
  const double i00 = b11 / det, i01 = -b01 / det, i10 = -b10 / det, i11 = b00 / det;
  const double a00 = i00 * j00 + i01 * j10, a01 = i00 * j01 + i01 * j11;
  const double a10 = i10 * j00 + i11 * j10, a11 = i10 * j01 + i11 * j11;
  const double q00 = a00 * a00 + a01 * a01, q01 = a00 * a10 + a01 * a11, q11 = a10 * a10 + a11 * a11;
  const double gamma = std::sqrt(0.5 * (q00 + q11 + std::sqrt((q00 - q11) * (q00 - q11) + 4 * q01 * q01)));
  const double r00 = a00 / gamma, r01 = a01 / gamma, r10 = a10 / gamma, r11 = a11 / gamma;
  const double c0 = std::sqrt(std::max(0.0, 1 - r00 * r00 - r10 * r10));
  double c1 = std::sqrt(std::max(0.0, 1 - r01 * r01 - r11 * r11));
  if (-r00 * r01 - r10 * r11 < 0) c1 = -c1;

  std::array<Pose, 2> out;
  for (int k = 0; k < 2; ++k) {
    const double sgn = k == 0 ? 1 : -1;
    const cv::Vec3d col0(r00, r10, sgn * c0), col1(r01, r11, sgn * c1);
    const cv::Vec3d col2 = col0.cross(col1);
    const cv::Matx33d local(col0[0], col1[0], col2[0], col0[1], col1[1], col2[1], col0[2], col1[2], col2[2]);
    out[k].R = Rv * local;
    out[k].t = translation_for(out[k].R, object, image);
  }
  return out;
}

Pose refine_pose(const Pose& start, const std::array<cv::Point3d, 4>& object, const Corners& image, double fx,
                 double fy, int iterations) {
  Pose p = start;
  double r[8];
  residuals(p, object, image, fx, fy, r);
  double cost = sum_sq(r);
  double lambda = 1e-3;
  const double scale = std::max(1e-9, cv::norm(p.t));
  for (int it = 0; it < iterations && cost > 1e-24; ++it) {
    // Jacobian by central differences (6 unknowns, 8 residuals: cheap and exact enough).
    cv::Matx<double, 8, 6> J;
    for (int k = 0; k < 6; ++k) {
      const double h = k < 3 ? 1e-7 : 1e-7 * scale;
      cv::Vec<double, 6> d = cv::Vec<double, 6>::all(0);
      d[k] = h;
      double rp[8], rm[8];
      residuals(apply(p, d), object, image, fx, fy, rp);
      d[k] = -h;
      residuals(apply(p, d), object, image, fx, fy, rm);
      for (int i = 0; i < 8; ++i) J(i, k) = (rp[i] - rm[i]) / (2 * h);
    }
    const cv::Matx<double, 6, 6> JtJ = J.t() * J;
    const cv::Matx<double, 8, 1> rv(r);
    const cv::Matx<double, 6, 1> g = J.t() * rv;
    bool improved = false;
    for (int tries = 0; tries < 10 && !improved; ++tries) {
      cv::Matx<double, 6, 6> Aug = JtJ;
      for (int k = 0; k < 6; ++k) Aug(k, k) += lambda * std::max(JtJ(k, k), 1e-12);
      cv::Matx<double, 6, 1> step;
      if (!cv::solve(Aug, -g, step, cv::DECOMP_CHOLESKY)) break;
      const Pose q = apply(p, cv::Vec<double, 6>(step.val));
      double rq[8];
      residuals(q, object, image, fx, fy, rq);
      const double cq = sum_sq(rq);
      if (cq < cost) {
        p = q;
        std::copy(rq, rq + 8, r);
        const bool tiny = cost - cq < 1e-14 * cost;
        cost = cq;
        lambda = std::max(lambda / 10, 1e-9);
        improved = true;
        if (tiny) return p;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  return p;
}

double reprojection_rms_px(const CameraModel& camera, const Pose& pose, const std::array<cv::Point3d, 4>& object,
                           const Corners& pixels) {
  std::vector<cv::Point3d> obj(object.begin(), object.end());
  std::vector<cv::Point2d> proj;
  cv::projectPoints(obj, rotation_vector(pose.R), pose.t, cv::Mat(camera.K), cv::Mat(camera.dist), proj);
  double s = 0;
  for (int i = 0; i < 4; ++i) {
    const cv::Point2d d = proj[i] - pixels[i];
    s += d.dot(d);
  }
  return std::sqrt(s / 4);
}

SquarePose estimate_square_pose(const CameraModel& camera, const Corners& pixels, double side) {
  const Corners image = normalise_corners(camera, pixels);
  const std::array<cv::Point3d, 4> object = square_object_points(side);
  const std::array<Pose, 2> start = ippe_square(image, side);
  std::array<Pose, 2> refined;
  std::array<double, 2> rms;
  for (int k = 0; k < 2; ++k) {
    refined[k] = refine_pose(start[k], object, image, camera.K(0, 0), camera.K(1, 1));
    rms[k] = reprojection_rms_px(camera, refined[k], object, pixels);
  }
  const int best = rms[1] < rms[0] ? 1 : 0;
  SquarePose out;
  out.pose = refined[best];
  out.alternative = refined[1 - best];
  out.rms_px = rms[best];
  out.alternative_rms_px = rms[1 - best];
  return out;
}

}  // namespace fest::markers
