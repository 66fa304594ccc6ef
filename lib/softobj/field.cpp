#include "softobj/field.hpp"

#include <algorithm>
#include <cmath>

#include "softobj/closest.hpp"

namespace fest::softobj {

Field::Field(CompiledSkeleton compiled, Kernel kernel) : c_(std::move(compiled)), kernel_(kernel) {
  dmin_ = 1e-9 * std::max(1.0, c_.bound_radius);
}

FieldSample Field::eval(const Eigen::Vector3d& r) const {
  FieldSample s;
  for (const Term& t : c_.terms) {
    Eigen::Vector3d R;
    switch (t.kind) {
      case Term::point: R = t.v[0]; break;
      case Term::segment: R = closest_on_segment(r, t.v[0], t.v[1]); break;
      default: R = closest_on_triangle(r, t.v[0], t.v[1], t.v[2]); break;
    }
    const Eigen::Vector3d dr = r - R;
    const double d = std::max(dr.norm(), dmin_);
    if (kernel_.kind == Kernel::wyvill) {
      const double R2 = kernel_.radius * kernel_.radius, x = d * d / R2;
      if (x >= 1) continue;
      s.f += t.p * (1 - 4.0 / 9 * x * x * x + 17.0 / 9 * x * x - 22.0 / 9 * x);
      const double dCdx = -4.0 / 3 * x * x + 34.0 / 9 * x - 22.0 / 9;
      s.grad += (t.p * dCdx * 2 / R2) * dr;  // dC/dd (r - R)/d with dx/dd = 2 d / R^2
      continue;
    }
    s.f += t.p / d;                       // Coulomb potential p / |r - R|
    s.grad -= (t.p / (d * d * d)) * dr;   // its gradient -p (r - R) / d^3
  }
  return s;
}

}  // namespace fest::softobj
