#include "feshape/global_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "core/parallel_for.hpp"

namespace fest::feshape {
namespace {

using Row = Eigen::Matrix<double, 1, n_pose_global>;
using Normal = Eigen::Matrix<double, n_pose_global, n_pose_global>;

Eigen::Quaterniond rotation_vector(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle < 1e-300) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle));
}

double wrap_v(double v) {
  v = std::fmod(v + pi, 2 * pi);
  if (v < 0) v += 2 * pi;
  return v - pi;
}

// Solves (H + mu diag(H)) x = g (Levenberg-Marquardt; Marquardt's scaling).
GlobalStep damped_solve(const Normal& h, const GlobalStep& g, double mu) {
  Normal a = h;
  for (int i = 0; i < n_pose_global; ++i) a(i, i) += mu * std::max(h(i, i), 1e-12 * h.trace() + 1e-300);
  return a.ldlt().solve(g);
}

// On the axis angles (sin or cos of u or v exactly 0, where mesh nodes sit) the
// parameterisation is singular for e != 1: the tangent is 0 (e > 1) or infinite (e < 1),
// and Gauss-Newton cannot leave the point. Start a hair away from them.
double off_axis(double w) {
  constexpr double nudge = 1e-7;
  const double r = std::remainder(w, pi / 2);  // distance to the nearest multiple of pi/2
  if (std::abs(r) < nudge) return w + (r >= 0 ? nudge : -nudge);
  return w;
}

}  // namespace

void apply_global_step(Model& m, const GlobalStep& step) {
  m.center += step.segment<3>(0);
  m.rotation = (rotation_vector(step.segment<3>(3)) * m.rotation).normalized();
  for (int i = 0; i < n_global; ++i) m.qs[i] += step[6 + i];
  clamp_global(m.qs);
}

double project_to_surface(const Model& m, const Eigen::Vector3d& z, Eigen::Vector2d& uv) {
  uv[0] = std::clamp(off_axis(uv[0]), -pi / 2, pi / 2);
  uv[1] = wrap_v(off_axis(uv[1]));
  const Eigen::Vector3d y = m.rotation.conjugate() * (z - m.center);
  Eigen::Vector3d r = y - shape(m.qs, uv[0], uv[1]);
  double e = r.squaredNorm();
  double lambda = 1e-6;
  for (int it = 0; it < 30 && e > 0; ++it) {
    const Eigen::Matrix<double, 3, 2> t = shape_tangents(m.qs, uv[0], uv[1]);
    Eigen::Matrix2d a = t.transpose() * t;
    const Eigen::Vector2d g = t.transpose() * r;
    const double scale = a.trace() + 1e-300;
    bool moved = false;
    for (int tries = 0; tries < 8; ++tries) {
      Eigen::Matrix2d damped = a;
      damped(0, 0) += lambda * (a(0, 0) + 1e-9 * scale);
      damped(1, 1) += lambda * (a(1, 1) + 1e-9 * scale);
      const Eigen::Vector2d step = damped.ldlt().solve(g);
      if (!step.allFinite()) break;
      Eigen::Vector2d trial(std::clamp(uv[0] + step[0], -pi / 2, pi / 2), wrap_v(uv[1] + step[1]));
      const Eigen::Vector3d rt = y - shape(m.qs, trial[0], trial[1]);
      const double et = rt.squaredNorm();
      if (et < e) {
        const bool tiny = e - et <= 1e-15 * e;
        uv = trial;
        r = rt;
        e = et;
        lambda = std::max(lambda / 10, 1e-12);
        moved = !tiny;
        break;
      }
      lambda *= 10;
    }
    if (!moved) break;
  }
  return e;
}

namespace {

// Sum of squared distances after projecting every point (warm start from uv).
double projected_energy(const Model& m, const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector2d>& uv,
                        int threads) {
  std::vector<double> e(points.size());
  constexpr std::size_t chunk = 128;
  parallel_for((points.size() + chunk - 1) / chunk, threads, [&](std::size_t c) {
    for (std::size_t i = c * chunk; i < std::min(points.size(), (c + 1) * chunk); ++i)
      e[i] = project_to_surface(m, points[i], uv[i]);
  });
  double sum = 0;
  for (double x : e) sum += x;  // in index order: deterministic for any thread count
  return sum;
}

}  // namespace

