#include "capture/calib_turntable.hpp"

#include <cmath>

#include <opencv2/calib3d.hpp>

#include "core/error.hpp"

namespace fest::capture {

namespace {

constexpr double kPi = 3.14159265358979323846;
double deg(double rad) { return rad * 180 / kPi; }
double rad(double deg) { return deg * kPi / 180; }
double wrap_pi(double a) { return std::remainder(a, 2 * kPi); }

// Rotation by `angle` about the unit vector `a` (Rodrigues).
cv::Matx33d rotation_about(const cv::Vec3d& a, double angle) {
  cv::Mat R;
  cv::Rodrigues(cv::Mat(a * angle), R);
  return cv::Matx33d(R);
}

// log map: the rotation vector (axis times angle, angle in [0, pi]).
cv::Vec3d log_map(const cv::Matx33d& R) {
  cv::Mat v;
  cv::Rodrigues(cv::Mat(R), v);
  return cv::Vec3d(v.at<double>(0), v.at<double>(1), v.at<double>(2));
}

// sin(angle) * axis: vee(R - R^T) / 2, which keeps the sense of turns below half a turn.
cv::Vec3d sin_axis(const cv::Matx33d& R) {
  return cv::Vec3d(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1)) * 0.5;
}

// Rotation angle of R about the unit axis a, in (-pi, pi].
double angle_about(const cv::Matx33d& R, const cv::Vec3d& a) {
  return std::atan2(sin_axis(R).dot(a), (cv::trace(R) - 1) * 0.5);
}

// Least-squares axis of all relative rotations R_l R_k^T (k < l): the direction
// that maximises sum (omega . a)^2 over their rotation vectors omega -- the principal
// eigenvector; pairs with larger turns weigh more, as their axes are better defined.
cv::Vec3d fit_axis(const std::vector<Pose>& poses, const std::vector<double>& angles, double& spread_deg) {
  cv::Matx33d M = cv::Matx33d::zeros();
  for (std::size_t k = 0; k < poses.size(); ++k)
    for (std::size_t l = k + 1; l < poses.size(); ++l) {
      const cv::Vec3d w = log_map(poses[l].R * poses[k].R.t());
      M += w * w.t();
    }
  cv::Mat values, vectors;
  cv::eigen(cv::Mat(M), values, vectors);
  cv::Vec3d a(vectors.at<double>(0, 0), vectors.at<double>(0, 1), vectors.at<double>(0, 2));
  // The sense: commanded turns of less than half a revolution must come out positive.
  double sense = 0, spread = 0, weight = 0;
  for (std::size_t k = 0; k < poses.size(); ++k)
    for (std::size_t l = k + 1; l < poses.size(); ++l) {
      const cv::Matx33d Rkl = poses[l].R * poses[k].R.t();
      sense += std::sin(rad(angles[l] - angles[k])) * sin_axis(Rkl).dot(a);
      const cv::Vec3d w = log_map(Rkl);
      const double n = cv::norm(w);
      if (n > rad(10)) {  // small turns have ill-defined axes: leave them out of the spread
        const double c = std::min(1.0, std::abs(w.dot(a)) / n);
        spread += n * n * std::acos(c) * std::acos(c);
        weight += n * n;
      }
    }
  if (sense < 0) a = -a;
  spread_deg = weight > 0 ? deg(std::sqrt(spread / weight)) : 0;
  return a / cv::norm(a);
}

}  // namespace

