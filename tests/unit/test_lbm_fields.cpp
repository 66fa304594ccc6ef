// Derived fields on fields whose derivatives are known exactly (docs/lbmsim.md 2.7).
#include <gtest/gtest.h>

#include "lbm/fields.hpp"

namespace fest::lbm {
namespace {

TEST(LbmFields, SolidBodyRotationHasVorticityTwoOmegaAndQOmegaSquared) {
  Case c;
  c.dim = 3;
  c.lattice = LatticeKind::d3q19;
  c.size = {6, 5, 4};
  for (auto& f : c.faces) f.kind = Face::Kind::wall;
  const Flags flags = shape_flags(c);
  const double W = 0.01;
  std::vector<double> rho(c.cells(), 1.0), u(3 * c.cells());
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 6; ++x) {
        const std::size_t k = flags.index(x, y, z);
        u[3 * k] = -W * y;
        u[3 * k + 1] = W * x;
        u[3 * k + 2] = 0.0;
      }
  const auto f = derived_fields({"vorticity", "qcriterion", "speed"}, c, flags, rho, u, 1.0, 0.5);
  ASSERT_EQ(f.size(), 3u);
  // spacing 0.5: derivatives double.
  for (std::size_t k = 0; k < c.cells(); ++k) {
    EXPECT_NEAR(f[1].values[3 * k + 2], 2 * W * 2, 1e-15);   // vorticity (3-D vector), z component
    EXPECT_NEAR(f[2].values[k], (2 * W) * (2 * W), 1e-15);   // Q = Omega^2
  }
}

TEST(LbmFields, UnknownNameGetsAHint) {
  try {
    check_field_names({"density", "vortcity"}, "--fields");
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_STREQ(e.what(), "field \"vortcity\" is unknown (did you mean \"vorticity\"?) (--fields)");
  }
}

}  // namespace
}  // namespace fest::lbm
