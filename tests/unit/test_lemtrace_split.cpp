// Splitting and mesh building (docs/lemtrace.md §4): conforming tetrahedralisation of
// hexahedra, wedges and pyramids (every interior triangle shared by exactly two tets,
// volume preserved), orientation repair, and the bad meshes that must be refused.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/split_cells.hpp"
#include "lemtrace/tet_mesh.hpp"

namespace {

using namespace fest::lemtrace;

double total_volume(const TetMesh& m) {
  double v = 0;
  for (const Tet& t : m.tets) v += signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
  return v;
}

std::size_t boundary_faces(const TetMesh& m) {
  std::size_t n = 0;
  for (const Tet& nb : m.neighbors)
    for (int k = 0; k < 4; ++k) n += nb[k] < 0;
  return n;
}

TEST(LemtraceSplit, JitteredHexGridIsConformingAndKeepsVolume) {
  for (int n : {1, 3, 6}) {
    GenOptions o;
    o.kind = "uniform";
    o.n = n;
    o.jitter = 0.3;
    o.hex = true;
    const GeneratedGrid g = generate(o);
    MeshReport rep;
    const TetMesh m = build_tet_mesh(g.points, g.vectors, g.cells, BuildOptions{}, &rep);
    EXPECT_EQ(m.tets.size(), static_cast<std::size_t>(6 * n * n * n));
    EXPECT_EQ(rep.split_cells, static_cast<std::size_t>(n * n * n));
    // Only the cube's 6 n^2 squares (2 triangles each) are boundary: every other
    // triangle has exactly one tet on the other side.
    EXPECT_EQ(boundary_faces(m), static_cast<std::size_t>(12 * n * n));
    EXPECT_NEAR(total_volume(m), 8.0, 1e-12);
    for (std::size_t c = 0; c < m.tets.size(); ++c)
      for (int k = 0; k < 4; ++k) {
        const int32_t o2 = m.neighbors[c][k];
        if (o2 < 0) continue;
        int back = 0;
        for (int j = 0; j < 4; ++j) back += m.neighbors[static_cast<std::size_t>(o2)][j] == static_cast<int32_t>(c);
        EXPECT_EQ(back, 1);
      }
  }
}

TEST(LemtraceSplit, WedgesAndPyramidsShareQuadFacesConformingly) {
  // Two wedges sharing the quad (1, 2, 5, 4), then a pyramid on top of a cube face.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 0}, {1, 1, 1}};
  RawCells cells;
  cells.add(13, {0, 1, 2, 3, 4, 5});
  cells.add(13, {6, 2, 1, 7, 5, 4});
  std::vector<Vec3> v(p.size(), Vec3(1, 0, 0));
  MeshReport rep;
  TetMesh m = build_tet_mesh(p, v, cells, BuildOptions{}, &rep);
  EXPECT_EQ(m.tets.size(), 6u);
  EXPECT_NEAR(total_volume(m), 1.0, 1e-14);
  // The unit cube's 6 faces = 12 boundary triangles; the shared quad is interior.
  EXPECT_EQ(boundary_faces(m), 12u);

  std::vector<Vec3> q = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  RawCells pyr;
  pyr.add(14, {0, 1, 2, 3, 4});
  m = build_tet_mesh(q, std::vector<Vec3>(q.size(), Vec3::Zero()), pyr, BuildOptions{}, &rep);
  EXPECT_EQ(m.tets.size(), 2u);
  EXPECT_NEAR(total_volume(m), 1.0 / 3.0, 1e-14);
}

TEST(LemtraceSplit, NegativeTetsAreReordered) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  RawCells cells;
  cells.add(10, {0, 2, 1, 3});  // negative orientation
  MeshReport rep;
  const TetMesh m = build_tet_mesh(p, std::vector<Vec3>(4, Vec3::Zero()), cells, BuildOptions{}, &rep);
  EXPECT_EQ(rep.flipped, 1u);
  EXPECT_GT(total_volume(m), 0);
}

void expect_bad_input(const std::vector<Vec3>& p, const RawCells& cells, const char* fragment, bool split = true) {
  BuildOptions o;
  o.split = split;
  try {
    build_tet_mesh(p, std::vector<Vec3>(p.size(), Vec3::Zero()), cells, o, nullptr);
    FAIL() << "accepted a mesh that should be refused (" << fragment << ")";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(LemtraceSplit, BadMeshesAreRefused) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.2, 0.2, 1}, {1, 1, 0}};
  RawCells flat;
  flat.add(10, {0, 1, 2, 6});
  expect_bad_input(p, flat, "zero volume");
  RawCells tri;
  tri.add(5, {0, 1, 2});
  expect_bad_input(p, tri, "triangle");
  RawCells three;  // three tets on the face (0, 1, 2)
  three.add(10, {0, 1, 2, 3});
  three.add(10, {0, 1, 2, 4});
  three.add(10, {0, 1, 2, 5});
  expect_bad_input(p, three, "non-manifold");
  RawCells out_of_range;
  out_of_range.add(10, {0, 1, 2, 9});
  expect_bad_input(p, out_of_range, "refers to point 9");
  RawCells hex;
  hex.add(12, {0, 1, 2, 3, 4, 5, 6, 0});
  expect_bad_input(p, hex, "only tetrahedra are accepted", false);
}

}  // namespace
