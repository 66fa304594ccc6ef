// Draco: lossless round trip is exact and keeps order; quantized output stays within
// the quantization step.

#include <algorithm>
#include <cmath>

#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

using formats::Format;
using formats::MeshWriteOptions;

// A 20x20 grid of quads over [0, 2] x [0, 1] with a wavy height; coordinates are
// doubles that no float holds exactly.
Mesh wavy_grid() {
  Mesh mesh;
  const int n = 20;
  std::vector<Mesh::VertexHandle> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = 2.0 * i / n, y = 1.0 * j / n;
      v.push_back(mesh.add_vertex(Mesh::Point(x, y, 0.1 * std::sin(3 * x) * std::cos(5 * y))));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      auto at = [&](int a, int b) { return v[b * (n + 1) + a]; };
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return mesh;
}

TEST(MeshDraco, LosslessIsExactAndKeepsOrder) {
  const Mesh grid = wavy_grid();
  Mesh back = formats::read_mesh(formats::write_mesh(grid, Format::drc), Format::drc);
  expect_same_geometry(grid, back);
}

TEST(MeshDraco, QuantizedErrorIsWithinTheStep) {
  const Mesh grid = wavy_grid();
  const double extent = 2.0;  // largest bounding box side (x runs over [0, 2])
  for (int bits : {8, 11, 14}) {
    for (int speed : {10, 5, 0}) {  // sequential at 10, edgebreaker below
      SCOPED_TRACE("bits " + std::to_string(bits) + " speed " + std::to_string(speed));
      MeshWriteOptions options;
      options.draco_position_bits = bits;
      options.draco_speed = speed;
      Mesh back = formats::read_mesh(formats::write_mesh(grid, Format::drc, options), Format::drc);
      ASSERT_EQ(back.n_vertices(), grid.n_vertices());
      ASSERT_EQ(back.n_faces(), grid.n_faces());
      // Edgebreaker may reorder vertices: match each decoded vertex with the nearest
      // original one (the grid spacing 0.05 is far above the step).
      const double bound = extent / std::pow(2.0, bits);
      double worst = 0;
      for (auto v : back.vertices()) {
        double nearest = 1e9;
        for (auto w : grid.vertices()) {
          const Mesh::Point d = back.point(v) - grid.point(w);
          nearest = std::min(nearest, std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])}));
        }
        worst = std::max(worst, nearest);
      }
      EXPECT_LE(worst, bound);
    }
  }
}

TEST(MeshDraco, BunnyQuantizedWithinStep) {
  FEST_REQUIRE_TESTDATA(path, "meshes/bunny00.off");
  const Mesh bunny = formats::read_mesh(slurp(path), Format::off);
  MeshWriteOptions options;
  options.draco_position_bits = 14;
  options.draco_speed = 10;  // sequential: order kept, so vertices compare one to one
  std::string bytes = formats::write_mesh(bunny, Format::drc, options);
  EXPECT_LT(bytes.size(), formats::write_mesh(bunny, Format::drc).size());
  Mesh back = formats::read_mesh(bytes, Format::drc);
  ASSERT_EQ(back.n_vertices(), bunny.n_vertices());
  ASSERT_EQ(back.n_faces(), bunny.n_faces());
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (auto v : bunny.vertices())
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], bunny.point(v)[k]);
      hi[k] = std::max(hi[k], bunny.point(v)[k]);
    }
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double bound = extent / std::pow(2.0, 14);
  for (auto v : bunny.vertices()) {
    const Mesh::Point d = back.point(Mesh::VertexHandle(v.idx())) - bunny.point(v);
    ASSERT_LE(std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])}), bound) << v.idx();
  }
  EXPECT_EQ(face_lists(back), face_lists(bunny));
}

TEST(MeshDraco, OptionsOutOfRangeAreUsageErrors) {
  MeshWriteOptions options;
  options.draco_position_bits = 31;
  try {
    formats::write_mesh(wavy_grid(), Format::drc, options);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::usage);
  }
  options.draco_position_bits = 0;
  options.draco_speed = -1;
  EXPECT_THROW(formats::write_mesh(wavy_grid(), Format::drc, options), Error);
}

}  // namespace
}  // namespace fest::test
