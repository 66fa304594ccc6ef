// Format features of each reader, on committed fixtures (tests/data/mesh) and on
// byte strings built here, with expectations from the files' stated content.

#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

using formats::Format;

Mesh read_fixture(const std::string& name, Format format) {
  return formats::read_mesh(slurp(fixture("mesh/" + name)), format);
}

TEST(MeshReaders, OffWithFaceColours) {
  Mesh cube = read_fixture("cube_quads.off", Format::off);
  EXPECT_EQ(cube.n_vertices(), 8u);
  EXPECT_EQ(cube.n_faces(), 6u);
  EXPECT_EQ(cube.n_edges(), 12u);
  ASSERT_TRUE(cube.has_face_colors());
  EXPECT_EQ(cube.color(Mesh::FaceHandle(0)), Mesh::Color(255, 0, 0));
  EXPECT_EQ(cube.color(Mesh::FaceHandle(5)), Mesh::Color(255, 0, 255));
  EXPECT_EQ(face_lists(cube)[0], (std::vector<int>{0, 2, 3, 1}));
  EXPECT_EQ(cube.point(Mesh::VertexHandle(7)), Mesh::Point(1, 1, 1));
}

TEST(MeshReaders, OffVariantsCoffNoffStoff) {
  // Vertex fields in Geomview's order: x y z [nx ny nz] [r g b a] [s t].
  Mesh m = formats::read_mesh(
      "STCNOFF 3 1 0\n"
      "0 0 0  0 0 1  1.0 0.5 0 1  0.25 0.75\n"
      "1 0 0  0 0 1  255 128 0 255  1 0\n"
      "0 1 0  0 0 1  0 0 255  0 1\n"
      "3 0 1 2\n",
      Format::off);
  ASSERT_EQ(m.n_vertices(), 3u);
  ASSERT_TRUE(m.has_vertex_normals() && m.has_vertex_colors() && m.has_vertex_texcoords2D());
  EXPECT_EQ(m.normal(Mesh::VertexHandle(0)), Mesh::Normal(0, 0, 1));
  EXPECT_EQ(m.color(Mesh::VertexHandle(0)), Mesh::Color(255, 128, 0));  // 0.5 * 255 = 127.5 -> 128
  EXPECT_EQ(m.color(Mesh::VertexHandle(1)), Mesh::Color(255, 128, 0));  // integers: 0..255
  EXPECT_EQ(m.color(Mesh::VertexHandle(2)), Mesh::Color(0, 0, 255));    // alpha optional
  EXPECT_EQ(m.texcoord2D(Mesh::VertexHandle(0)), Mesh::TexCoord2D(0.25f, 0.75f));

  Mesh c = formats::read_mesh("COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n", Format::off);
  EXPECT_EQ(c.color(Mesh::VertexHandle(1)), Mesh::Color(0, 1, 0));  // all integers: 0..255 scale
  Mesh n = formats::read_mesh("NOFF\n3 1 0\n0 0 0 0 0 -1\n1 0 0 0 0 -1\n0 1 0 0 0 -1\n3 0 2 1\n", Format::off);
  EXPECT_EQ(n.normal(Mesh::VertexHandle(2)), Mesh::Normal(0, 0, -1));
}

TEST(MeshReaders, OffCommentsBlankLinesAndCrLf) {
  Mesh m = formats::read_mesh("OFF # comment\r\n\r\n# another\r\n3 1 0\r\n0 0 0\r\n1 0 0 # x axis\r\n0 1 0\r\n\r\n3 0 1 2\r\n",
                              Format::off);
  EXPECT_EQ(m.n_vertices(), 3u);
  EXPECT_EQ(m.n_faces(), 1u);
}

