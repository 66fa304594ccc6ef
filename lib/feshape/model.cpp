#include "feshape/model.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "feshape/refine.hpp"

namespace fest::feshape {

Eigen::Vector3d Model::node_position(std::size_t i) const {
  return center + rotation * (shape(qs, mesh.u[i], mesh.v[i]) + d[i]);
}

std::vector<Eigen::Vector3d> Model::node_positions() const {
  std::vector<Eigen::Vector3d> x(mesh.nodes());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = node_position(i);
  return x;
}

Eigen::Vector3d Model::global_point(double u, double v) const { return center + rotation * shape(qs, u, v); }

Model make_model(int rings, int meridians, const GlobalParams& qs, const Eigen::Vector3d& center,
                 const Eigen::Quaterniond& rotation) {
  Model m;
  m.mesh = lat_long_mesh(rings, meridians);
  m.qs = qs;
  m.center = center;
  m.rotation = rotation.normalized();
  m.d.assign(m.mesh.nodes(), Eigen::Vector3d::Zero());
  return m;
}

void displace_new_nodes(Model& m, const std::vector<Eigen::Vector3d>& positions, const std::vector<NewNode>& created) {
  m.d.resize(m.mesh.nodes(), Eigen::Vector3d::Zero());
  const Eigen::Matrix3d rt = m.rotation.toRotationMatrix().transpose();
  for (const NewNode& n : created)
    m.d[n.node] = rt * (positions[n.node] - m.center) - shape(m.qs, m.mesh.u[n.node], m.mesh.v[n.node]);
}

void auto_initialize(const std::vector<Eigen::Vector3d>& points, Model& m) {
  if (points.empty()) throw make_error(Status::failure, "no points to initialise the model from");
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
  cov /= static_cast<double>(points.size());
  if (!cov.allFinite() || !mean.allFinite())
    throw make_error(Status::failure, "the points' spread overflows double precision: rescale them");
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // ascending eigenvalues
  Eigen::Matrix3d axes = eig.eigenvectors();                // column 2 = largest variance
  if (axes.determinant() < 0) axes.col(0) = -axes.col(0);
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  for (const auto& p : points) half = half.cwiseMax((axes.transpose() * (p - mean)).cwiseAbs());
  const double a = half.maxCoeff();
  if (!(a > 0) || !std::isfinite(a)) throw make_error(Status::failure, "all points coincide: no shape to initialise from");
  if (half[1] < 1e-9 * a) throw make_error(Status::failure, "the points are collinear: no shape to initialise from");
  m.center = mean;
  m.rotation = Eigen::Quaterniond(axes).normalized();
  m.qs = {a, std::max(half[0] / a, 0.05), std::max(half[1] / a, 0.05), std::max(half[2] / a, 0.05), 1, 1, 0, 0, 0, 0, 1};
  m.d.assign(m.mesh.nodes(), Eigen::Vector3d::Zero());
}

}  // namespace fest::feshape
