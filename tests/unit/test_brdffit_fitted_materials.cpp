#include "brdffit/fitted_materials.hpp"

#include <gtest/gtest.h>

#include "brdffit/lafortune_model.hpp"
#include "core/error.hpp"

using namespace fest::brdffit;

namespace {

// Two clusters whose f_C differ in rho_d; basis lists start with f_C (index = cluster).
Projection two_clusters(const std::vector<std::uint16_t>& cluster) {
  Projection p;
  p.basis.model.lobes = 1;
  for (double rho : {0.2, 0.7}) {
    fest::reflectance::LafortuneBrdf b;
    b.rho_d = {rho, rho, rho};
    b.lobes.push_back({{-1, -1, -1}, {1, 1, 1}, {20, 20, 20}});
    p.basis.brdfs.push_back(from_brdf(p.basis.model, b));
  }
  p.basis.cluster_basis = {{0, 1}, {1, 0}};
  p.basis_size = 2;
  p.cluster = cluster;
  p.weights.assign(cluster.size() * 2, 0.5f);
  return p;
}

LumitexelSet on_triangles(const std::vector<std::uint32_t>& tri, const std::vector<std::uint16_t>& count) {
  LumitexelSet s;
  for (std::size_t i = 0; i < tri.size(); ++i) {
    Lumitexel l;
    l.triangle = tri[i];
    l.count = count[i];
    s.lumitexels.push_back(l);
  }
  return s;
}

}  // namespace

TEST(BrdffitFittedMaterials, MajorityClusterPerTriangleTiesLowFallbackLargest) {
  // Triangle 0: clusters 1, 1, 0 -> 1. Triangle 1: 0, 1 -> tie -> 0. Triangle 2: only a
  // lumitexel without samples -> fallback = the cluster with most voting lumitexels (1: 3
  // votes against 2). Triangle 3: nothing -> fallback.
  const Projection p = two_clusters({1, 1, 0, 0, 1, 0});
  const LumitexelSet s = on_triangles({0, 0, 0, 1, 1, 2}, {5, 5, 5, 5, 5, 0});
  const fest::reflectance::SurfaceMaterials m = materials_from_projection(p, s, 4);
  ASSERT_EQ(m.brdfs.size(), 2u);
  EXPECT_DOUBLE_EQ(m.brdfs[0].rho_d[0], 0.2);
  EXPECT_DOUBLE_EQ(m.brdfs[1].rho_d[0], 0.7);
  EXPECT_EQ(m.triangle_material, (std::vector<std::uint16_t>{1, 0, 1, 1}));
  EXPECT_TRUE(m.vertex_weights.empty());
}

TEST(BrdffitFittedMaterials, InconsistentInputsAreBadInput) {
  const Projection p = two_clusters({0, 1});
  EXPECT_THROW(materials_from_projection(p, on_triangles({0}, {3}), 2), fest::Error);        // counts differ
  EXPECT_THROW(materials_from_projection(p, on_triangles({0, 7}, {3, 3}), 2), fest::Error);  // triangle 7 of 2
}

TEST(BrdffitFittedMaterials, GapsTakeTheirNeighboursMajority) {
  // A strip of four triangles; lumitexels only on the ends (triangle 0: cluster 1,
  // triangle 3: cluster 0). Triangle 1 touches triangle 0 at two vertices and triangle 3
  // at one -> 1; triangle 2 touches 0 at one vertex and 3 at two -> 0. A fifth triangle
  // with no neighbour keeps the fallback (the largest cluster: 0, two votes against one).
  const Projection p = two_clusters({1, 0, 0});
  const LumitexelSet s = on_triangles({0, 3, 3}, {5, 5, 5});
  const std::vector<std::array<std::uint32_t, 3>> faces = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {3, 4, 5}, {6, 7, 8}};
  const fest::reflectance::SurfaceMaterials m = materials_from_projection(p, s, faces);
  EXPECT_EQ(m.triangle_material, (std::vector<std::uint16_t>{1, 1, 0, 0, 0}));
  // Without the mesh every gap takes the largest cluster.
  EXPECT_EQ(materials_from_projection(p, s, 5).triangle_material, (std::vector<std::uint16_t>{1, 0, 0, 0, 0}));
}