TEST(MeshReaders, PlyAsciiWithNormalsAndColours) {
  Mesh tetra = read_fixture("tetra_colors_normals.ply", Format::ply);
  EXPECT_EQ(tetra.n_vertices(), 4u);
  EXPECT_EQ(tetra.n_faces(), 4u);
  EXPECT_EQ(tetra.n_edges(), 6u);
  EXPECT_EQ(tetra.point(Mesh::VertexHandle(1)), Mesh::Point(1, -1, -1));
  EXPECT_EQ(tetra.normal(Mesh::VertexHandle(2))[2], -0.57735026);  // the text's exact value
  EXPECT_EQ(tetra.color(Mesh::VertexHandle(3)), Mesh::Color(255, 255, 255));
  // Every edge of a regular tetrahedron on cube corners is a face diagonal: 2*sqrt(2).
  for (auto e : tetra.edges()) EXPECT_DOUBLE_EQ(tetra.calc_edge_length(e), 2 * std::sqrt(2.0));
}

// Builds a binary PLY of one triangle by hand, in either byte order, with a double x.
std::string hand_binary_ply(bool big_endian) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 3\nproperty double x\nproperty float y\nproperty short z\n"
                    "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
  auto put = [&](const void* p, std::size_t n) {
    unsigned char raw[8];
    std::memcpy(raw, p, n);
    const std::uint16_t probe = 1;
    const bool host_little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    if (big_endian == host_little)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(raw[i], raw[n - 1 - i]);
    out.append(reinterpret_cast<const char*>(raw), n);
  };
  const double xs[3] = {0.1, 1.0 / 3.0, -2.5};
  const float ys[3] = {0.5f, -1.0f, 3.0f};
  const std::int16_t zs[3] = {-7, 0, 300};
  for (int i = 0; i < 3; ++i) {
    put(&xs[i], 8);
    put(&ys[i], 4);
    put(&zs[i], 2);
  }
  out.push_back(3);
  for (std::uint32_t i : {2u, 1u, 0u}) put(&i, 4);
  return out;
}

TEST(MeshReaders, PlyBinaryBothByteOrders) {
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big endian" : "little endian");
    Mesh m = formats::read_mesh(hand_binary_ply(big), Format::ply);
    ASSERT_EQ(m.n_vertices(), 3u);
    EXPECT_EQ(m.point(Mesh::VertexHandle(0)), Mesh::Point(0.1, 0.5, -7));
    EXPECT_EQ(m.point(Mesh::VertexHandle(1)), Mesh::Point(1.0 / 3.0, -1, 0));
    EXPECT_EQ(m.point(Mesh::VertexHandle(2)), Mesh::Point(-2.5, 3, 300));
    EXPECT_EQ(face_lists(m), (std::vector<std::vector<int>>{{2, 1, 0}}));
  }
}

