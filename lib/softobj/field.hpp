#pragma once
// The potential field of a compiled skeleton (docs/softobj.md §1):
//   f(r) = sum_P p_P / d_P(r),   grad f = -sum_P p_P (r - R_P) / d_P^3,
// R_P the point of primitive P closest to r; d clamped to 1e-9 x scale.

#include <Eigen/Core>

#include "softobj/skeleton.hpp"

namespace fest::softobj {

struct FieldSample {
  double f = 0;
  Eigen::Vector3d grad = Eigen::Vector3d::Zero();
};

// The kernel of a primitive's contribution: the seed's Coulomb p/d, or (for comparison
// with classic soft objects; Wyvill, McPheeters & Wyvill 1986) p C(d) with
// C = 1 - 4/9 x^3 + 17/9 x^2 - 22/9 x, x = (d/R)^2, for d < R, else 0. Compact support:
// no far-field sphere, so shrink-wrap cannot start from one.
struct Kernel {
  enum Kind { coulomb, wyvill } kind = coulomb;
  double radius = 0;  // R of wyvill
};

class Field {
 public:
  explicit Field(CompiledSkeleton compiled, Kernel kernel = {});
  const Kernel& kernel() const { return kernel_; }
  FieldSample eval(const Eigen::Vector3d& r) const;
  double value(const Eigen::Vector3d& r) const { return eval(r).f; }
  const CompiledSkeleton& skeleton() const { return c_; }

 private:
  CompiledSkeleton c_;
  Kernel kernel_;
  double dmin_;
};

}  // namespace fest::softobj
