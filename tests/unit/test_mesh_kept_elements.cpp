// Nothing a mesh file holds is lost on the way through fest (mesh_io.hpp): faces
// OpenMesh's halfedge structure refuses keep their place, line and point elements are
// kept, and a format that cannot hold something refuses it by name and count.
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_mesh_helpers.hpp"

namespace fest::test {
namespace {

using formats::Format;

// Every face a mesh holds in the order fest writes them (its own faces with the ones
// kept beside them in place), read from the OFF text it writes.
std::vector<std::vector<int>> faces_in_order(Mesh m) {
  formats::carry_skipped_faces(m);
  std::istringstream in(formats::write_mesh(m, Format::off));
  std::string header, line;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> header >> nv >> nf >> ne;
  std::getline(in, line);
  for (std::size_t i = 0; i < nv; ++i) std::getline(in, line);
  std::vector<std::vector<int>> faces;
  for (std::size_t i = 0; i < nf; ++i) {
    std::size_t n = 0;
    in >> n;
    faces.emplace_back(n);
    for (auto& v : faces.back()) in >> v;
  }
  return faces;
}

// assimp's regr_3429812.obj: a quad and two triangles on its edges (complex edges).
constexpr const char* quad_and_fins =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 4 3 2 1\nf 4 3 2\nf 4 2 1\n";

TEST(MeshKeptElements, FacesTheHalfedgesRefuseKeepTheirPlace) {
  const Mesh m = formats::read_mesh(quad_and_fins, Format::obj);
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(formats::skipped_faces(m), 2u);
  EXPECT_EQ(formats::total_faces(m), 3u);
  EXPECT_EQ(formats::describe_mesh(m)["faces"], 3);
  const std::vector<std::vector<int>> expected{{3, 2, 1, 0}, {3, 2, 1}, {3, 1, 0}};
  EXPECT_EQ(faces_in_order(m), expected);
}

TEST(MeshKeptElements, EveryWriterWritesThemInFileOrder) {
  // The refused face comes first in the file: it must come first in every output.
  const std::string off = "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 3 1 0\n4 3 2 1 0\n3 3 2 1\n";
  Mesh m = formats::read_mesh(off, Format::off);
  ASSERT_EQ(m.n_faces() + formats::skipped_faces(m), 3u);
  formats::carry_skipped_faces(m);
  const std::vector<std::vector<int>> expected{{3, 1, 0}, {3, 2, 1, 0}, {3, 2, 1}};
  EXPECT_EQ(faces_in_order(m), expected);
  for (Format f : {Format::ply, Format::off, Format::obj}) {
    const Mesh back = formats::read_mesh(formats::write_mesh(m, f), f);
    EXPECT_EQ(faces_in_order(back), expected) << formats::format_name(f);
  }
  // STL and Draco hold triangles: the quad kept beside is written as a fan of two.
  for (Format f : {Format::stl, Format::drc})
    EXPECT_EQ(formats::total_faces(formats::read_mesh(formats::write_mesh(m, f), f)), 4u) << formats::format_name(f);
}

TEST(MeshKeptElements, PolygonVisitingAVertexTwiceIsOneFace) {
  // A square with a slit to its centre, as assimp's concave_polygon.obj: vertex 5
  // (the centre's neighbour on the slit) is visited twice.
  const std::string obj =
      "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 1 1 0\nv 1 0 0\n"
      "f 1 6 5 6 2 3 4\n";
  Mesh m = formats::read_mesh(obj, Format::obj);
  EXPECT_EQ(formats::total_faces(m), 1u);
  ASSERT_EQ(formats::skipped_face_list(m).size(), 1u);
  EXPECT_EQ(formats::skipped_face_list(m)[0], (std::vector<int>{0, 5, 4, 5, 1, 2, 3}));
  formats::carry_skipped_faces(m);
  const Mesh back = formats::read_mesh(formats::write_mesh(m, Format::ply), Format::ply);
  EXPECT_EQ(formats::skipped_face_list(back), formats::skipped_face_list(m));
}

TEST(MeshKeptElements, SkippedFacesKeepTheirColour) {
  const std::string off = "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2 255 0 0\n3 1 0 3 0 255 0\n3 0 1 2 0 0 255\n";
  Mesh m = formats::read_mesh(off, Format::off);
  ASSERT_EQ(formats::skipped_faces(m), 1u);  // the third repeats the first one's vertices
  formats::carry_skipped_faces(m);
  const std::string out = formats::write_mesh(m, Format::off);
  EXPECT_NE(out.find("3 0 1 2 0 0 255 255\n"), std::string::npos) << out;
}

TEST(MeshKeptElements, ObjLinesAndPointsGoToObjAndPly) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nl 1 2 3 4\nl 4/1 1/1\np 1 3\nf 1 2 3\n";
  const Mesh m = formats::read_mesh(obj, Format::obj);
  EXPECT_EQ(formats::line_elements(m), (std::vector<std::vector<int>>{{0, 1, 2, 3}, {3, 0}}));
  EXPECT_EQ(formats::point_elements(m), (std::vector<std::vector<int>>{{0, 2}}));
  EXPECT_EQ(formats::line_segments(m), 4u);
  EXPECT_EQ(formats::point_count(m), 2u);
  const auto info = formats::describe_mesh(m);
  EXPECT_EQ(info["lines"], 2);
  EXPECT_EQ(info["line_segments"], 4);
  EXPECT_EQ(info["points"], 2);

