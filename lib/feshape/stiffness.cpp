#include "feshape/stiffness.hpp"

#include <cmath>
#include <vector>

namespace fest::feshape {
namespace {

struct ElementGeometry {
  double area = 0;
  std::array<std::array<double, 2>, 3> grad{};  // grad_(u,v) N_i, constant on the element
};

ElementGeometry element_geometry(const Triangulation& t, int tri) {
  const auto c = unwrapped_corners(t, tri);
  ElementGeometry g;
  const double du1 = c[1][0] - c[0][0], dv1 = c[1][1] - c[0][1];
  const double du2 = c[2][0] - c[0][0], dv2 = c[2][1] - c[0][1];
  const double det = du1 * dv2 - du2 * dv1;  // 2 x signed area
  g.area = 0.5 * std::abs(det);
  if (g.area < 1e-300) return g;  // a degenerate parameter triangle contributes nothing
  // N_i = barycentric coordinates; their gradients come from the inverse edge matrix.
  const double inv = 1.0 / det;
  g.grad[1] = {dv2 * inv, -du2 * inv};
  g.grad[2] = {-dv1 * inv, du1 * inv};
  g.grad[0] = {-g.grad[1][0] - g.grad[2][0], -g.grad[1][1] - g.grad[2][1]};
  return g;
}

}  // namespace

Eigen::VectorXd lumped_mass(const Triangulation& t) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(t.nodes()));
  for (std::size_t f = 0; f < t.elements(); ++f) {
    const ElementGeometry g = element_geometry(t, static_cast<int>(f));
    for (int i = 0; i < 3; ++i) m[t.tris[f][i]] += g.area / 3;
  }
  return m;
}

Eigen::SparseMatrix<double> assemble_stiffness(const Triangulation& t, const StiffnessWeights& w) {
  using Triplet = Eigen::Triplet<double>;
  const auto n = static_cast<Eigen::Index>(t.nodes());
  std::vector<Triplet> ku, kv, kuv;
  for (std::size_t f = 0; f < t.elements(); ++f) {
    const ElementGeometry g = element_geometry(t, static_cast<int>(f));
    if (g.area == 0) continue;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int a = t.tris[f][i], b = t.tris[f][j];
        ku.emplace_back(a, b, g.area * g.grad[i][0] * g.grad[j][0]);
        kv.emplace_back(a, b, g.area * g.grad[i][1] * g.grad[j][1]);
        kuv.emplace_back(a, b, g.area * 0.5 * (g.grad[i][0] * g.grad[j][1] + g.grad[i][1] * g.grad[j][0]));
      }
  }
  Eigen::SparseMatrix<double> Ku(n, n), Kv(n, n), Kuv(n, n);
  Ku.setFromTriplets(ku.begin(), ku.end());
  Kv.setFromTriplets(kv.begin(), kv.end());
  Kuv.setFromTriplets(kuv.begin(), kuv.end());
  const Eigen::VectorXd m = lumped_mass(t);
  Eigen::SparseMatrix<double> K(n, n);
  std::vector<Triplet> diag;
  for (Eigen::Index i = 0; i < n; ++i) diag.emplace_back(i, i, m[i]);
  K.setFromTriplets(diag.begin(), diag.end());
  K *= w.w00;
  K += w.w10 * Ku + w.w01 * Kv;
  if (w.w20 != 0 || w.w02 != 0 || w.w11 != 0) {
    // Second-derivative terms as mixed operators: K_u M^-1 K_u ~ int (d_uu)^2.
    Eigen::VectorXd minv(n);
    for (Eigen::Index i = 0; i < n; ++i) minv[i] = m[i] > 0 ? 1.0 / m[i] : 0.0;
    const Eigen::SparseMatrix<double> Ku_w = minv.asDiagonal() * Ku;
    const Eigen::SparseMatrix<double> Kv_w = minv.asDiagonal() * Kv;
    const Eigen::SparseMatrix<double> Kuv_w = minv.asDiagonal() * Kuv;
    if (w.w20 != 0) K += w.w20 * Eigen::SparseMatrix<double>(Ku.transpose() * Ku_w);
    if (w.w02 != 0) K += w.w02 * Eigen::SparseMatrix<double>(Kv.transpose() * Kv_w);
    if (w.w11 != 0) K += w.w11 * Eigen::SparseMatrix<double>(Kuv.transpose() * Kuv_w);
  }
  K.makeCompressed();
  return K;
}

}  // namespace fest::feshape
