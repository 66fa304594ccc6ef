#pragma once
// A free-form deformation lattice (Sederberg & Parry 1986, section 3; docs/ffd.md 2.1-2.2):
// a parallelepiped X0 + s S + t T + u U, (s, t, u) in [0, 1]^3, with L x M x N control
// points stored as displacements from their rest positions. The deformation is
//     X' = X + sum_ijk w_i(s) w_j(t) w_k(u) dP_ijk                (X inside the box)
// which equals S&P's eq. (1)-(2) sum B P_ijk for the Bernstein basis because the rest
// points reproduce X (linear precision), and is the identity for dP = 0 with every basis.

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "ffd/basis.hpp"

namespace fest::ffd {

enum class Outside { none, clamp };

struct Lattice {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 3> axes{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  std::array<int, 3> dims{2, 2, 2};
  std::array<Basis, 3> basis{Basis::bernstein, Basis::bernstein, Basis::bernstein};
  std::vector<Eigen::Vector3d> displacement;  // index i + L (j + M k); empty = all zero

  std::size_t size() const { return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(dims[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k);
  }
  // Rest position P0_ijk of a control point (uniform, or Greville for bspline axes).
  Eigen::Vector3d rest_point(int i, int j, int k) const;
  // Throws fest::Error(bad_input) for a degenerate box ((T x U).S ~ 0), dims outside
  // 2..max_axis_points, a displacement count that does not match, non-finite values.
  void validate() const;
};

// The frame of a validated lattice: local coordinates (S&P section 3) and evaluation.
class Deformer {
 public:
  explicit Deformer(const Lattice& lattice);  // validates

  // (s, t, u) of X: s = (T x U).(X - X0) / ((T x U).S), and likewise.
  Eigen::Vector3d local(const Eigen::Vector3d& x) const { return inverse_frame_ * (x - lattice_.origin); }
  // Inside the closed box (a tolerance of 1e-12 absorbs rounding of points on its faces).
  static bool inside(const Eigen::Vector3d& stu);

  // Deformed position of X; points outside stay put (Outside::none) or take the
  // displacement of the nearest box point (Outside::clamp).
  Eigen::Vector3d apply(const Eigen::Vector3d& x, Outside outside = Outside::none) const;
  // Jacobian dX'/dX: I + sum dP (grad_stu w)^T (d stu / dX) (docs/ffd.md 2.2).
  Eigen::Matrix3d jacobian(const Eigen::Vector3d& x, Outside outside = Outside::none) const;
  // The tensor-product weights of X's control points (index, weight), for the joint
  // constraints of docs/ffd.md 2.3; empty outside the box.
  void weights(const Eigen::Vector3d& x, std::vector<std::pair<std::size_t, double>>& out) const;

  const Lattice& lattice() const { return lattice_; }
  const Eigen::Matrix3d& inverse_frame() const { return inverse_frame_; }

 private:
  Lattice lattice_;
  Eigen::Matrix3d inverse_frame_;
};

// Deforms many points (parallel over `threads`, results identical for any count).
void apply_all(const Deformer& deformer, std::vector<Eigen::Vector3d>& points, Outside outside, int threads);

}  // namespace fest::ffd
