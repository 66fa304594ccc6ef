#include "brdffit/normals.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "brdffit/parallel_chunks.hpp"
#include "core/error.hpp"
#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

namespace {

// A sample's unit directions, normalised once per lumitexel.
struct Directions {
  Eigen::Vector3d u, v;
  double uv;
};

void directions(const Sample* s, std::size_t count, std::vector<Directions>& out) {
  out.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i].u = s[i].u_world.cast<double>().normalized();
    out[i].v = s[i].v_world.cast<double>().normalized();
    out[i].uv = out[i].u.dot(out[i].v);
  }
}

// Residuals r_c - f_L(u', v') max(0, u'.n') of every sample and channel for normal n.
void residuals(const Sample* s, const std::vector<Directions>& d, const Eigen::Vector3d& n, const BlendedBrdf& f,
               Eigen::VectorXd& out) {
  const std::size_t count = d.size();
  out.resize(3 * static_cast<Eigen::Index>(count));
  for (std::size_t i = 0; i < count; ++i) {
    const double uz = d[i].u.dot(n), vz = d[i].v.dot(n);
    const double xy = d[i].uv - uz * vz;  // u_x v_x + u_y v_y in any frame around n
    const Eigen::Vector3d fl = blended_value(f.functions, f.weights, f.mode, f.basis_size, xy, uz * vz);
    const double sw = std::sqrt(std::max(0.0f, s[i].weight));
    for (int c = 0; c < 3; ++c)
      out[static_cast<Eigen::Index>(3 * i) + c] = sw * (s[i].r[c] - fl[c] * std::max(0.0, uz));
  }
}

Eigen::Vector3d tilted(const Eigen::Vector3d& n0, const Eigen::Matrix3d& frame, const Eigen::Vector2d& ab) {
  return (n0 + ab[0] * frame.col(0) + ab[1] * frame.col(1)).normalized();
}

}  // namespace

double normal_residual(const Sample* s, std::size_t count, const Eigen::Vector3d& n, const BlendedBrdf& f) {
  std::vector<Directions> d;
  directions(s, count, d);
  Eigen::VectorXd r;
  residuals(s, d, n, f, r);
  return r.squaredNorm();
}

Eigen::Vector3d refine_normal(const Sample* s, std::size_t count, const Eigen::Vector3d& n0, const BlendedBrdf& f,
                              const NormalOptions& o, double* before, double* after) {
  const Eigen::Matrix3d frame = reflectance::local_frame(n0);
  const double radius = std::tan(o.max_tilt_deg * M_PI / 180);
  auto clamp_tilt = [radius](Eigen::Vector2d ab) {
    const double len = ab.norm();
    return len > radius ? Eigen::Vector2d(ab * (radius / len)) : ab;
  };
  Eigen::Vector2d ab = Eigen::Vector2d::Zero();
  std::vector<Directions> dirs;
  directions(s, count, dirs);
  Eigen::VectorXd r, rp, rm;
  residuals(s, dirs, n0, f, r);
  double e = r.squaredNorm();
  if (before) *before = e;
  double mu = -1;
  const double h = 1e-6;
  for (int it = 0; it < o.max_iterations && e > 0; ++it) {
    // Jacobian by central differences: two parameters, cheap and exact enough.
    Eigen::MatrixXd j(r.size(), 2);
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d d = Eigen::Vector2d::Zero();
      d[k] = h;
      residuals(s, dirs, tilted(n0, frame, ab + d), f, rp);
      residuals(s, dirs, tilted(n0, frame, ab - d), f, rm);
      j.col(k) = (rp - rm) / (2 * h);
    }
    const Eigen::Matrix2d jtj = j.transpose() * j;
    const Eigen::Vector2d g = j.transpose() * r;
    if (mu < 0) mu = 1e-3 * std::max(jtj.diagonal().maxCoeff(), 1e-300);
    bool accepted = false;
    for (int tries = 0; tries < 30 && !accepted; ++tries) {
      const Eigen::Vector2d step = (jtj + mu * Eigen::Matrix2d::Identity()).ldlt().solve(-g);
      const Eigen::Vector2d trial = clamp_tilt(ab + step);
      Eigen::VectorXd rt;
      residuals(s, dirs, tilted(n0, frame, trial), f, rt);
      const double et = rt.squaredNorm();
      if (std::isfinite(et) && et < e) {
        const double decrease = (e - et) / e;
        ab = trial;
        r = std::move(rt);
        e = et;
        mu = std::max(mu / 10, 1e-300);
        accepted = true;
        if (decrease < 1e-10 || step.norm() < 1e-9) it = o.max_iterations;  // converged
      } else {
        mu *= 10;
      }
    }
    if (!accepted) break;
  }
  if (after) *after = e;
  return tilted(n0, frame, ab);
}

NormalResult refine_normals(const LumitexelSet& set, const Projection& p, const NormalOptions& o) {
  if (o.min_samples < 3)
    throw usage_error("normal refinement needs at least 3 samples per lumitexel (two unknowns), not {}", o.min_samples);
  if (!(o.max_tilt_deg > 0 && o.max_tilt_deg < 90))
    throw usage_error("the largest normal tilt must lie in (0, 90) degrees, not {}", o.max_tilt_deg);
  if (o.alternate < 1) throw usage_error("rounds of re-projection and normals must be at least 1, not {}", o.alternate);
  if (p.cluster.size() != set.lumitexels.size()) throw bad_input("the weights are for {} lumitexels, the lumitexel file has {}", p.cluster.size(), set.lumitexels.size());
  const std::size_t n = set.lumitexels.size();
  NormalResult res;
  res.normals.resize(n);
  res.refined.assign(n, 0);
  std::vector<float> weights = p.weights;
  const int per = p.values_per_lumitexel();
  std::vector<double> before(n, 0), after(n, 0);
  const std::vector<ModelEvaluator> ev = evaluators_of(p.basis);
  ProgressCounter chunks(o.progress, chunk_count(n, 512));
  for_each_chunk(n, 512, o.threads, [&](std::size_t, std::size_t b, std::size_t e) {
    std::vector<FitSample> local;
    for (std::size_t i = b; i < e; ++i) {
      const Lumitexel& l = set.lumitexels[i];
      Eigen::Vector3d normal = l.n.cast<double>().normalized();
      res.normals[i] = normal.cast<float>();
      if (l.count < o.min_samples) continue;
      BlendedBrdf f{functions_of(p, ev, i), weights.data() + i * static_cast<std::size_t>(per), p.mode,
                    p.basis_size};
      const Sample* s = set.samples.data() + l.first_sample;
      for (int round = 0; round < o.alternate; ++round) {
        if (round > 0) {  // re-project the weights in the frame of the refined normal
          local_samples_of(set, i, normal, local);
          ProjectOptions po = o.project;
          po.weights = p.mode;
          solve_weights(local.data(), local.size(), f.functions, po, p.basis_size,
                        weights.data() + i * static_cast<std::size_t>(per));
        }
        double b0 = 0, a0 = 0;
        normal = refine_normal(s, l.count, normal, f, o, &b0, &a0);
        if (round == 0) before[i] = b0;
        after[i] = a0;
      }
      res.normals[i] = normal.cast<float>();
      res.refined[i] = 1;
    }
    chunks.step();
  });
  chunks.finish();
  for (std::size_t i = 0; i < n; ++i)
    if (res.refined[i]) {
      ++res.refined_count;
      res.residual_before += before[i];
      res.residual_after += after[i];
    }
  return res;
}

}  // namespace fest::brdffit
