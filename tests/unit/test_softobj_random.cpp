// softobj property tests (docs/softobj.md §6) on random connected skeletons: triangle
// strips from a random walk (fixed seeds), 1-20 triangles. Whatever the shape, every
// vertex lies on f = V*, the mesh is closed with Euler characteristic 2 and positive
// volume, and every chord satisfies both acceptability bounds.
#include <random>

#include <gtest/gtest.h>

#include "softobj/field.hpp"
#include "softobj/mesh_measures.hpp"
#include "softobj/shrinkwrap.hpp"
#include "softobj_random_strip.hpp"

using namespace fest::softobj;

TEST(SoftobjRandom, StripsAreClosedOnSurfaceAndAcceptable) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    int n = 0;
    const Skeleton s = fest::softobj::testing::random_strip(seed, &n);
    const Field f(compile_terms(s));
    ShrinkwrapOptions o;
    o.iso = 1.0 / 3;  // rho = 3
    const fest::TriMesh m = shrinkwrap(f, o);
    const MeshMeasures mm = measure(m);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(n) + " triangles");
    EXPECT_LE(max_iso_error(f, m, o.iso), 1e-6);
    EXPECT_TRUE(mm.closed);
    EXPECT_EQ(mm.euler_characteristic, 2);
    EXPECT_GT(mm.volume, 0);
    EXPECT_LE(mm.max_edge, 3 * (1 + 1e-9));
    EXPECT_LE(mm.max_normal_angle_deg, 15 + 1e-9);
  }
}

TEST(SoftobjRandom, ScalingAndTranslationCarryOver) {
  // f for the skeleton scaled by s, at s r, is f(r)/s: with iso / s the surface (and, the
  // thresholds being relative, the mesh) scales by s. A translation moves it.
  Skeleton s;
  s.vertices = {{0, 0, 0}, {12, 0, 0}, {5, 9, 2}, {3, -7, 4}};
  s.triangles = {{0, 1, 2}, {0, 3, 1}};
  Skeleton t = s;
  const double k = 2.5;
  const Eigen::Vector3d shift(100, -40, 7);
  for (auto& v : t.vertices) v = k * v + shift;
  ShrinkwrapOptions o;
  o.iso = 1.0 / 3;
  const fest::TriMesh a = shrinkwrap(Field(compile_terms(s)), o);
  o.iso /= k;
  const fest::TriMesh b = shrinkwrap(Field(compile_terms(t)), o);
  const MeshMeasures ma = measure(a), mb = measure(b);
  EXPECT_NEAR(mb.volume, k * k * k * ma.volume, 1e-3 * mb.volume);
  EXPECT_NEAR(mb.area, k * k * ma.area, 1e-3 * mb.area);
  ASSERT_EQ(a.n_vertices(), b.n_vertices());  // the same decisions at every step
  {
    double worst = 0;
    for (auto v : a.vertices()) {
      const auto& p = a.point(v);
      const auto& q = b.point(fest::TriMesh::VertexHandle(v.idx()));
      worst = std::max(worst, (Eigen::Vector3d(q[0], q[1], q[2]) - (k * Eigen::Vector3d(p[0], p[1], p[2]) + shift)).norm());
    }
    EXPECT_LT(worst, 1e-6 * 3 * k);
  }
}