  const Mesh obj_back = formats::read_mesh(formats::write_mesh(m, Format::obj), Format::obj);
  EXPECT_EQ(formats::line_elements(obj_back), formats::line_elements(m));
  EXPECT_EQ(formats::point_elements(obj_back), formats::point_elements(m));

  // PLY holds lines (as edges) but not points: refused by name and count, or dropped.
  EXPECT_EQ(formats::unwritable_parts(m, Format::ply).size(), 1u);
  expect_bad_input([&] { formats::write_mesh(m, Format::ply); }, "points to PLY");
  formats::MeshWriteOptions drop;
  drop.drop_unrepresentable = true;
  for (bool ascii : {false, true}) {
    drop.ascii = ascii;
    const Mesh ply = formats::read_mesh(formats::write_mesh(m, Format::ply, drop), Format::ply);
    EXPECT_EQ(formats::line_elements(ply), (std::vector<std::vector<int>>{{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
    EXPECT_EQ(formats::line_segments(ply), formats::line_segments(m));
    EXPECT_EQ(ply.n_faces(), 1u);
  }
  for (Format f : {Format::off, Format::stl, Format::drc}) {
    const auto parts = formats::unwritable_parts(m, f);
    ASSERT_EQ(parts.size(), 2u) << formats::format_name(f);
    EXPECT_EQ(parts[0].describe(), "2 line elements (4 segments)");
    EXPECT_EQ(parts[1].describe(), "1 point elements (2 points)");
    expect_bad_input([&] { formats::write_mesh(m, f); }, formats::format_name(f));
  }
}

TEST(MeshKeptElements, LineOfOneVertexHasNoPlyEdge) {
  const Mesh m = formats::read_mesh("v 0 0 0\nv 1 0 0\nl 1 2\nl 2\n", Format::obj);
  const auto parts = formats::unwritable_parts(m, Format::ply);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].describe(), "1 line elements of fewer than 2 vertices");
  EXPECT_TRUE(formats::unwritable_parts(m, Format::obj).empty());
}

TEST(MeshKeptElements, PlyEdgeElementIsRead) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty uchar red\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 1 9\n1 2 9\n";
  const Mesh m = formats::read_mesh(ply, Format::ply);
  EXPECT_EQ(formats::line_elements(m), (std::vector<std::vector<int>>{{0, 1}, {1, 2}}));
  expect_bad_input([&] { formats::read_mesh("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty "
                                            "float y\nproperty float z\nelement edge 1\nproperty int vertex1\n"
                                            "property int vertex2\nend_header\n0 0 0\n0 1\n",
                                            Format::ply); },
                   "edge index out of range");
}

TEST(MeshKeptElements, FacesOfFewerThanThreeVerticesOnlyWherePolygonsAre) {
  Mesh m = formats::read_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n", Format::obj);
  EXPECT_EQ(formats::total_faces(m), 2u);
  formats::carry_skipped_faces(m);
  for (Format f : {Format::ply, Format::off, Format::obj}) {
    EXPECT_TRUE(formats::unwritable_parts(m, f).empty()) << formats::format_name(f);
    EXPECT_EQ(formats::total_faces(formats::read_mesh(formats::write_mesh(m, f), f)), 2u) << formats::format_name(f);
  }
  for (Format f : {Format::stl, Format::drc}) {
    const auto parts = formats::unwritable_parts(m, f);
    ASSERT_EQ(parts.size(), 1u);
    EXPECT_EQ(parts[0].describe(), "1 faces of fewer than 3 vertices");
    expect_bad_input([&] { formats::write_mesh(m, f); }, formats::format_name(f));
  }
}

TEST(MeshKeptElements, PlyHeaderLineWithoutCommentKeyword) {
  // The header Blender 2.47 writes (assimp's Wuson.ply): free text without `comment`.
  const std::string ply =
      "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org, source file: \nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const Mesh m = formats::read_mesh(ply, Format::ply);
  EXPECT_EQ(m.n_faces(), 1u);
  const auto warnings = formats::read_warnings(m);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("line 3"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("Created by Blender3D"), std::string::npos) << warnings[0];
  EXPECT_TRUE(formats::read_warnings(formats::read_mesh(formats::write_mesh(m, Format::ply), Format::ply)).empty());
}

TEST(MeshKeptElements, PlyPropertiesAndElementsNotKeptAreNamed) {
  // The Stanford scans' header (opencv's bunny.ply): confidence and intensity per vertex.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float confidence\nproperty float intensity\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property uchar flags\nelement material 2\nproperty float shine\nelement edge 1\nproperty int vertex1\n"
      "property int vertex2\nproperty uchar red\nend_header\n"
      "0 0 0 1 2\n1 0 0 1 2\n0 1 0 1 2\n3 0 1 2 7\n0.5\n0.25\n0 1 9\n";
  const Mesh m = formats::read_mesh(ply, Format::ply);
  const auto parts = formats::unread_parts(m);
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_EQ(parts[0].describe(), "3 vertices' confidence, intensity (PLY properties)");
  EXPECT_EQ(parts[1].describe(), "1 faces' flags (PLY properties)");
  EXPECT_EQ(parts[2].describe(), "2 PLY 'material' elements");
  EXPECT_EQ(parts[3].describe(), "1 edges' red (PLY properties)");
  EXPECT_EQ(formats::describe_mesh(m)["not_kept"].size(), 4u);
  // What fest writes itself reads back with nothing left out.
  EXPECT_TRUE(formats::unread_parts(formats::read_mesh(formats::write_mesh(m, Format::ply), Format::ply)).empty());
}

TEST(MeshKeptElements, ObjCornerNormalsThatDifferAreNamed) {
  // Two triangles folded along their shared edge, each with its own flat normal: the
  // shared vertices 1 and 3 get the first triangle's normal; the second triangle's two
  // corners there name another one. Texture coordinates agree (index 1 and 3 are equal).
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nvn 0 0 1\nvn 0 1 0\nvt 0 0\nvt 1 0\nvt 0 0\n"
      "f 1/1/1 2/2/1 4/3/1\nf 2/2/2 3/2/2 4/1/2\n";
  const Mesh m = formats::read_mesh(obj, Format::obj);
  const auto parts = formats::unread_parts(m);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].count, 2u);
  EXPECT_NE(parts[0].what.find("normals"), std::string::npos);
  // fest's own OBJ (one normal per vertex) reads back with nothing left out.
  EXPECT_TRUE(formats::unread_parts(formats::read_mesh(formats::write_mesh(m, Format::obj), Format::obj)).empty());
}

TEST(MeshKeptElements, ObjPointCloudNormalsBelongToTheVertices) {
  // assimp's point_cloud.obj (written by MeshLab): vn before each v, no faces.
  const Mesh m = formats::read_mesh("vn 0 0 1\nv 1 2 3\nvn 0 1 0\nv 4 5 6\n", Format::obj);
  ASSERT_TRUE(m.has_vertex_normals());
  EXPECT_EQ(m.normal(Mesh::VertexHandle(0)), Mesh::Normal(0, 0, 1));
  EXPECT_EQ(m.normal(Mesh::VertexHandle(1)), Mesh::Normal(0, 1, 0));
}

}  // namespace
}  // namespace fest::test
