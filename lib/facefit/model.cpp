#include "facefit/model.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace fest::facefit {

Eigen::VectorXd reconstruct(const Model& model, const Eigen::VectorXd& c) {
  const auto n = static_cast<Eigen::Index>(model.n());
  const Eigen::Index k = c.size();
  Eigen::VectorXd scaled = c.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(model.sigma.data(), k));
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(model.mean.data(), n);
  if (model.basis_type == Dtype::f32) {
    // Float GEMV over the big basis, accumulated per row in float by Eigen; the
    // coefficients stay double until this last product.
    Eigen::Map<const Eigen::MatrixXf> S(static_cast<const float*>(model.basis), n, static_cast<Eigen::Index>(model.components));
    v += (S.leftCols(k) * scaled.cast<float>()).cast<double>();
  } else {
    Eigen::Map<const Eigen::MatrixXd> S(static_cast<const double*>(model.basis), n, static_cast<Eigen::Index>(model.components));
    v += S.leftCols(k) * scaled;
  }
  return v;
}

void reconstruct_f32(const Model& model, const Eigen::VectorXd& c, float* out) {
  const auto n = static_cast<Eigen::Index>(model.n());
  if (model.basis_type != Dtype::f32) {
    Eigen::Map<Eigen::VectorXf>(out, n) = reconstruct(model, c).cast<float>();
    return;
  }
  const Eigen::Index k = c.size();
  const Eigen::VectorXf scaled = c.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(model.sigma.data(), k)).cast<float>();
  Eigen::Map<const Eigen::MatrixXf> S(static_cast<const float*>(model.basis), n, static_cast<Eigen::Index>(model.components));
  Eigen::Map<Eigen::VectorXf> v(out, n);
  v.noalias() = S.leftCols(k) * scaled;  // one float GEMV over the (memory-mapped) basis
  const double* mean = model.mean.data();
  for (Eigen::Index i = 0; i < n; ++i) out[i] = static_cast<float>(mean[i] + static_cast<double>(out[i]));
}

Eigen::VectorXd coefficients_of(const Model& model, const Eigen::VectorXd& shape) {
  const auto n = static_cast<Eigen::Index>(model.n());
  const auto k = static_cast<Eigen::Index>(model.components);
  Eigen::VectorXd d = shape - Eigen::Map<const Eigen::VectorXd>(model.mean.data(), n);
  Eigen::VectorXd proj(k);
  if (model.basis_type == Dtype::f32) {
    Eigen::Map<const Eigen::MatrixXf> S(static_cast<const float*>(model.basis), n, k);
    for (Eigen::Index i = 0; i < k; ++i) proj(i) = S.col(i).cast<double>().dot(d);
  } else {
    Eigen::Map<const Eigen::MatrixXd> S(static_cast<const double*>(model.basis), n, k);
    proj = S.transpose() * d;
  }
  return proj.cwiseQuotient(Eigen::Map<const Eigen::VectorXd>(model.sigma.data(), k));
}

Model truncated(const Model& model, std::size_t k) {
  if (k == 0 || k > model.components)
    throw usage_error("component count {} is outside 1..{} (the model's components)", k, model.components);
  Model m = model;  // shares the basis storage; columns are contiguous, so the first k fit
  m.components = k;
  m.sigma.resize(k);
  return m;
}

}  // namespace fest::facefit
