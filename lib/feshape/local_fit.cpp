#include "feshape/local_fit.hpp"

#include <Eigen/SparseCholesky>

#include "core/error.hpp"

namespace fest::feshape {

void solve_local_equilibrium(Model& m, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<MeshPoint>& assigned, const std::vector<Eigen::Vector3d>& normals,
                             const Eigen::SparseMatrix<double>& k, double beta) {
  const auto n = static_cast<Eigen::Index>(m.mesh.nodes());
  std::vector<Eigen::Vector3d> s(m.mesh.nodes());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = shape(m.qs, m.mesh.u[i], m.mesh.v[i]);
  std::vector<Eigen::Triplet<double>> ata;
  ata.reserve(points.size() * 81 + static_cast<std::size_t>(9 * k.nonZeros() + 3 * n));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(3 * n);
  double diag_scale = 0;
  const Eigen::Matrix3d rt = m.rotation.toRotationMatrix().transpose();
  // Weight of the tangential part of the residual: enough to stop nodes sliding back and
  // forth as points change elements, small enough to keep the point-to-plane speed.
  constexpr double tangential = 0.1;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto& f = m.mesh.tris[assigned[p].face];
    const auto& l = assigned[p].lambda;
    const Eigen::Vector3d y = rt * (points[p] - m.center);
    const Eigen::Vector3d nm = rt * normals[p];  // the residual's direction, model frame
    const Eigen::Matrix3d nn = nm * nm.transpose() + tangential * (Eigen::Matrix3d::Identity() - nm * nm.transpose());
    const Eigen::Vector3d target = nn * (y - (l[0] * s[f[0]] + l[1] * s[f[1]] + l[2] * s[f[2]]));
    for (int i = 0; i < 3; ++i) {
      rhs.segment<3>(3 * f[i]) += beta * l[i] * target;
      for (int j = 0; j < 3; ++j)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) ata.emplace_back(3 * f[i] + r, 3 * f[j] + c, beta * l[i] * l[j] * nn(r, c));
      diag_scale += beta * l[i] * l[i];
    }
  }
  for (int col = 0; col < k.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, col); it; ++it) {
      for (int r = 0; r < 3; ++r) ata.emplace_back(3 * it.row() + r, 3 * it.col() + r, it.value());
      if (it.row() == it.col()) diag_scale += std::abs(it.value());
    }
  // A tiny Tikhonov term keeps directions that neither data nor stiffness reach at d = 0.
  const double eps = 1e-10 * diag_scale / static_cast<double>(n);
  for (Eigen::Index i = 0; i < 3 * n; ++i) ata.emplace_back(i, i, eps);
  Eigen::SparseMatrix<double> a(3 * n, 3 * n);
  a.setFromTriplets(ata.begin(), ata.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) throw make_error(Status::failure, "local displacement system is singular");
  const Eigen::VectorXd d = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !d.allFinite())
    throw make_error(Status::failure, "local displacement solve failed (NaN)");
  for (Eigen::Index i = 0; i < n; ++i) m.d[static_cast<std::size_t>(i)] = d.segment<3>(3 * i);
}

}  // namespace fest::feshape
