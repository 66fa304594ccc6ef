// softobj palate (docs/softobj.md §4.1): pass 1 puts a penetrating point on the virtual
// sphere with its segment's length kept, steps a point off the plane and scales the
// row's coronal lengths by exactly 1 + ratio; pass 2 leaves no vertex outside.
#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "softobj/field.hpp"
#include "softobj/palate.hpp"
#include "softobj/shrinkwrap.hpp"

using namespace fest::softobj;

TEST(SoftobjPalate, SphereRotationKeepsLength) {
  Palate pl;  // centre (-10, -24, 0), R = 40; virtual radius 34 for rho = 6
  TongueParams p = neutral_tongue();
  p[14] = 60;  // a3: the back segment turns steeply upwards
  const auto before = tongue_points(p);
  ASSERT_GT((before[3] - pl.centre).norm(), 34);
  const PalateFix fix = palate_pass1(p, pl, 6);
  EXPECT_GE(fix.sphere, 1);
  const auto after = tongue_points(p);
  EXPECT_NEAR((after[3] - pl.centre).norm(), 34, 1e-9);
  EXPECT_NEAR((after[3] - after[2]).norm(), 17, 1e-12);  // l3 kept
  EXPECT_DOUBLE_EQ(p[5], 17);
}

TEST(SoftobjPalate, PlaneStepScalesCoronalLengths) {
  Palate pl;  // strip x <= 14 for y in [-8, 6]; virtual plane x = 8 for rho = 6
  TongueParams p = neutral_tongue();
  p[0] = 12;  // x0: the tip 4 mm beyond the virtual plane
  const double l1 = p[3], l4 = p[6], l5 = p[7];
  const PalateFix fix = palate_pass1(p, pl, 6);
  EXPECT_EQ(fix.plane, 1);
  const auto vl = tongue_points(p);
  EXPECT_NEAR(vl[0].x(), 8, 1e-12);
  const double ratio = (l1 - p[3]) / l1;
  EXPECT_DOUBLE_EQ(p[6], l4 * (1 + ratio));
  EXPECT_DOUBLE_EQ(p[7], l5 * (1 + ratio));
}

TEST(SoftobjPalate, Pass2LeavesNothingOutside) {
  Palate pl;
  pl.radius = 30;  // a tight palate
  pl.plane[2] = -6;
  const Field f(compile_terms(tongue_skeleton(neutral_tongue(), TongueLayout::default10, 6)));
  ShrinkwrapOptions o;
  o.iso = 1.0 / 6;
  fest::TriMesh m = shrinkwrap(f, o);
  EXPECT_GT(palate_pass2(m, pl), 0u);
  for (auto v : m.vertices()) {
    const Eigen::Vector3d q(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
    if (q.x() > pl.centre.x()) {
      EXPECT_LE((q - pl.centre).norm(), pl.radius + 1e-9);
    }
    if (q.y() >= -8 && q.y() <= 6 && std::abs(q.z()) <= 20) {
      EXPECT_LE(q.x(), 6 + 1e-9);
    }
  }
}

TEST(SoftobjPalate, DecodeRejectsBadInput) {
  EXPECT_NO_THROW(decode_palate(R"({"sphere": {"center": [-10,-24,0], "radius": 40},
    "strip": {"plane": [1,0,-14], "y_range": [-8,6], "width": 40}, "step": 4})"));
  EXPECT_THROW(decode_palate(R"({"sphere": {"center": [0,0], "radius": 40}, "strip": {}})"), fest::Error);
  EXPECT_THROW(decode_palate(R"({"sphere": {"center": [0,0,0], "radius": -1},
    "strip": {"plane": [1,0,-14], "y_range": [-8,6], "width": 40}})"), fest::Error);
}
