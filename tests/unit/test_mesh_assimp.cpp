// assimp's OBJ and PLY test models (Debian assimp-testmodels, fetched by
// scripts/fetch-test-data.sh into meshes/assimp/): every face, line segment and point
// is read. The expected figures are assimp's own: `assimp info FILE -r` (assimp-utils
// 5.2.5, no post-processing) prints them as "Faces", counting faces, line segments and
// points together; tests/cli/fconv_assimp.sh asks assimp again at test time.
#include <fstream>
#include <string>

#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

using formats::Format;

struct Expected {
  const char* file;
  std::size_t faces, line_segments, points;  // assimp -r "Faces" = their sum
};

// spider.obj: assimp reports 1368 faces; WusonOBJ.obj 3732 (VTK's reader agrees).
constexpr Expected assimp_counts[] = {
    {"WusonOBJ.obj", 3732, 0, 0},      {"spider.obj", 1368, 0, 0},
    {"box_longline.obj", 6, 0, 0},     {"regr_3429812.obj", 3, 0, 0},
    {"space_in_material_name.obj", 1, 0, 0}, {"concave_polygon.obj", 1, 0, 0},
    {"testline.obj", 0, 18, 0},        {"testpoints.obj", 0, 0, 24},
    {"testmixed.obj", 6, 18, 24},
};

TEST(MeshAssimp, EveryPrimitiveOfEveryModelIsRead) {
  FEST_REQUIRE_TESTDATA(dir, "meshes/assimp");
  for (const Expected& e : assimp_counts) {
    const std::string path = dir + "/" + e.file;
    if (!std::ifstream(path).good()) GTEST_SKIP() << "fetched test data lacks " << path << " (run scripts/fetch-test-data.sh)";
    Mesh m = formats::read_mesh(slurp(path), Format::obj);
    EXPECT_EQ(formats::total_faces(m), e.faces) << e.file;
    EXPECT_EQ(formats::line_segments(m), e.line_segments) << e.file;
    EXPECT_EQ(formats::point_count(m), e.points) << e.file;
    // Converted to OBJ and read back, nothing is lost either.
    formats::carry_skipped_faces(m);
    const Mesh back = formats::read_mesh(formats::write_mesh(m, Format::obj), Format::obj);
    EXPECT_EQ(formats::total_faces(back), e.faces) << e.file;
    EXPECT_EQ(formats::skipped_face_list(back), formats::skipped_face_list(m)) << e.file;
    EXPECT_EQ(formats::line_segments(back), e.line_segments) << e.file;
    EXPECT_EQ(formats::point_count(back), e.points) << e.file;
  }
}

TEST(MeshAssimp, ConcavePolygonIsOneFaceOf66Corners) {
  FEST_REQUIRE_TESTDATA(path, "meshes/assimp/concave_polygon.obj");
  if (!std::ifstream(path).good()) GTEST_SKIP() << "fetched test data lacks " << path;
  const Mesh m = formats::read_mesh(slurp(path), Format::obj);
  // The file's one f line lists 66 corners; assimp -r: 1 face, 66 vertices.
  ASSERT_EQ(formats::total_faces(m), 1u);
  ASSERT_EQ(formats::faces_beside(m).size(), 1u);
  EXPECT_EQ(formats::faces_beside(m)[0].size(), 66u);
}

TEST(MeshAssimp, ConcavePolygonAsTrianglesCoversItsOwnArea) {
  FEST_REQUIRE_TESTDATA(path, "meshes/assimp/concave_polygon.obj");
  if (!std::ifstream(path).good()) GTEST_SKIP() << "fetched test data lacks " << path;
  Mesh m = formats::read_mesh(slurp(path), Format::obj);
  const std::vector<int> polygon = formats::faces_beside(m).at(0);
  // Anchor: the polygon's area from Newell's formula (half the length of the sum of
  // its edges' cross products), independent of any triangulation. Its fan around the
  // first corner covers 13 times that area (3.22 against 0.245).
  Mesh::Point newell(0, 0, 0);
  for (std::size_t i = 0; i < polygon.size(); ++i)
    newell += m.point(Mesh::VertexHandle(polygon[i])) % m.point(Mesh::VertexHandle(polygon[(i + 1) % polygon.size()]));
  const double area = 0.5 * newell.norm();
  formats::carry_skipped_faces(m);
  formats::MeshWriteOptions ascii;
  ascii.ascii = true;
  const Mesh stl = formats::read_mesh(formats::write_mesh(m, Format::stl, ascii), Format::stl);
  EXPECT_EQ(formats::total_faces(stl), 64u);  // n - 2 triangles
  double sum = 0;
  auto add = [&](const std::vector<Mesh::Point>& c) { sum += 0.5 * ((c[1] - c[0]) % (c[2] - c[0])).norm(); };
  for (auto f : stl.faces()) {
    std::vector<Mesh::Point> c;
    for (auto v : stl.fv_range(f)) c.push_back(stl.point(v));
    add(c);
  }
  for (const auto& face : formats::faces_beside(stl))
    add({stl.point(Mesh::VertexHandle(face[0])), stl.point(Mesh::VertexHandle(face[1])),
         stl.point(Mesh::VertexHandle(face[2]))});
  EXPECT_NEAR(sum, area, 1e-9 * area);
}

TEST(MeshAssimp, BlenderPlyWithoutCommentKeyword) {
  FEST_REQUIRE_TESTDATA(path, "meshes/assimp/Wuson.ply");
  if (!std::ifstream(path).good()) GTEST_SKIP() << "fetched test data lacks " << path;
  const Mesh m = formats::read_mesh(slurp(path), Format::ply);
  // assimp -r: 11184 vertices, 3732 faces.
  EXPECT_EQ(m.n_vertices(), 11184u);
  EXPECT_EQ(formats::total_faces(m), 3732u);
  EXPECT_EQ(formats::read_warnings(m).size(), 1u);
}

}  // namespace
}  // namespace fest::test
