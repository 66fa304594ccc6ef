#include "brdffit/pbr_appearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdffit/lafortune_model.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

double pbr_roughness(const reflectance::LafortuneBrdf& brdf) {
  double best_peak = -1, n = 0;
  for (const auto& lobe : brdf.lobes) {
    // The base max(0, Cxy (ux vx + uy vy) + Cz uz vz) peaks at max(|Cxy|, |Cz|) for a
    // mirror-like lobe (Cxy < 0 < Cz), so the lobe's peak is that to the power N.
    const double base = std::max(std::abs(lobe.cxy.mean()), std::abs(lobe.cz.mean()));
    const double peak = std::pow(base, lobe.n.mean());
    if (peak > best_peak) {
      best_peak = peak;
      n = lobe.n.mean();
    }
  }
  return brdf.lobes.empty() ? 1.0 : std::sqrt(2.0 / (n + 2.0));
}

PbrPoint pbr_of_blend(const std::vector<const reflectance::LafortuneBrdf*>& brdfs, const float* weights, bool rgb) {
  std::vector<double> roughness;
  for (const auto* b : brdfs) roughness.push_back(pbr_roughness(*b));
  return pbr_of_blend(brdfs, roughness, weights, rgb);
}

PbrPoint pbr_of_blend(const std::vector<const reflectance::LafortuneBrdf*>& brdfs, const std::vector<double>& roughness,
                      const float* weights, bool rgb) {
  PbrPoint p;
  const std::size_t count = brdfs.size();
  double dominant = -1;
  for (std::size_t j = 0; j < count; ++j) {
    double magnitude = 0;
    for (int c = 0; c < 3; ++c) {
      const double t = rgb ? weights[static_cast<std::size_t>(c) * count + j] : weights[j];
      p.base_color[c] += t * brdfs[j]->rho_d[c];
      magnitude += std::abs(t) / 3;
    }
    if (magnitude > dominant) {
      dominant = magnitude;
      p.roughness = roughness[j];
    }
  }
  p.base_color = p.base_color.cwiseMax(0.0).cwiseMin(1.0);
  return p;
}

PbrSurface materials_surface(const reflectance::TriangleMesh& mesh, const reflectance::SurfaceMaterials& mats) {
  const std::size_t m = mats.brdfs.size();
  if (m == 0) throw bad_input("the materials name no BRDF");
  if (!mats.vertex_weights.empty()) {
    if (mats.vertex_weights.size() != mesh.vertices.size() * m)
      throw bad_input("{} vertex weights for {} vertices x {} materials", mats.vertex_weights.size(), mesh.vertices.size(), m);
  } else if (mats.triangle_material.size() != mesh.triangles.size()) {
    throw bad_input("{} triangle materials for {} triangles", mats.triangle_material.size(), mesh.triangles.size());
  } else {
    for (std::uint16_t id : mats.triangle_material)
      if (id >= m) throw bad_input("triangle material {} of {} materials", id, m);
  }
  std::vector<const reflectance::LafortuneBrdf*> all;
  std::vector<double> roughness;
  std::vector<PbrPoint> pure;  // each material alone
  for (const auto& b : mats.brdfs) {
    all.push_back(&b);
    roughness.push_back(pbr_roughness(b));
    pure.push_back({b.rho_d.cwiseMax(0.0).cwiseMin(1.0), roughness.back(), 0, Eigen::Vector3d::Zero()});
  }
  return [&mesh, &mats, all, roughness, pure, m](std::uint32_t t, const Eigen::Vector3d& bary) {
    if (mats.vertex_weights.empty()) return pure[mats.triangle_material[t]];
    std::vector<float> w(m, 0.f);
    for (std::size_t k = 0; k < 3; ++k) {
      const float* vw = &mats.vertex_weights[mesh.triangles[t][k] * m];
      for (std::size_t j = 0; j < m; ++j) w[j] += static_cast<float>(bary[static_cast<Eigen::Index>(k)]) * vw[j];
    }
    return pbr_of_blend(all, roughness, w.data(), false);
  };
}

