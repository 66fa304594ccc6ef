#include "brdffit/registration.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <opencv2/imgproc.hpp>

#include "brdffit/nelder_mead.hpp"
#include "core/error.hpp"
#include "reflectance/rasterizer.hpp"
#include "reflectance/silhouette_runs.hpp"

namespace fest::brdffit {

using reflectance::PinholeCamera;
using reflectance::TriangleMesh;

SilhouettePyramid make_pyramid(const cv::Mat& mask, int levels) {
  if (mask.empty() || mask.type() != CV_8U) throw bad_input("the silhouette mask must be an 8-bit image");
  SilhouettePyramid p;
  cv::Mat full = (mask > 0) / 255;  // 0/1
  for (int l = levels - 1; l >= 0; --l) {
    const double s = 1.0 / (1 << l);
    cv::Mat m;
    if (l == 0) {
      m = full.clone();
    } else {
      cv::Mat f, small;
      full.convertTo(f, CV_32F);
      cv::resize(f, small, cv::Size(static_cast<int>(std::ceil(mask.cols * s)), static_cast<int>(std::ceil(mask.rows * s))),
                 0, 0, cv::INTER_AREA);
      m = small >= 0.5f;
      m /= 255;
    }
    p.masks.push_back(m);
    p.scales.push_back(s);
    p.counts.push_back(cv::countNonZero(m));
    p.runs.push_back(reflectance::runs_of_mask(m.ptr<std::uint8_t>(0), m.cols, m.rows, m.step[0]));
  }
  if (p.counts.back() == 0) throw bad_input("the silhouette mask is empty");
  return p;
}

double silhouette_xor(const TriangleMesh& mesh, const PinholeCamera& camera, const SilhouettePyramid& pyramid,
                      std::size_t level, int threads) {
  const cv::Mat& m = pyramid.masks[level];
  PinholeCamera c = reflectance::scaled_camera(camera, pyramid.scales[level]);
  c.width = m.cols;
  c.height = m.rows;
  const std::size_t diff = reflectance::symmetric_difference(reflectance::silhouette_runs(mesh, c, threads), pyramid.runs[level]);
  return static_cast<double>(diff) / std::max(1.0, pyramid.counts[level]);
}

Eigen::VectorXd pose_parameters(const PinholeCamera& camera) {
  Eigen::VectorXd x(7);
  const Eigen::AngleAxisd aa(camera.R);
  x.head<3>() = aa.axis() * aa.angle();
  x.segment<3>(3) = camera.t;
  x[6] = std::log(camera.fx);
  return x;
}

namespace {

Eigen::Matrix3d rotation_of(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

double distance_of(const PinholeCamera& c, const TriangleMesh& mesh) {
  Eigen::Vector3d centre;
  double r = 0;
  reflectance::bounding_sphere(mesh, centre, r);
  return std::max(r, c.to_camera(centre).norm());
}

struct Candidate {
  Eigen::VectorXd x;
  double cost;
};

}  // namespace

PinholeCamera camera_from_parameters(const PinholeCamera& base, const Eigen::VectorXd& x) {
  PinholeCamera c = base;
  c.R = rotation_of(x.head<3>());
  c.t = x.segment<3>(3);
  c.fx = std::exp(x[6]);
  c.fy = c.fx * (base.fy / base.fx);
  return c;
}

std::vector<Eigen::Matrix3d> random_rotations(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Matrix3d> out;
  for (int i = 0; i < count; ++i) {
    const double u1 = u(rng), u2 = u(rng), u3 = u(rng);
    const Eigen::Quaterniond q(std::sqrt(u1) * std::cos(2 * M_PI * u3), std::sqrt(1 - u1) * std::sin(2 * M_PI * u2),
                               std::sqrt(1 - u1) * std::cos(2 * M_PI * u2), std::sqrt(u1) * std::sin(2 * M_PI * u3));
    out.push_back(q.normalized().toRotationMatrix());
  }
  return out;
}

RegistrationResult register_silhouette(const TriangleMesh& mesh, const cv::Mat& mask, const PinholeCamera& initial,
                                       const RegistrationOptions& o) {
  if (mask.cols != initial.width || mask.rows != initial.height)
    throw bad_input("the mask is {}x{} but the camera is {}x{}", mask.cols, mask.rows, initial.width, initial.height);
  const SilhouettePyramid pyr = make_pyramid(mask);
  RegistrationResult res;
  auto cost_at = [&](std::size_t level) {
    return [&, level](const Eigen::VectorXd& x) {
      ++res.evaluations;
      return silhouette_xor(mesh, camera_from_parameters(initial, x), pyr, level, o.threads);
    };
  };
  auto steps = [&](double distance, double shrink) {
    Eigen::VectorXd s(7);
    s.head<3>().setConstant(o.rotation_step_deg * M_PI / 180 * shrink);
    s.segment<3>(3).setConstant(o.translation_step * distance * shrink);
    s[6] = o.fix_focal ? 0.0 : o.focal_step * shrink;  // a zero step keeps f where it is
    return s;
  };

  // Progress in simplex runs: the coarse orientation search, then every candidate through
  // every level and the restarts.
  const std::uint64_t per_candidate = pyr.masks.size() + static_cast<std::uint64_t>(std::max(0, o.restarts));
  const std::uint64_t runs =
      o.automatic ? static_cast<std::uint64_t>(std::max(0, o.orient_samples)) +
                        per_candidate * static_cast<std::uint64_t>(std::max(1, std::min(o.keep, o.orient_samples)))
                  : per_candidate;
  std::uint64_t run = 0;
  const auto ran = [&](std::uint64_t n) {
    run += n;
    if (o.progress) o.progress(std::min(run, runs), runs);
  };
  std::vector<Candidate> candidates;
  if (!o.automatic) {
    candidates.push_back({pose_parameters(initial), 0});
  } else {
    // Chapter §8.6.2: the object centred, at the distance where its bounding sphere spans
    // 80 % of the shorter image side; orientations uniformly on SO(3).
    Eigen::Vector3d centre;
    double radius = 0;
    reflectance::bounding_sphere(mesh, centre, radius);
    const double d0 = initial.fx * 2 * radius / (0.8 * std::min(initial.width, initial.height));
    const cv::Moments mo = cv::moments(mask > 0, true);
    if (mo.m00 <= 0) throw bad_input("the silhouette mask is empty");
    const Eigen::Vector3d ray((mo.m10 / mo.m00 - initial.cx) / initial.fx, (mo.m01 / mo.m00 - initial.cy) / initial.fy, 1);
    for (const Eigen::Matrix3d& R : random_rotations(o.orient_samples, o.seed)) {
      PinholeCamera c = initial;
      c.R = R;
      c.t = d0 * ray - R * centre;
      const SimplexResult r = nelder_mead(cost_at(0), pose_parameters(c), steps(d0, 2.0), o.coarse_iters);
      candidates.push_back({r.x, r.value});
      ran(1);
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
    candidates.resize(std::min<std::size_t>(candidates.size(), static_cast<std::size_t>(std::max(1, o.keep))));
  }
  // Every candidate through every level, the simplex restarted at each with smaller steps.
  for (Candidate& cand : candidates) {
    const std::uint64_t first_run = run;
    for (std::size_t level = 0; level < pyr.masks.size(); ++level) {
      const double shrink = pyr.scales[level] < 1 ? 1.0 / (1 << (pyr.masks.size() - 1 - level)) * 2 : 0.25;
      const double d = distance_of(camera_from_parameters(initial, cand.x), mesh);
      SimplexResult r = nelder_mead(cost_at(level), cand.x, steps(d, std::max(shrink, 0.05)), o.iters_per_level);
      // The XOR cost is piecewise constant: the simplex collapses early. Restarts at the
      // finest level with fresh, smaller simplices go on while they gain.
      if (level + 1 == pyr.masks.size())
        for (int k = 0; k < o.restarts; ++k) {
          const SimplexResult again = nelder_mead(cost_at(level), r.x, steps(d, 0.1 / (k + 1)), o.iters_per_level);
          const bool gained = again.value < r.value;
          if (again.value <= r.value) r = again;
          if (!gained && k > 0) break;
        }
      cand.x = r.x;
      cand.cost = r.value;
      if (level + 1 < pyr.masks.size()) ran(1);
    }
    ran(first_run + per_candidate - run);
  }
  const auto best = std::min_element(candidates.begin(), candidates.end(),
                                     [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
  res.camera = camera_from_parameters(initial, best->x);
  res.xor_cost = best->cost;
  return res;
}

void estimate_turntable_axis(const std::vector<PinholeCamera>& cams, const std::vector<double>& angle_deg,
                             Eigen::Vector3d& direction, Eigen::Vector3d& point) {
  direction = Eigen::Vector3d::UnitZ();
  point.setZero();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k < cams.size(); ++k) {
    const double dtheta = angle_deg[k] - angle_deg[0];
    const Eigen::AngleAxisd rel(cams[0].R.transpose() * cams[k].R);
    if (std::abs(std::sin(dtheta * M_PI / 180)) < 1e-3 || rel.angle() < 1e-6) continue;
    // The relative rotation turns by dtheta about the axis: orient the axis accordingly.
    const double s = std::sin(rel.angle()) * std::sin(dtheta * M_PI / 180) >= 0 ? 1.0 : -1.0;
    sum += s * rel.axis() * std::abs(std::sin(rel.angle()));
  }
  if (sum.norm() < 1e-9) return;
  direction = sum.normalized();
  // Least squares for a, with a . d = 0 pinning the free position along the axis.
  Eigen::MatrixXd A(3 * static_cast<Eigen::Index>(cams.size()) + 1, 3);
  Eigen::VectorXd b(A.rows());
  A.setZero();
  b.setZero();
  for (std::size_t k = 1; k < cams.size(); ++k) {
    const Eigen::Matrix3d Rk = Eigen::AngleAxisd((angle_deg[k] - angle_deg[0]) * M_PI / 180, direction).toRotationMatrix();
    A.block<3, 3>(3 * static_cast<Eigen::Index>(k), 0) = Eigen::Matrix3d::Identity() - Rk;
    b.segment<3>(3 * static_cast<Eigen::Index>(k)) = cams[0].R.transpose() * (cams[k].t - cams[0].t);
  }
  A.row(A.rows() - 1) = direction.transpose();
  point = A.colPivHouseholderQr().solve(b);
}

TurntableFit register_turntable(const TriangleMesh& mesh, const std::vector<cv::Mat>& masks,
                                const std::vector<double>& angle_deg, const std::vector<PinholeCamera>& initial,
                                const Eigen::Vector3d& axis_direction, const Eigen::Vector3d& axis_point,
                                const RegistrationOptions& o) {
  const std::size_t n = masks.size();
  if (n == 0 || angle_deg.size() != n || initial.size() != n) throw bad_input("turntable registration: no images");
  std::vector<SilhouettePyramid> pyr;
  for (std::size_t k = 0; k < n; ++k) {
    if (masks[k].cols != initial[k].width || masks[k].rows != initial[k].height)
      throw bad_input("mask {} is {}x{} but its camera is {}x{}", k, masks[k].cols, masks[k].rows, initial[k].width,
                      initial[k].height);
    pyr.push_back(make_pyramid(masks[k]));
  }
  const Eigen::Vector3d d0 = axis_direction.normalized();
  const Eigen::Vector3d e1 = d0.unitOrthogonal(), e2 = d0.cross(e1);
  auto rot = [](const Eigen::Vector3d& d, double deg) {
    return Eigen::AngleAxisd(deg * M_PI / 180, d).toRotationMatrix();
  };
  // Base pose at angle 0 from the first image: R_k = R0 R_axis(theta_k).
  PinholeCamera base = initial[0];
  base.R = initial[0].R * rot(d0, angle_deg[0]).transpose();
  base.t = initial[0].t - base.R * (axis_point - rot(d0, angle_deg[0]) * axis_point);
  TurntableFit fit;
  auto cameras_of = [&](const Eigen::VectorXd& x, Eigen::Vector3d& d, Eigen::Vector3d& a) {
    const PinholeCamera c0 = camera_from_parameters(base, x.head<7>());
    d = (d0 + x[7] * e1 + x[8] * e2).normalized();
    a = axis_point + x[9] * e1 + x[10] * e2;
    std::vector<PinholeCamera> cams(n, c0);
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Matrix3d Ra = rot(d, angle_deg[k]);
      cams[k].R = c0.R * Ra;
      cams[k].t = c0.R * (a - Ra * a) + c0.t;
    }
    return cams;
  };
  auto cost_at = [&](std::size_t level) {
    return [&, level](const Eigen::VectorXd& x) {
      Eigen::Vector3d d, a;
      const std::vector<PinholeCamera> cams = cameras_of(x, d, a);
      double sum = 0;
      for (std::size_t k = 0; k < n; ++k) sum += silhouette_xor(mesh, cams[k], pyr[k], level, o.threads);
      fit.evaluations += static_cast<long>(n);
      return sum / static_cast<double>(n);
    };
  };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(11);
  x.head<7>() = pose_parameters(base);
  const double dist = distance_of(base, mesh);
  Eigen::Vector3d centre;
  double radius = 0;
  reflectance::bounding_sphere(mesh, centre, radius);
  double value = 0;
  const std::size_t levels = pyr[0].masks.size();
  for (std::size_t level = 0; level < levels; ++level) {
    const double shrink = level + 1 == levels ? 0.25 : 2.0 / (1 << (levels - 1 - level));
    Eigen::VectorXd s(11);
    s.head<3>().setConstant(o.rotation_step_deg * M_PI / 180 * shrink);
    s.segment<3>(3).setConstant(o.translation_step * dist * shrink);
    s[6] = o.fix_focal ? 0.0 : o.focal_step * shrink;
    s.segment<2>(7).setConstant(o.rotation_step_deg * M_PI / 180 * shrink);
    s.segment<2>(9).setConstant(o.translation_step * radius * shrink);
    SimplexResult r = nelder_mead(cost_at(level), x, s, o.iters_per_level);
    if (level + 1 == levels) r = nelder_mead(cost_at(level), r.x, s * 0.2, o.iters_per_level);
    x = r.x;
    value = r.value;
    if (o.progress) o.progress(level + 1, levels);  // the last level's two simplex runs count as one step
  }
  fit.cameras = cameras_of(x, fit.axis_direction, fit.axis_point);
  fit.xor_cost = value;
  return fit;
}

}  // namespace fest::brdffit