bool global_step_smooth(Model& m, const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector2d>& uv,
                        double& mu, double& energy, int threads) {
  energy = projected_energy(m, points, uv, threads);
  const Eigen::Matrix3d r = m.rotation.toRotationMatrix();
  // One row of the point-to-plane Jacobian per point (in parallel), summed in index order.
  std::vector<Row> rows(points.size(), Row::Zero());
  std::vector<double> residual(points.size(), 0.0);
  constexpr std::size_t chunk = 128;
  parallel_for((points.size() + chunk - 1) / chunk, threads, [&](std::size_t c) {
    for (std::size_t p = c * chunk; p < std::min(points.size(), (c + 1) * chunk); ++p) {
      const double u = uv[p][0], v = uv[p][1];
      const Eigen::Vector3d x = m.global_point(u, v);
      const Eigen::Vector3d res = points[p] - x;
      const Eigen::Matrix<double, 3, 2> t = r * shape_tangents(m.qs, u, v);
      Eigen::Vector3d n = t.col(0).cross(t.col(1));
      // Point-to-plane: the residual along the surface normal (the residual itself where
      // the parameterisation is singular, at the poles).
      if (n.norm() > 1e-12 * (t.col(0).norm() * t.col(1).norm() + 1e-300))
        n.normalize();
      else if (res.norm() > 0)
        n = res.normalized();
      else
        continue;
      rows[p].segment<3>(0) = n.transpose();
      rows[p].segment<3>(3) = (x - m.center).cross(n).transpose();
      rows[p].segment<n_global>(6) = n.transpose() * r * shape_jacobian(m.qs, u, v);
      residual[p] = n.dot(res);
    }
  });
  Normal h = Normal::Zero();
  GlobalStep g = GlobalStep::Zero();
  for (std::size_t p = 0; p < points.size(); ++p) {
    h.noalias() += rows[p].transpose() * rows[p];
    g.noalias() += rows[p].transpose() * residual[p];
  }
  for (int tries = 0; tries < 12; ++tries) {
    const GlobalStep step = damped_solve(h, g, mu);
    if (!step.allFinite()) return false;
    Model trial = m;
    apply_global_step(trial, step);
    std::vector<Eigen::Vector2d> uv_trial = uv;
    const double e = projected_energy(trial, points, uv_trial, threads);
    if (e < energy) {
      m.center = trial.center;
      m.rotation = trial.rotation;
      m.qs = trial.qs;
      uv = std::move(uv_trial);
      energy = e;
      mu = std::max(mu / 3, 1e-9);
      return true;
    }
    mu *= 4;
  }
  return false;
}

std::vector<Eigen::Vector3d> residual_directions(const std::vector<Eigen::Vector3d>& points,
                                                 const std::vector<Eigen::Vector3d>& positions,
                                                 const std::vector<std::array<int, 3>>& tris,
                                                 const std::vector<MeshPoint>& assigned) {
  std::vector<Eigen::Vector3d> n(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto& f = tris[assigned[p].face];
    const auto& l = assigned[p].lambda;
    const Eigen::Vector3d r = points[p] - (l[0] * positions[f[0]] + l[1] * positions[f[1]] + l[2] * positions[f[2]]);
    const Eigen::Vector3d face = (positions[f[1]] - positions[f[0]]).cross(positions[f[2]] - positions[f[0]]);
    const double scale = std::sqrt(face.norm());
    if (r.norm() > 1e-12 * scale)
      n[p] = r.normalized();
    else if (face.norm() > 0)
      n[p] = face.normalized();
    else
      n[p] = Eigen::Vector3d::UnitZ();
  }
  return n;
}

double flat_energy(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& positions,
                   const std::vector<std::array<int, 3>>& tris, const std::vector<MeshPoint>& assigned,
                   const std::vector<Eigen::Vector3d>& normals) {
  double e = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto& f = tris[assigned[p].face];
    const auto& l = assigned[p].lambda;
    const double r = normals[p].dot(points[p] - (l[0] * positions[f[0]] + l[1] * positions[f[1]] + l[2] * positions[f[2]]));
    e += r * r;
  }
  return e;
}

bool global_step_flat(Model& m, const std::vector<Eigen::Vector3d>& points, const std::vector<MeshPoint>& assigned,
                      const std::vector<Eigen::Vector3d>& normals, double& mu, double& energy) {
  const std::vector<Eigen::Vector3d> x = m.node_positions();
  const auto& tris = m.mesh.tris;
  energy = flat_energy(points, x, tris, assigned, normals);
  const Eigen::Matrix3d r = m.rotation.toRotationMatrix();
  // L_i = [I  -[x_i - c]x  R J(u_i)] per node; a data point's L is the barycentric mix.
  std::vector<Eigen::Matrix<double, 3, n_pose_global>> node_l(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto& l = node_l[i];
    l.block<3, 3>(0, 0).setIdentity();
    const Eigen::Vector3d w = x[i] - m.center;
    l.block<3, 3>(0, 3) << 0, w.z(), -w.y(), -w.z(), 0, w.x(), w.y(), -w.x(), 0;  // d(theta x w) = -[w]x
    l.block<3, n_global>(0, 6) = r * shape_jacobian(m.qs, m.mesh.u[i], m.mesh.v[i]);
  }
  Normal h = Normal::Zero();
  GlobalStep g = GlobalStep::Zero();
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto& f = tris[assigned[p].face];
    const auto& lam = assigned[p].lambda;
    const Row row = normals[p].transpose() * (lam[0] * node_l[f[0]] + lam[1] * node_l[f[1]] + lam[2] * node_l[f[2]]);
    const double res = normals[p].dot(points[p] - (lam[0] * x[f[0]] + lam[1] * x[f[1]] + lam[2] * x[f[2]]));
    h.noalias() += row.transpose() * row;
    g.noalias() += row.transpose() * res;
  }
  for (int tries = 0; tries < 12; ++tries) {
    const GlobalStep step = damped_solve(h, g, mu);
    if (!step.allFinite()) return false;
    Model trial = m;
    apply_global_step(trial, step);
    const double e = flat_energy(points, trial.node_positions(), tris, assigned, normals);
    if (e < energy) {
      m.center = trial.center;
      m.rotation = trial.rotation;
      m.qs = trial.qs;
      energy = e;
      mu = std::max(mu / 3, 1e-9);
      return true;
    }
    mu *= 4;
  }
  return false;
}

}  // namespace fest::feshape
