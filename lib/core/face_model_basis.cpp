#include "core/face_model_basis.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace fest::face {

void set_owned_basis(Model& model, const Eigen::MatrixXd& basis) {
  auto owned = std::make_shared<std::vector<double>>(basis.data(), basis.data() + basis.size());
  model.basis_type = Dtype::f64;
  model.basis = owned->data();
  model.storage = owned;
}

void set_owned_basis_f32(Model& model, const Eigen::MatrixXd& basis) {
  auto owned = std::make_shared<std::vector<float>>(basis.size());
  for (Eigen::Index i = 0; i < basis.size(); ++i) (*owned)[static_cast<std::size_t>(i)] = static_cast<float>(basis.data()[i]);
  model.basis_type = Dtype::f32;
  model.basis = owned->data();
  model.storage = owned;
}

Eigen::MatrixXd basis_matrix(const Model& model) {
  const auto n = static_cast<Eigen::Index>(model.n());
  const auto k = static_cast<Eigen::Index>(model.components);
  if (model.basis_type == Dtype::f32)
    return Eigen::Map<const Eigen::MatrixXf>(static_cast<const float*>(model.basis), n, k).cast<double>();
  return Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(model.basis), n, k);
}

CheckResult check_model(Model& model, bool fix_basis) {
  CheckResult result;
  if (model.dims != 2 && model.dims != 3) throw bad_input("model: dims is {}, expected 2 or 3", model.dims);
  if (model.points == 0) throw bad_input("model: no points");
  if (model.components == 0) throw bad_input("model: no components (k = 0)");
  if (model.mean.size() != model.n()) throw bad_input("model: mean has {} values, expected {}", model.mean.size(), model.n());
  if (model.sigma.size() != model.components)
    throw bad_input("model: sigma has {} values, expected {}", model.sigma.size(), model.components);
  if (!model.basis) throw bad_input("model: no basis");
  for (double v : model.mean)
    if (!std::isfinite(v)) throw bad_input("model: non-finite value in the mean");
  for (double s : model.sigma)
    if (!std::isfinite(s) || s <= 0) throw bad_input("model: sigma must be finite and positive (got {})", s);
  for (const auto& t : model.triangles)
    for (auto v : t)
      if (v >= model.points) throw bad_input("model: triangle vertex {} out of range (p = {})", v, model.points);
  for (const auto& [name, v] : model.landmarks)
    if (v >= model.points) throw bad_input("model: landmark '{}' maps to vertex {} >= p = {}", name, v, model.points);
  for (auto v : model.eval_mask)
    if (v >= model.points) throw bad_input("model: eval mask vertex {} out of range", v);

  const bool descending = std::is_sorted(model.sigma.rbegin(), model.sigma.rend());
  // Column norms, in double whatever the storage.
  const auto n = static_cast<Eigen::Index>(model.n());
  // Vectorised per column (this runs on every load, over the whole 91 MB basis of a
  // paper-sized model); float columns accumulate in float, ample for a 1e-3 test.
  std::vector<double> norms(model.components);
  const auto k = static_cast<Eigen::Index>(model.components);
  Eigen::VectorXd sq(k);
  if (model.basis_type == Dtype::f32)
    sq = Eigen::Map<const Eigen::MatrixXf>(static_cast<const float*>(model.basis), n, k).colwise().squaredNorm().transpose().cast<double>();
  else
    sq = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(model.basis), n, k).colwise().squaredNorm().transpose();
  for (std::size_t i = 0; i < model.components; ++i) {
    norms[i] = std::sqrt(sq(static_cast<Eigen::Index>(i)));
    if (!std::isfinite(norms[i])) throw bad_input("model: non-finite value in basis column {}", i);
  }
  bool bad_norm = false;
  std::size_t first_bad = 0;
  for (std::size_t i = 0; i < norms.size(); ++i)
    if (std::abs(norms[i] - 1.0) > 1e-3 && !bad_norm) {
      bad_norm = true;
      first_bad = i;
    }
  if (bad_norm && !fix_basis)
    throw bad_input("model: basis column {} has norm {:.6g}, not 1", first_bad,
                    norms[first_bad]);
  if (!descending || bad_norm) {
    std::vector<std::size_t> order(model.components);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return model.sigma[a] > model.sigma[b]; });
    Eigen::MatrixXd old = basis_matrix(model);
    Eigen::MatrixXd fixed(old.rows(), old.cols());
    std::vector<double> sigma(model.components);
    for (std::size_t i = 0; i < order.size(); ++i) {
      const double scale = bad_norm ? 1.0 / norms[order[i]] : 1.0;
      fixed.col(static_cast<Eigen::Index>(i)) = old.col(static_cast<Eigen::Index>(order[i])) * scale;
      sigma[i] = model.sigma[order[i]];
    }
    model.sigma = sigma;
    if (model.basis_type == Dtype::f32)
      set_owned_basis_f32(model, fixed);
    else
      set_owned_basis(model, fixed);
    result.reordered = !descending;
    result.renormalised = bad_norm;
  }
  return result;
}

}  // namespace fest::face
