#include "radiosity/direct.hpp"

#include <Eigen/Dense>

#include "core/error.hpp"

namespace fest::radiosity {

std::vector<Rgb> direct_solve(const Model& model, FormFactors& ff, std::size_t max_elements) {
  const std::vector<int> active = model.active_elements();
  const std::size_t n = active.size();
  if (n > max_elements)
    throw bad_input("direct solve: {} elements, more than the {} a dense matrix allows", n, max_elements);
  std::vector<int> row_of(model.elements.size(), -1);
  for (std::size_t k = 0; k < n; ++k) row_of[active[k]] = static_cast<int>(k);
  // G(e, e') = F_{e->i(e')} A_e' / A_i(e'): the geometric part, shared by the channels.
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  std::vector<double> recv, row;
  for (std::size_t i = 0; i < model.patches.size(); ++i) {
    ff.shoot(static_cast<int>(i), recv, row);
    const Patch& pi = model.patches[i];
    for (std::size_t k = 0; k < n; ++k) {
      const double f = recv[active[k]];
      if (f == 0) continue;
      for (int e2 : pi.elements) g(static_cast<Eigen::Index>(k), row_of[e2]) += f * model.elements[e2].area / pi.area;
    }
  }
  std::vector<Rgb> out(model.elements.size(), Rgb::Zero());
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd a = -g;
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k) {
      const Patch& p = model.patches[model.elements[active[k]].patch];
      a.row(static_cast<Eigen::Index>(k)) *= p.rho[c];
      a(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)) += 1.0;
      rhs[static_cast<Eigen::Index>(k)] = p.E[c];
    }
    const Eigen::VectorXd b = a.partialPivLu().solve(rhs);
    for (std::size_t k = 0; k < n; ++k) out[active[k]][c] = b[static_cast<Eigen::Index>(k)];
  }
  return out;
}

}  // namespace fest::radiosity