TurntableCalibration calibrate_turntable(const std::vector<Pose>& poses, const std::vector<double>& angles_deg,
                                         const BoardSpec& board) {
  const std::size_t n = poses.size();
  if (n != angles_deg.size())
    throw bad_input("{} board views for {} turntable angles", n, angles_deg.size());
  if (n < 3) throw bad_input("{} board view{}; turntable calibration needs at least 3", n, n == 1 ? "" : "s");
  double lo = angles_deg[0], hi = angles_deg[0];
  for (double a : angles_deg) lo = std::min(lo, a), hi = std::max(hi, a);
  if (hi - lo < 20)
    throw bad_input("the views span {:.3g} degrees of turntable angle; at least 20 are needed", hi - lo);

  TurntableCalibration cal;
  cal.axis = fit_axis(poses, angles_deg, cal.axis_spread_deg);
  const cv::Vec3d a = cal.axis;

  // Measured turn of each view relative to view 0, then one common offset (the zero
  // of the commanded angles is arbitrary) fitted as a circular mean.
  std::vector<double> relative(n);
  double s = 0, c = 0;
  for (std::size_t k = 0; k < n; ++k) {
    relative[k] = angle_about(poses[k].R * poses[0].R.t(), a);
    const double d = wrap_pi(relative[k] - rad(angles_deg[k] - angles_deg[0]));
    s += std::sin(d), c += std::cos(d);
  }
  const double offset = std::atan2(s, c);
  double sum2 = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double residual = wrap_pi(relative[k] - rad(angles_deg[k] - angles_deg[0]) - offset);
    cal.angle_residual_deg.push_back(deg(residual));
    cal.measured_deg.push_back(angles_deg[k] + deg(residual));
    sum2 += residual * residual;
  }
  cal.angle_rms_deg = deg(std::sqrt(sum2 / double(n)));

  // A basis of the plane perpendicular to the axis.
  const cv::Vec3d helper = std::abs(a[0]) < 0.9 ? cv::Vec3d(1, 0, 0) : cv::Vec3d(0, 1, 0);
  const cv::Vec3d u = cv::normalize(helper - a * a.dot(helper));
  const cv::Vec3d v = a.cross(u);

  // Every corner j travels on a circle about the axis: one shared centre (cu, cv),
  // one radius per corner. Kasa's algebraic fit is linear in (cu, cv, e_j):
  //   x^2 + y^2 = 2 cu x + 2 cv y + e_j,   r_j^2 = e_j + cu^2 + cv^2.
  const std::vector<cv::Point3f> object = board_object_points(board);
  const int m = int(object.size());
  cv::Mat A = cv::Mat::zeros(int(n) * m, 2 + m, CV_64F), b(int(n) * m, 1, CV_64F);
  std::vector<std::vector<cv::Vec3d>> X(n);
  double height = 0;
  for (std::size_t k = 0; k < n; ++k)
    for (int j = 0; j < m; ++j) {
      const cv::Vec3d P(object[std::size_t(j)].x, object[std::size_t(j)].y, object[std::size_t(j)].z);
      const cv::Vec3d x = poses[k].R * P + poses[k].t;
      X[k].push_back(x);
      const double px = x.dot(u), py = x.dot(v);
      const int row = int(k) * m + j;
      A.at<double>(row, 0) = 2 * px;
      A.at<double>(row, 1) = 2 * py;
      A.at<double>(row, 2 + j) = 1;
      b.at<double>(row) = px * px + py * py;
      height += x.dot(a);
    }
  height /= double(n) * m;
  cv::Mat sol;
  if (!cv::solve(A, b, sol, cv::DECOMP_QR))
    throw bad_input("the board positions do not determine a circle about the axis (too little turn?)");
  const double cu = sol.at<double>(0), cv_ = sol.at<double>(1);
  cal.t_T0 = u * cu + v * cv_ + a * height;

  for (std::size_t k = 0; k < n; ++k) {
    double circle = 0, plane = 0;
    for (int j = 0; j < m; ++j) {
      const double r2 = sol.at<double>(2 + j) + cu * cu + cv_ * cv_;
      const cv::Vec3d d = X[k][std::size_t(j)] - cal.t_T0;
      const double h = d.dot(a);
      const double radial = std::sqrt(std::max(0.0, d.dot(d) - h * h)) - std::sqrt(std::max(0.0, r2));
      circle += radial * radial;
      plane += h * h;
    }
    cal.circle_rms_mm.push_back(std::sqrt(circle / m));
    cal.height_rms_mm.push_back(std::sqrt(plane / m));
  }

  // T's x axis: the board's x axis at angle 0 -- each view's, turned back by its measured
  // angle about the axis, averaged in the plane of the table.
  cv::Vec3d x0(0, 0, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const cv::Vec3d bx(poses[k].R(0, 0), poses[k].R(1, 0), poses[k].R(2, 0));
    x0 += rotation_about(a, -rad(cal.measured_deg[k])) * bx;
  }
  x0 -= a * a.dot(x0);
  if (cv::norm(x0) < 1e-9) throw bad_input("the board lies perpendicular to the table; lay it flat on the table top");
  x0 = cv::normalize(x0);
  const cv::Vec3d y0 = a.cross(x0);
  cal.R_T0 = cv::Matx33d(x0[0], y0[0], a[0], x0[1], y0[1], a[1], x0[2], y0[2], a[2]);
  return cal;
}

}  // namespace fest::capture
