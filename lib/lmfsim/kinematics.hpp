#pragma once
// Per-evaluation kinematic state of one body (or of the world) and the small vector
// helpers the constraint and force code shares.

#include <Eigen/Core>

#include "lmfsim/model.hpp"

namespace fest::lmfsim {

using Vec6 = Eigen::Matrix<double, 6, 1>;
// Blocks of the solvers: at most 6x6 (6 dof per rigid body, <= 6 rows per constraint),
// stored on the stack.
using Blk = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;
using Vecx = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1>;

struct BodyKin {
  Vec3 p = Vec3::Zero(), v = Vec3::Zero(), w = Vec3::Zero();  // w: angular velocity
  Mat3 R = Mat3::Identity();
  int dof = 0;  // 0 for world/fixed, 3 particle, 6 rigid
};

inline Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Two unit vectors perpendicular to n (and to each other), deterministic.
inline void perpendiculars(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : (std::abs(n.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  t1 = n.cross(helper).normalized();
  t2 = n.cross(t1);
}

}  // namespace fest::lmfsim
