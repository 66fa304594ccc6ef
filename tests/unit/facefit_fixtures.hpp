#pragma once
// Shared fixtures of the facefit tests: the exact linear model G1 (docs/facefit.md §4)
// and helpers to draw faces from it.

#include <cmath>

#include <Eigen/QR>

#include "core/error.hpp"
#include "facefit/model.hpp"
#include "facefit/rng.hpp"

namespace facefit_test {

using namespace fest::facefit;

// G1: p = 400 points on a 20×20 grid of a spherical cap (radius 90 mm), k = 30,
// σ_i = 20·0.85^(i−1), S = Q factor of a seeded Gaussian n×k matrix.
inline Model g1_model(bool f64 = true, std::size_t k = 30) {
  Model m;
  m.dims = 3;
  m.points = 400;
  m.components = k;
  m.mean.resize(1200);
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const double x = -60 + 120.0 * i / 19, y = -60 + 120.0 * j / 19;
      const std::size_t p = static_cast<std::size_t>(j * 20 + i);
      m.mean[3 * p] = x;
      m.mean[3 * p + 1] = y;
      m.mean[3 * p + 2] = std::sqrt(90.0 * 90.0 - x * x - y * y);
    }
  Rng rng(42);
  Eigen::MatrixXd G(1200, static_cast<Eigen::Index>(k));
  for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = rng.normal();
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(G);
  const Eigen::MatrixXd S = qr.householderQ() * Eigen::MatrixXd::Identity(1200, static_cast<Eigen::Index>(k));
  for (std::size_t i = 0; i < k; ++i) m.sigma.push_back(20 * std::pow(0.85, static_cast<double>(i)));
  if (f64) set_owned_basis(m, S);
  else set_owned_basis_f32(m, S);
  return m;
}

inline Eigen::VectorXd random_coefficients(Rng& rng, std::size_t k) {
  Eigen::VectorXd c(static_cast<Eigen::Index>(k));
  for (Eigen::Index i = 0; i < c.size(); ++i) c(i) = rng.normal();
  return c;
}

}  // namespace facefit_test
