#pragma once
// The potential field of a compiled skeleton (docs/softobj.md §2.1):
//   f(r) = sum_P p_P / d_P(r),   grad f = -sum_P p_P (r - R_P) / d_P^3,
// R_P the point of primitive P closest to r; d clamped to 1e-9 x scale.

#include <Eigen/Core>

#include "softobj/skeleton.hpp"

namespace fest::softobj {

struct FieldSample {
  double f = 0;
  Eigen::Vector3d grad = Eigen::Vector3d::Zero();
};

class Field {
 public:
  explicit Field(CompiledSkeleton compiled);
  FieldSample eval(const Eigen::Vector3d& r) const;
  double value(const Eigen::Vector3d& r) const { return eval(r).f; }
  const CompiledSkeleton& skeleton() const { return c_; }

 private:
  CompiledSkeleton c_;
  double dmin_;
};

}  // namespace fest::softobj
