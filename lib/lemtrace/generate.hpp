#pragma once
// Synthetic grids with known fields (lemtrace(1) `gen`): a cube [-1, 1]^3 of n^3 hexahedra,
// optionally jittered, split conformingly into tetrahedra (or kept as hexahedra), with
// a field evaluated at the vertices. Globally linear fields (v = A x + b) are reproduced
// exactly by the piecewise-linear interpolant, so their paths are known in closed form:
// x(t) = exp(tA) x0 + t phi1(tA) b.

#include <cstdint>
#include <string>
#include <vector>

#include "lemtrace/tet_mesh.hpp"

namespace fest::lemtrace {

struct LinearField {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Vec3 b = Vec3::Zero();
};

struct GenOptions {
  std::string kind = "helix";
  int n = 40;
  double jitter = 0.0;      // fraction of the cell size
  uint64_t seed = 1;
  bool hex = false;         // keep hexahedra (the tool then splits them)
};

struct GeneratedGrid {
  std::vector<Vec3> points;
  std::vector<Vec3> vectors;
  RawCells cells;
  bool linear = false;      // field is A x + b everywhere
  LinearField field;
};

// The kinds gen knows, in the order of the man page.
const std::vector<std::string>& gen_kinds();
// Throws usage_error for an unknown kind or n < 1.
GeneratedGrid generate(const GenOptions& options);
// The linear field of a linear kind (throws usage_error otherwise).
LinearField linear_kind(const std::string& kind, bool* is_linear);
// The nonlinear fields, for tests and references.
Vec3 sphere_potential_velocity(const Vec3& x);   // U = e_z, R = 0.4
Vec3 abc_velocity(const Vec3& x);

}  // namespace fest::lemtrace

namespace fest::lemtrace {
// x(t) = exp(tA) x0 + t phi1(tA) b, from the exponential of [[A, b], [0, 0]] t.
Vec3 linear_flow(const LinearField& field, const Vec3& x0, double t);
}  // namespace fest::lemtrace
