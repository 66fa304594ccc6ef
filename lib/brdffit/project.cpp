#include "brdffit/project.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/SVD>

#include "brdffit/nnls.hpp"
#include "brdffit/parallel_chunks.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

namespace {

// Where the parts of project_lumitexels end on its bar (fractions of the whole).
constexpr double kNearestEnd = 0.25, kBasisEnd = 0.85;

void check(const ProjectOptions& o) {
  if (o.basis < 1 || o.basis > 64) throw usage_error("basis size {} per cluster is outside 1..64", o.basis);
  if (!(o.svd_threshold >= 0 && o.svd_threshold < 1)) throw usage_error("the SVD threshold must lie in [0, 1)");
}

Eigen::VectorXd solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const ProjectOptions& o) {
  if (o.nonneg) return nnls(a, b);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(o.svd_threshold);  // singular values below threshold * sigma_max are discarded
  return svd.solve(b);
}

}  // namespace

Basis build_basis(const LumitexelSet& set, const std::vector<FitSample>& local, const ModelSpec& model,
                  const std::vector<MaterialCluster>& clusters, const std::vector<std::uint16_t>& assignment,
                  const ProjectOptions& o) {
  check(o);
  Basis basis;
  basis.model = model;
  for (const MaterialCluster& c : clusters) basis.brdfs.push_back(c.params);
  std::vector<std::vector<std::size_t>> members(clusters.size());
  for (std::size_t i = 0; i < set.lumitexels.size(); ++i)
    if (set.lumitexels[i].count > 0) members[assignment[i]].push_back(i);
  ClusterOptions split = o.split;
  split.fit.model = model;
  for (std::size_t j = 0; j < clusters.size(); ++j) {
    if (o.progress) o.progress(j, clusters.size());
    std::vector<int> list = {static_cast<int>(j)};
    if (o.basis >= 3)
      for (Eigen::VectorXd& child : trial_split(set, local, members[j], clusters[j], split)) {
        list.push_back(static_cast<int>(basis.brdfs.size()));
        basis.brdfs.push_back(std::move(child));
      }
    if (static_cast<int>(list.size()) < o.basis && clusters.size() > 1) {
      // The other clusters by mean D over this cluster's members, nearest first.
      std::vector<std::pair<double, std::size_t>> near;
      for (std::size_t k = 0; k < clusters.size(); ++k) {
        if (k == j) continue;
        std::vector<double> d(members[j].size());
        const ModelEvaluator fk(model, clusters[k].params);
        for_each_chunk(members[j].size(), 1024, split.fit.threads, [&](std::size_t, std::size_t b, std::size_t e) {
          for (std::size_t m = b; m < e; ++m) d[m] = mean_squared_residual(fk, local.data() + set.lumitexels[members[j][m]].first_sample, local.data() + set.lumitexels[members[j][m]].first_sample + set.lumitexels[members[j][m]].count);
        });
        const double mean = d.empty() ? 0 : std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
        near.emplace_back(mean, k);
      }
      std::sort(near.begin(), near.end());
      for (const auto& [mean, k] : near) {
        if (static_cast<int>(list.size()) >= o.basis) break;
        list.push_back(static_cast<int>(k));
      }
    }
    list.resize(std::min<std::size_t>(list.size(), static_cast<std::size_t>(o.basis)));
    basis.cluster_basis.push_back(std::move(list));
  }
  if (o.progress) o.progress(clusters.size(), clusters.size());
  return basis;
}

void solve_weights(const FitSample* s, std::size_t n, const BasisFunctions& fns, const ProjectOptions& o, int basis_size,
                   float* out) {
  const int nb = static_cast<int>(fns.size());
  const int per = o.weights == WeightMode::rgb ? 3 : 1;
  std::fill(out, out + per * basis_size, 0.0f);
  if (n < fns.size()) {  // docs/brdffit.md §5: too few samples for the basis: the pure cluster BRDF
    for (int c = 0; c < per; ++c) out[c * basis_size] = 1;
    return;
  }
  // Basis radiance per sample, channel and function.
  Eigen::MatrixXd f(3 * static_cast<Eigen::Index>(n), nb);
  Eigen::VectorXd r(3 * static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double sw = std::sqrt(std::max(0.0f, s[i].w));
    for (int c = 0; c < 3; ++c) {
      const auto row = static_cast<Eigen::Index>(3 * i + static_cast<std::size_t>(c));
      r[row] = sw * s[i].r[c];
      for (int j = 0; j < nb; ++j) f(row, j) = sw * fns[j]->value(c, s[i].xy, s[i].z) * s[i].uz;
    }
  }
  if (per == 1) {
    const Eigen::VectorXd t = solve(f, r, o);
    for (int j = 0; j < nb; ++j) out[j] = static_cast<float>(t[j]);
    return;
  }
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd fc(static_cast<Eigen::Index>(n), nb);
    Eigen::VectorXd rc(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      fc.row(static_cast<Eigen::Index>(i)) = f.row(static_cast<Eigen::Index>(3 * i) + c);
      rc[static_cast<Eigen::Index>(i)] = r[static_cast<Eigen::Index>(3 * i) + c];
    }
    const Eigen::VectorXd t = solve(fc, rc, o);
    for (int j = 0; j < nb; ++j) out[c * basis_size + j] = static_cast<float>(t[j]);
  }
}

