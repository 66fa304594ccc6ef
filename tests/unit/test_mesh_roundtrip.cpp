// Write -> read round trips of every mesh format on hand-built meshes whose content is
// known exactly (test_mesh_helpers.hpp): geometry must come back bit for bit, in order.

#include <nlohmann/json.hpp>

#include "test_mesh_helpers.hpp"

namespace fest::test {
namespace {

using formats::Format;
using formats::MeshWriteOptions;

struct Variant {
  Format format;
  bool ascii;
  const char* name;
};

const Variant all_variants[] = {
    {Format::ply, false, "ply-binary"}, {Format::ply, true, "ply-ascii"}, {Format::off, true, "off"},
    {Format::obj, true, "obj"},         {Format::stl, true, "stl-ascii"}, {Format::drc, false, "drc-lossless"},
};

Mesh round_trip(const Mesh& mesh, const Variant& variant) {
  MeshWriteOptions options;
  options.ascii = variant.ascii;
  return formats::read_mesh(formats::write_mesh(mesh, variant.format, options), variant.format);
}

TEST(MeshRoundTrip, TetrahedronGeometryIsExactInEveryFormat) {
  // Coordinates such as 1/3, 1e-300 and 1e300 are not floats: only exact (shortest
  // round-trip) text and double binary properties keep them.
  const Mesh tetra = attributed_tetrahedron();
  for (const Variant& variant : all_variants) {
    if (variant.format == Format::stl) continue;  // below: STL renumbers vertices
    SCOPED_TRACE(variant.name);
    expect_same_geometry(tetra, round_trip(tetra, variant));
  }
}

// Each face's corner coordinates in order: what STL (a triangle soup) keeps.
std::vector<std::vector<double>> triangle_soup(const Mesh& mesh) {
  std::vector<std::vector<double>> soup;
  for (auto f : mesh.faces()) {
    soup.emplace_back();
    for (auto v : mesh.fv_range(f))
      for (int k = 0; k < 3; ++k) soup.back().push_back(mesh.point(v)[k]);
  }
  return soup;
}

TEST(MeshRoundTrip, AsciiStlKeepsEveryTriangleExactly) {
  // STL has no vertex list: vertices come back in order of first appearance, but
  // every triangle's corners keep their exact coordinates and order.
  const Mesh tetra = attributed_tetrahedron();
  Mesh back = round_trip(tetra, {Format::stl, true, "stl-ascii"});
  EXPECT_EQ(back.n_vertices(), 4u);
  EXPECT_EQ(triangle_soup(back), triangle_soup(tetra));
  EXPECT_EQ(face_lists(back)[0], (std::vector<int>{0, 1, 2}));  // tetra's first face is 0 2 1
  EXPECT_TRUE(same_bits(back.point(Mesh::VertexHandle(1))[1], 1e300));
}

TEST(MeshRoundTrip, VertexAttributesSurvivePlyOffObjDraco) {
  const Mesh tetra = attributed_tetrahedron();
  for (const Variant& variant : all_variants) {
    if (variant.format == Format::stl) continue;  // STL has no vertex attributes
    SCOPED_TRACE(variant.name);
    expect_same_vertex_attributes(tetra, round_trip(tetra, variant));
  }
}

TEST(MeshRoundTrip, QuadCubeKeepsQuadsAndFaceColours) {
  const Mesh cube = quad_cube();
  for (const Variant& variant : all_variants) {
    if (variant.format == Format::stl || variant.format == Format::drc) continue;  // triangles only
    SCOPED_TRACE(variant.name);
    Mesh back = round_trip(cube, variant);
    expect_same_geometry(cube, back);
    if (variant.format == Format::obj) continue;  // OBJ has no face colours
    ASSERT_TRUE(back.has_face_colors());
    for (auto f : cube.faces()) EXPECT_EQ(cube.color(f), back.color(Mesh::FaceHandle(f.idx())));
  }
}

TEST(MeshRoundTrip, TriangleOnlyFormatsSplitEachQuadIntoTwoTriangles) {
  const Mesh cube = quad_cube();
  for (Variant variant : {Variant{Format::stl, true, "stl-ascii"}, Variant{Format::stl, false, "stl-binary"},
                          Variant{Format::drc, false, "drc"}}) {
    SCOPED_TRACE(variant.name);
    Mesh back = round_trip(cube, variant);
    EXPECT_EQ(back.n_vertices(), 8u);
    EXPECT_EQ(back.n_faces(), 12u);  // 6 quads -> 12 triangles
    EXPECT_EQ(back.n_edges(), 18u);  // Euler: V - E + F = 2 for the closed cube
    EXPECT_EQ(formats::skipped_faces(back), 0u);
  }
}

TEST(MeshRoundTrip, BinaryPlyStoresFloatsOnlyWhenExact) {
  Mesh exact = quad_cube();  // +-1 are floats
  std::string bytes = formats::write_mesh(exact, Format::ply);
  EXPECT_NE(bytes.find("property float x"), std::string::npos);
  EXPECT_EQ(bytes.size(), bytes.find("end_header\n") + 11 + 8 * 12 + 6 * (1 + 16 + 3));

  Mesh doubles = attributed_tetrahedron();  // 1/3 is no float
  bytes = formats::write_mesh(doubles, Format::ply);
  EXPECT_NE(bytes.find("property double x"), std::string::npos);
  EXPECT_NE(bytes.find("property double nx"), std::string::npos);
}

TEST(MeshRoundTrip, BinaryStlRoundsToFloatButKeepsFloats) {
  // Binary STL is float by definition: float coordinates survive exactly.
  const Mesh cube = quad_cube();
  MeshWriteOptions binary;
  std::string bytes = formats::write_mesh(cube, Format::stl, binary);
  EXPECT_EQ(bytes.size(), 84u + 50u * 12u);
  Mesh back = formats::read_mesh(bytes, Format::stl);
  nlohmann::json info = formats::describe_mesh(back);
  EXPECT_EQ(info["bbox"]["min"], nlohmann::json({-1.0, -1.0, -1.0}));
  EXPECT_EQ(info["bbox"]["max"], nlohmann::json({1.0, 1.0, 1.0}));
}

TEST(MeshRoundTrip, StlFacetNormalsAreUnitOutwardNormals) {
  // The writer computes facet normals; the cube's are the axis directions.
  Mesh back = round_trip(quad_cube(), {Format::stl, true, "stl-ascii"});
  ASSERT_TRUE(back.has_face_normals());
  for (auto f : back.faces()) {
    Mesh::Point centre(0, 0, 0);
    for (auto v : back.fv_range(f)) centre += back.point(v);
    centre /= 3.0;
    Mesh::Normal n = back.normal(f);
    EXPECT_DOUBLE_EQ(n.norm(), 1.0);
    EXPECT_GT(n | centre, 0.0);  // points away from the cube's centre
  }
}

TEST(MeshRoundTrip, DescribeMeshReportsCountsBoxAndAttributes) {
  nlohmann::json cube = formats::describe_mesh(quad_cube());
  EXPECT_EQ(cube["vertices"], 8);
  EXPECT_EQ(cube["faces"], 6);
  EXPECT_EQ(cube["edges"], 12);
  EXPECT_EQ(cube["triangles"], false);
  EXPECT_EQ(cube["attributes"], nlohmann::json({"face_colors"}));
  EXPECT_FALSE(cube.contains("skipped_faces"));

  nlohmann::json tetra = formats::describe_mesh(attributed_tetrahedron());
  EXPECT_EQ(tetra["triangles"], true);
  EXPECT_EQ(tetra["edges"], 6);
  EXPECT_EQ(tetra["bbox"]["min"], nlohmann::json({-7.25, 0.0, -0.0}));
  EXPECT_EQ(tetra["bbox"]["max"], nlohmann::json({3.141592653589793, 1e300, 2.5}));
  EXPECT_EQ(tetra["attributes"], nlohmann::json({"vertex_normals", "vertex_colors", "vertex_texcoords"}));

  EXPECT_TRUE(formats::describe_mesh(Mesh())["bbox"].is_null());
}

TEST(MeshRoundTrip, EmptyMeshWritesAndReadsBackInTextFormats) {
  for (Variant variant : {Variant{Format::ply, false, "ply-binary"}, Variant{Format::ply, true, "ply-ascii"},
                          Variant{Format::off, true, "off"}}) {
    SCOPED_TRACE(variant.name);
    Mesh back = round_trip(Mesh(), variant);
    EXPECT_EQ(back.n_vertices(), 0u);
    EXPECT_EQ(back.n_faces(), 0u);
  }
}

TEST(MeshRoundTrip, PointCloudRoundTripsThroughDraco) {
  Mesh cloud;
  for (int i = 0; i < 5; ++i) cloud.add_vertex(Mesh::Point(i, i * 0.5, -i));
  Mesh back = round_trip(cloud, {Format::drc, false, "drc"});
  expect_same_geometry(cloud, back);
}

TEST(MeshRoundTrip, DeletedElementsAreCompactedBeforeWriting) {
  Mesh cube = quad_cube();
  cube.request_vertex_status();
  cube.request_edge_status();
  cube.request_halfedge_status();
  cube.request_face_status();
  cube.delete_face(Mesh::FaceHandle(0), false);
  Mesh back = formats::read_mesh(formats::write_mesh(cube, Format::off), Format::off);
  EXPECT_EQ(back.n_vertices(), 8u);
  EXPECT_EQ(back.n_faces(), 5u);
}

}  // namespace
}  // namespace fest::test