LumitexelSurface::LumitexelSurface(const reflectance::TriangleMesh& mesh, const LumitexelSet& set,
                                   const Projection& projection, const reflectance::SurfaceMaterials& fallback,
                                   std::vector<Eigen::Vector3d> refined_normals)
    : mesh_(mesh), set_(set), projection_(projection), fallback_(fallback), normals_(std::move(refined_normals)) {
  const std::size_t n = set.lumitexels.size();
  if (projection.cluster.size() != n)
    throw bad_input("the weights hold {} lumitexels, the lumitexel file {}", projection.cluster.size(), n);
  if (projection.weights.size() != n * static_cast<std::size_t>(projection.values_per_lumitexel()))
    throw bad_input("the weights hold {} values for {} lumitexels", projection.weights.size(), n);
  if (!normals_.empty() && normals_.size() != n)
    throw bad_input("{} refined normals for {} lumitexels", normals_.size(), n);
  if (fallback.triangle_material.size() != mesh.triangles.size() || fallback.brdfs.empty())
    throw bad_input("the fallback materials do not cover the {} triangles", mesh.triangles.size());
  for (const Eigen::VectorXd& p : projection.basis.brdfs) {
    basis_.push_back(to_brdf(projection.basis.model, p));
    roughness_.push_back(pbr_roughness(basis_.back()));
  }
  for (const auto& list : projection.basis.cluster_basis)
    for (int j : list)
      if (j < 0 || static_cast<std::size_t>(j) >= basis_.size())
        throw bad_input("a cluster's basis names BRDF {} of {}", j, basis_.size());
  first_.assign(mesh.triangles.size() + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Lumitexel& l = set.lumitexels[i];
    if (l.triangle >= mesh.triangles.size())
      throw bad_input("lumitexel {} lies on triangle {}, the mesh has {}", i, l.triangle, mesh.triangles.size());
    if (projection.cluster[i] >= projection.basis.cluster_basis.size())
      throw bad_input("lumitexel {} is in cluster {} of {}", i, projection.cluster[i], projection.basis.cluster_basis.size());
    ++first_[l.triangle + 1];
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) first_[t + 1] += first_[t];
  order_.resize(n);
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order_[fill[set.lumitexels[i].triangle]++] = static_cast<std::uint32_t>(i);
}

PbrPoint LumitexelSurface::operator()(std::uint32_t t, const Eigen::Vector3d& bary) const {
  const auto& tri = mesh_.triangles[t];
  const Eigen::Vector3d p = bary[0] * mesh_.vertices[tri[0]] + bary[1] * mesh_.vertices[tri[1]] + bary[2] * mesh_.vertices[tri[2]];
  double best = std::numeric_limits<double>::infinity();
  std::int64_t nearest = -1;
  for (std::uint32_t k = first_[t]; k < first_[t + 1]; ++k) {
    const double d = (set_.lumitexels[order_[k]].p.cast<double>() - p).squaredNorm();
    if (d < best) {
      best = d;
      nearest = order_[k];
    }
  }
  if (nearest < 0) {
    PbrPoint q;
    q.base_color = fallback_.brdfs[fallback_.triangle_material[t]].rho_d.cwiseMax(0.0).cwiseMin(1.0);
    q.roughness = pbr_roughness(fallback_.brdfs[fallback_.triangle_material[t]]);
    return q;
  }
  const auto i = static_cast<std::size_t>(nearest);
  const std::vector<int>& list = projection_.basis.cluster_basis[projection_.cluster[i]];
  std::vector<const reflectance::LafortuneBrdf*> brdfs;
  std::vector<double> roughness;
  for (int j : list) {
    brdfs.push_back(&basis_[static_cast<std::size_t>(j)]);
    roughness.push_back(roughness_[static_cast<std::size_t>(j)]);
  }
  // Weights are stored basis_size wide (rgb: 3 x basis_size); the list may be shorter, its
  // trailing weights are 0. Copy the used ones into the layout pbr_of_blend reads.
  const bool rgb = projection_.mode == WeightMode::rgb;
  const std::size_t width = static_cast<std::size_t>(projection_.basis_size);
  const float* stored = &projection_.weights[i * static_cast<std::size_t>(projection_.values_per_lumitexel())];
  std::vector<float> w(rgb ? 3 * brdfs.size() : brdfs.size());
  for (std::size_t j = 0; j < brdfs.size() && j < width; ++j) {
    if (rgb) {
      for (std::size_t c = 0; c < 3; ++c) w[c * brdfs.size() + j] = stored[c * width + j];
    } else {
      w[j] = stored[j];
    }
  }
  PbrPoint q = pbr_of_blend(brdfs, roughness, w.data(), rgb);
  if (!normals_.empty()) q.normal = normals_[i];
  return q;
}

}  // namespace fest::brdffit