TEST(MeshReaders, PlySkipsUnknownElementsAndProperties) {
  Mesh m = formats::read_mesh(
      "ply\nformat ascii 1.0\nelement material 2\nproperty list uchar float values\nproperty int id\n"
      "element vertex 3\nproperty float confidence\nproperty float x\nproperty float y\nproperty float z\n"
      "property list uchar int extra\nelement face 1\nproperty uchar flags\nproperty list uchar int vertex_index\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "2 0.5 0.25 7\n0 8\n"
      "0.9 0 0 0 0\n0.8 1 0 0 2 5 6\n0.7 0 1 0 1 9\n"
      "1 3 0 1 2\n"
      "0 1\n",
      Format::ply);
  EXPECT_EQ(m.n_vertices(), 3u);
  EXPECT_EQ(m.point(Mesh::VertexHandle(1)), Mesh::Point(1, 0, 0));
  EXPECT_EQ(face_lists(m), (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(MeshReaders, PlyFacesBeforeVertices) {
  Mesh m = formats::read_mesh(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n"
      "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n",
      Format::ply);
  EXPECT_EQ(m.n_faces(), 1u);
}

TEST(MeshReaders, ObjCornerAttributesAndRelativeIndices) {
  Mesh square = read_fixture("square_uv.obj", Format::obj);
  EXPECT_EQ(square.n_vertices(), 4u);
  EXPECT_EQ(face_lists(square), (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}}));
  ASSERT_TRUE(square.has_vertex_normals() && square.has_vertex_texcoords2D());
  for (auto v : square.vertices()) {
    EXPECT_EQ(square.normal(v), Mesh::Normal(0, 0, 1));
    const Mesh::Point& p = square.point(v);  // the fixture's texture coordinates are (x, y)
    EXPECT_EQ(square.texcoord2D(v), Mesh::TexCoord2D(static_cast<float>(p[0]), static_cast<float>(p[1])));
  }
}

TEST(MeshReaders, ObjVertexColoursExtension) {
  Mesh m = formats::read_mesh("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 0.5\nf 1 2 3\n", Format::obj);
  ASSERT_TRUE(m.has_vertex_colors());
  EXPECT_EQ(m.color(Mesh::VertexHandle(0)), Mesh::Color(255, 0, 0));
  EXPECT_EQ(m.color(Mesh::VertexHandle(2)), Mesh::Color(0, 0, 128));
}

TEST(MeshReaders, StlAsciiMergesSharedCorners) {
  Mesh square = read_fixture("triangle.stl", Format::stl);
  EXPECT_EQ(square.n_vertices(), 4u);  // 6 corners, 4 distinct points
  EXPECT_EQ(square.n_faces(), 2u);
  EXPECT_EQ(face_lists(square), (std::vector<std::vector<int>>{{0, 1, 2}, {1, 3, 2}}));
  ASSERT_TRUE(square.has_face_normals());
  EXPECT_EQ(square.normal(Mesh::FaceHandle(1)), Mesh::Normal(0, 0, 1));
}

TEST(MeshReaders, BinaryStlWhoseHeaderSaysSolid) {
  // Some exporters start the 80-byte binary header with "solid": the size decides.
  std::string bytes = formats::write_mesh(quad_cube(), Format::stl);
  std::memcpy(bytes.data(), "solid cube", 10);
  Mesh m = formats::read_mesh(bytes, Format::stl);
  EXPECT_EQ(m.n_vertices(), 8u);
  EXPECT_EQ(m.n_faces(), 12u);
}

TEST(MeshReaders, NonManifoldFacesAreSkippedAndCounted) {
  // Three triangles share the edge 0-1: the third cannot join OpenMesh's halfedge
  // structure. It is skipped and counted, not lost silently. A degenerate face (a
  // repeated vertex) and a two-vertex face are skipped too.
  const std::string off =
      "OFF\n5 5 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
      "3 0 1 2\n3 1 0 3\n3 0 1 4\n3 0 0 2\n2 0 1\n";
  Mesh m = formats::read_mesh(off, Format::off);
  EXPECT_EQ(m.n_vertices(), 5u);
  EXPECT_EQ(m.n_faces(), 2u);
  EXPECT_EQ(formats::skipped_faces(m), 3u);
  EXPECT_EQ(formats::describe_mesh(m)["skipped_faces"], 3);
}

TEST(MeshReaders, HugePolygonWithRepeatedVerticesIsSkippedQuickly) {
  // 300 000 corners cycling over three vertices: the repeated-vertex check must not
  // be quadratic (this once would have taken minutes).
  std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n300000";
  for (int i = 0; i < 300000; ++i) off += i % 3 == 0 ? " 0" : i % 3 == 1 ? " 1" : " 2";
  off += "\n";
  Mesh m = formats::read_mesh(off, Format::off);
  EXPECT_EQ(m.n_faces(), 0u);
  EXPECT_EQ(formats::skipped_faces(m), 1u);
}

TEST(MeshReaders, DescribeFixtures) {
  nlohmann::json tetra = formats::describe_mesh(read_fixture("tetra_colors_normals.ply", Format::ply));
  EXPECT_EQ(tetra["vertices"], 4);
  EXPECT_EQ(tetra["faces"], 4);
  EXPECT_EQ(tetra["triangles"], true);
  EXPECT_EQ(tetra["bbox"]["min"], nlohmann::json({-1.0, -1.0, -1.0}));
  EXPECT_EQ(tetra["attributes"], nlohmann::json({"vertex_normals", "vertex_colors"}));
  nlohmann::json cube = formats::describe_mesh(read_fixture("cube_quads.off", Format::off));
  EXPECT_EQ(cube["triangles"], false);
  EXPECT_EQ(cube["bbox"]["max"], nlohmann::json({1.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace fest::test
