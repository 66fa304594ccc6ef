// Consistency and stability checks of a case (docs/lbmsim.md "Guards").
#include "lbm/case.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::lbm {

const char* face_name(int face) noexcept {
  static const char* const names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  return face >= 0 && face < 6 ? names[face] : "?";
}

void validate_case(Case& c, const std::string& where) {
  if (!(c.collision.tau > 0.5 + 1e-4))
    throw bad_input("collision.tau = {} gives zero viscosity; need tau > 0.5 ({})", c.collision.tau, where);
  for (int a = 0; a < c.dim; ++a) {
    const bool lo = c.faces[2 * a].kind == Face::Kind::periodic, hi = c.faces[2 * a + 1].kind == Face::Kind::periodic;
    if (lo != hi)
      throw bad_input("faces {} and {}: a periodic face needs a periodic opposite face ({})", face_name(2 * a),
                      face_name(2 * a + 1), where);
  }
  double umax = c.u_ref;
  for (int i = 0; i < 2 * c.dim; ++i) {
    const Face& f = c.faces[i];
    double s = 0;
    if (f.kind == Face::Kind::moving || (f.kind == Face::Kind::velocity && f.u_vector))
      s = std::sqrt(f.u[0] * f.u[0] + f.u[1] * f.u[1] + f.u[2] * f.u[2]);
    else if (f.kind == Face::Kind::velocity)
      s = std::abs(f.speed);
    umax = std::max(umax, s);
  }
  const double ma = umax * std::sqrt(3.0);
  if (ma > 0.3)
    throw bad_input("Mach number {:.3g} (lattice speed {:.3g}) exceeds 0.3: compressibility errors and instability; "
                    "lower u_ref/u_lattice and refine ({})",
                    ma, umax, where);
  if (ma > 0.2) c.warnings.push_back(fmt::format("Mach number {:.3g} is high", ma));
  if (c.collision.model == CollisionModel::bgk && c.collision.tau < 0.51)
    c.warnings.push_back(fmt::format("tau = {:.4g} is close to 1/2: BGK may be unstable; consider \"model\": \"trt\"",
                                     c.collision.tau));
  if (c.output.every < 0) throw bad_input("output.every must be >= 0 ({})", where);
  for (const auto& p : c.probes)
    for (int a = 0; a < c.dim; ++a)
      if (p[a] < 0 || p[a] > c.size[a])
        throw bad_input("probe at ({}, {}, {}) lies outside the lattice ({})", p[0], p[1], p[2], where);
}

}  // namespace fest::lbm