Eigen::Vector3d blended_value(const BasisFunctions& fns, const float* w, WeightMode mode, int basis_size, double xy,
                              double z) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int c = 0; c < 3; ++c)
    for (std::size_t j = 0; j < fns.size(); ++j) {
      const float t = mode == WeightMode::rgb ? w[c * basis_size + static_cast<int>(j)] : w[j];
      if (t != 0) f[c] += t * fns[j]->value(c, xy, z);
    }
  return f;
}

std::vector<ModelEvaluator> evaluators_of(const Basis& basis) {
  std::vector<ModelEvaluator> ev;
  for (const Eigen::VectorXd& b : basis.brdfs) ev.emplace_back(basis.model, b);
  return ev;
}

BasisFunctions functions_of(const Projection& p, const std::vector<ModelEvaluator>& ev, std::size_t i) {
  BasisFunctions fns;
  for (int k : p.basis.cluster_basis[p.cluster[i]]) fns.push_back(&ev[static_cast<std::size_t>(k)]);
  return fns;
}

Projection project_lumitexels(const LumitexelSet& set, const std::vector<FitSample>& local, const ModelSpec& model,
                              const std::vector<MaterialCluster>& clusters, const ProjectOptions& o) {
  check(o);
  if (clusters.empty()) throw bad_input("no clusters to project onto");
  if (clusters.size() > 65535) throw bad_input("{} clusters: at most 65535 fit the .ltw file", clusters.size());
  std::vector<Eigen::VectorXd> params;
  for (const MaterialCluster& c : clusters) params.push_back(c.params);
  const int threads = o.split.fit.threads;
  Projection p;
  p.mode = o.weights;
  // One bar over the three parts, weighted by their share of the time (measured on 200,000
  // synthetic lumitexels of five materials).
  p.cluster = nearest_clusters(set, local, model, params, threads, progress_part(o.progress, 0.0, kNearestEnd));
  ProjectOptions basis_options = o;
  basis_options.progress = progress_part(o.progress, kNearestEnd, kBasisEnd);
  p.basis = build_basis(set, local, model, clusters, p.cluster, basis_options);
  for (const auto& list : p.basis.cluster_basis) p.basis_size = std::max(p.basis_size, static_cast<int>(list.size()));
  const int per = p.values_per_lumitexel();
  p.weights.assign(set.lumitexels.size() * static_cast<std::size_t>(per), 0.0f);
  const std::vector<ModelEvaluator> ev = evaluators_of(p.basis);
  ProgressCounter chunks(progress_part(o.progress, kBasisEnd, 1.0), chunk_count(set.lumitexels.size(), 1024));
  for_each_chunk(set.lumitexels.size(), 1024, threads, [&](std::size_t, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const Lumitexel& l = set.lumitexels[i];
      solve_weights(local.data() + l.first_sample, l.count, functions_of(p, ev, i), o, p.basis_size,
                    p.weights.data() + i * static_cast<std::size_t>(per));
    }
    chunks.step();
  });
  chunks.finish();
  return p;
}

ProjectionError projection_error(const LumitexelSet& set, const std::vector<FitSample>& local, const Projection& p,
                                 int threads, const ProgressFn& progress) {
  const std::size_t chunks = chunk_count(set.lumitexels.size(), 1024);
  ProgressCounter done(progress, chunks);
  std::vector<ProjectionError> parts(chunks);
  const int per = p.values_per_lumitexel();
  const std::vector<ModelEvaluator> ev = evaluators_of(p.basis);
  for_each_chunk(set.lumitexels.size(), 1024, threads, [&](std::size_t ci, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const Lumitexel& l = set.lumitexels[i];
      const BasisFunctions fns = functions_of(p, ev, i);
      const float* w = p.weights.data() + i * static_cast<std::size_t>(per);
      for (std::size_t k = 0; k < l.count; ++k) {
        const FitSample& s = local[l.first_sample + k];
        const Eigen::Vector3d fl = blended_value(fns, w, p.mode, p.basis_size, s.xy, s.z);
        for (int c = 0; c < 3; ++c) {
          const double a = s.r[c] - fl[c] * s.uz;
          const double q = s.r[c] - fns[0]->value(c, s.xy, s.z) * s.uz;
          parts[ci].projected += s.w * a * a / 3;
          parts[ci].per_cluster += s.w * q * q / 3;
        }
      }
    }
    done.step();
  });
  done.finish();
  ProjectionError total;
  for (const ProjectionError& e : parts) total.projected += e.projected, total.per_cluster += e.per_cluster;
  return total;
}

}  // namespace fest::brdffit
