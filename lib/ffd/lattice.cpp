#include "ffd/lattice.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::ffd {

Eigen::Vector3d Lattice::rest_point(int i, int j, int k) const {
  return origin + rest_coordinate(basis[0], dims[0], i) * axes[0] + rest_coordinate(basis[1], dims[1], j) * axes[1] +
         rest_coordinate(basis[2], dims[2], k) * axes[2];
}

void Lattice::validate() const {
  for (int a = 0; a < 3; ++a)
    if (dims[a] < 2 || dims[a] > max_axis_points)
      throw bad_input("lattice axis {} has {} control points (2..{})", a, dims[a], max_axis_points);
  if (!origin.allFinite() || !axes[0].allFinite() || !axes[1].allFinite() || !axes[2].allFinite())
    throw bad_input("lattice origin or axes are not finite");
  const double vol = axes[1].cross(axes[2]).dot(axes[0]);
  const double scale = axes[0].norm() * axes[1].norm() * axes[2].norm();
  if (!(std::abs(vol) > 1e-12 * scale) || !(scale > 0))
    throw bad_input("lattice box is degenerate ((T x U).S = {:g})", vol);
  if (!displacement.empty() && displacement.size() != size())
    throw bad_input("lattice has {} displacements for {} control points", displacement.size(), size());
  for (std::size_t i = 0; i < displacement.size(); ++i)
    if (!displacement[i].allFinite()) throw bad_input("displacement of control point {} is not finite", i);
}

Deformer::Deformer(const Lattice& lattice) : lattice_(lattice) {
  lattice_.validate();
  if (lattice_.displacement.empty()) lattice_.displacement.assign(lattice_.size(), Eigen::Vector3d::Zero());
  Eigen::Matrix3d frame;
  frame.col(0) = lattice_.axes[0];
  frame.col(1) = lattice_.axes[1];
  frame.col(2) = lattice_.axes[2];
  // Rows are (T x U)/((T x U).S) etc. (S&P section 3).
  inverse_frame_.row(0) = lattice_.axes[1].cross(lattice_.axes[2]) / lattice_.axes[1].cross(lattice_.axes[2]).dot(lattice_.axes[0]);
  inverse_frame_.row(1) = lattice_.axes[0].cross(lattice_.axes[2]) / lattice_.axes[0].cross(lattice_.axes[2]).dot(lattice_.axes[1]);
  inverse_frame_.row(2) = lattice_.axes[0].cross(lattice_.axes[1]) / lattice_.axes[0].cross(lattice_.axes[1]).dot(lattice_.axes[2]);
}

bool Deformer::inside(const Eigen::Vector3d& stu) {
  constexpr double tol = 1e-12;
  return stu[0] >= -tol && stu[0] <= 1 + tol && stu[1] >= -tol && stu[1] <= 1 + tol && stu[2] >= -tol && stu[2] <= 1 + tol;
}

namespace {
struct Weights3 {
  AxisWeights a[3];
};

bool evaluate_weights(const Deformer& d, const Eigen::Vector3d& x, Outside outside, Weights3& w, bool derivatives) {
  Eigen::Vector3d stu = d.local(x);
  if (!Deformer::inside(stu) && outside == Outside::none) return false;
  const Lattice& l = d.lattice();
  for (int a = 0; a < 3; ++a) axis_weights(l.basis[a], l.dims[a], std::clamp(stu[a], 0.0, 1.0), w.a[a], derivatives);
  return true;
}
}  // namespace

Eigen::Vector3d Deformer::apply(const Eigen::Vector3d& x, Outside outside) const {
  Weights3 w;
  if (!evaluate_weights(*this, x, outside, w, false)) return x;
  const AxisWeights &wu = w.a[0], &wv = w.a[1], &ww = w.a[2];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int c = 0; c < ww.count; ++c) {
    Eigen::Vector3d sj = Eigen::Vector3d::Zero();
    for (int b = 0; b < wv.count; ++b) {
      const Eigen::Vector3d* row = &lattice_.displacement[lattice_.index(wu.first, wv.first + b, ww.first + c)];
      Eigen::Vector3d si = Eigen::Vector3d::Zero();
      for (int a = 0; a < wu.count; ++a) si += wu.w[static_cast<std::size_t>(a)] * row[a];
      sj += wv.w[static_cast<std::size_t>(b)] * si;
    }
    sum += ww.w[static_cast<std::size_t>(c)] * sj;
  }
  return x + sum;
}

Eigen::Matrix3d Deformer::jacobian(const Eigen::Vector3d& x, Outside outside) const {
  Weights3 w;
  if (!evaluate_weights(*this, x, outside, w, true)) return Eigen::Matrix3d::Identity();
  // Clamped outside points see a displacement constant along the clamped direction.
  const Eigen::Vector3d stu = local(x);
  double inside_axis[3];
  for (int a = 0; a < 3; ++a) inside_axis[a] = (stu[a] >= -1e-12 && stu[a] <= 1 + 1e-12) ? 1.0 : 0.0;
  const AxisWeights &wu = w.a[0], &wv = w.a[1], &ww = w.a[2];
  Eigen::Matrix3d d_stu = Eigen::Matrix3d::Zero();  // columns: dX'/ds, dX'/dt, dX'/du of the displacement
  for (int c = 0; c < ww.count; ++c)
    for (int b = 0; b < wv.count; ++b)
      for (int a = 0; a < wu.count; ++a) {
        const Eigen::Vector3d& p = lattice_.displacement[lattice_.index(wu.first + a, wv.first + b, ww.first + c)];
        const std::size_t ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b), ic = static_cast<std::size_t>(c);
        d_stu.col(0) += (wu.dw[ia] * wv.w[ib] * ww.w[ic] * inside_axis[0]) * p;
        d_stu.col(1) += (wu.w[ia] * wv.dw[ib] * ww.w[ic] * inside_axis[1]) * p;
        d_stu.col(2) += (wu.w[ia] * wv.w[ib] * ww.dw[ic] * inside_axis[2]) * p;
      }
  return Eigen::Matrix3d::Identity() + d_stu * inverse_frame_;
}

void Deformer::weights(const Eigen::Vector3d& x, std::vector<std::pair<std::size_t, double>>& out) const {
  out.clear();
  Weights3 w;
  if (!evaluate_weights(*this, x, Outside::none, w, false)) return;
  const AxisWeights &wu = w.a[0], &wv = w.a[1], &ww = w.a[2];
  for (int c = 0; c < ww.count; ++c)
    for (int b = 0; b < wv.count; ++b)
      for (int a = 0; a < wu.count; ++a)
        out.emplace_back(lattice_.index(wu.first + a, wv.first + b, ww.first + c),
                         wu.w[static_cast<std::size_t>(a)] * wv.w[static_cast<std::size_t>(b)] * ww.w[static_cast<std::size_t>(c)]);
}

void apply_all(const Deformer& deformer, std::vector<Eigen::Vector3d>& points, Outside outside, int threads) {
  constexpr std::size_t chunk = 4096;
  const std::size_t jobs = (points.size() + chunk - 1) / chunk;
  parallel_for(jobs, threads, [&](std::size_t j) {
    const std::size_t end = std::min(points.size(), (j + 1) * chunk);
    for (std::size_t i = j * chunk; i < end; ++i) points[i] = deformer.apply(points[i], outside);
  });
}

}  // namespace fest::ffd
