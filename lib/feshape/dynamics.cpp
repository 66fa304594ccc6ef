#include "feshape/dynamics.hpp"

#include <Eigen/SparseCholesky>

#include "core/error.hpp"
#include "feshape/global_fit.hpp"

namespace fest::feshape {

struct EulerIntegrator::Factor {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
};

EulerIntegrator::EulerIntegrator(const Eigen::SparseMatrix<double>& k, double beta, double dt, const Damping& damping,
                                 bool local, bool semi_implicit)
    : k_(k), beta_(beta), dt_(dt), damping_(damping), local_(local) {
  if (local && semi_implicit) {
    factor_ = std::make_unique<Factor>();
    Eigen::SparseMatrix<double> a = dt * k;
    Eigen::SparseMatrix<double> id(k.rows(), k.cols());
    id.setIdentity();
    a += damping.d * id;
    factor_->solver.compute(a);
    if (factor_->solver.info() != Eigen::Success) throw make_error(Status::failure, "D + dt K is not positive definite");
  }
}

EulerIntegrator::~EulerIntegrator() = default;

void EulerIntegrator::step(Model& m, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<MeshPoint>& assigned) const {
  const std::vector<Eigen::Vector3d> x = m.node_positions();
  // Eq. 10 at each data point, eq. 11 to the element's nodes: f_i = sum_p lambda_pi beta (z - x(u_z)).
  std::vector<Eigen::Vector3d> f(x.size(), Eigen::Vector3d::Zero());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto& t = m.mesh.tris[assigned[p].face];
    const auto& l = assigned[p].lambda;
    const Eigen::Vector3d force = beta_ * (points[p] - (l[0] * x[t[0]] + l[1] * x[t[1]] + l[2] * x[t[2]]));
    for (int i = 0; i < 3; ++i) f[t[i]] += l[i] * force;
  }
  // Generalized forces (eq. 5): f_c = sum f, f_theta = sum (x - c) x f, f_s = sum J^T R^T f.
  const Eigen::Matrix3d rt = m.rotation.toRotationMatrix().transpose();
  GlobalStep gf = GlobalStep::Zero();
  Eigen::MatrixXd fd(static_cast<Eigen::Index>(x.size()), 3);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector3d fm = rt * f[i];
    gf.segment<3>(0) += f[i];
    gf.segment<3>(3) += (x[i] - m.center).cross(f[i]);
    gf.segment<n_global>(6) += shape_jacobian(m.qs, m.mesh.u[i], m.mesh.v[i]).transpose() * fm;
    fd.row(static_cast<Eigen::Index>(i)) = fm.transpose();
  }
  GlobalStep step;
  step.segment<3>(0) = dt_ / damping_.c * gf.segment<3>(0);
  step.segment<3>(3) = dt_ / damping_.theta * gf.segment<3>(3);
  step.segment<n_global>(6) = dt_ / damping_.s * gf.segment<n_global>(6);
  if (local_) {
    Eigen::MatrixXd d(fd.rows(), 3);
    for (Eigen::Index i = 0; i < d.rows(); ++i) d.row(i) = m.d[static_cast<std::size_t>(i)].transpose();
    Eigen::MatrixXd next;
    if (factor_)
      next = factor_->solver.solve(damping_.d * d + dt_ * fd);
    else
      next = d + dt_ / damping_.d * (fd - k_ * d);
    if (!next.allFinite()) throw make_error(Status::failure, "explicit integration diverged (NaN): the time step is too large for the data's scale");
    for (Eigen::Index i = 0; i < d.rows(); ++i) m.d[static_cast<std::size_t>(i)] = next.row(i).transpose();
  }
  if (!step.allFinite()) throw make_error(Status::failure, "explicit integration diverged (NaN): the time step is too large for the data's scale");
  apply_global_step(m, step);
}

}  // namespace fest::feshape
