// softobj property tests (docs/softobj.md §6) on random connected skeletons: triangle
// strips from a random walk (fixed seeds), 1-20 triangles. Whatever the shape, every
// vertex lies on f = V*, the mesh is closed with Euler characteristic 2 and positive
// volume, and every chord satisfies both acceptability bounds.
#include <random>

#include <gtest/gtest.h>

#include "softobj/field.hpp"
#include "softobj/mesh_measures.hpp"
#include "softobj/shrinkwrap.hpp"

using namespace fest::softobj;

TEST(SoftobjRandom, StripsAreClosedOnSurfaceAndAcceptable) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> count(1, 20);
    const int n = count(rng);
    Skeleton s;
    s.vertices = {{0, 0, 0}, {4, 0, 0}};
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d a = s.vertices[s.vertices.size() - 2], b = s.vertices.back();
      Eigen::Vector3d step(u(rng), u(rng), 0.4 * u(rng));
      s.vertices.push_back(0.5 * (a + b) + 4 * step.normalized());
      s.triangles.push_back({static_cast<int>(s.vertices.size()) - 3, static_cast<int>(s.vertices.size()) - 2,
                             static_cast<int>(s.vertices.size()) - 1});
    }
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
