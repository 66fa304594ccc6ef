// Real meshes from the test data folder (scripts/fetch-test-data.sh).

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

using formats::Format;
using formats::MeshWriteOptions;

// Bit-exact chains ask for double PLY coordinates: by default a PLY of decimal text
// with up to 7 digits stores floats (test_mesh_precision.cpp checks that).
Mesh convert(const Mesh& mesh, Format format, bool ascii) {
  MeshWriteOptions options;
  options.ascii = ascii;
  options.precision = formats::CoordinatePrecision::float64;
  return formats::read_mesh(formats::write_mesh(mesh, format, options), format);
}

TEST(MeshRealData, BunnyConversionChainIsExact) {
  FEST_REQUIRE_TESTDATA(path, "meshes/bunny00.off");
  const Mesh bunny = formats::read_mesh(slurp(path), Format::off);
  // Counts stated in the Debian data package's documentation of bunny00.off.
  ASSERT_EQ(bunny.n_vertices(), 37706u);
  ASSERT_EQ(bunny.n_faces(), 75408u);
  EXPECT_EQ(formats::skipped_faces(bunny), 0u);
  // The first vertex line of the file is "-0.167662 -0.411917 -0.0732205": the reader
  // must give the correctly rounded doubles of that text, not floats.
  EXPECT_TRUE(same_bits(bunny.point(Mesh::VertexHandle(0))[0], std::strtod("-0.167662", nullptr)));
  EXPECT_TRUE(same_bits(bunny.point(Mesh::VertexHandle(0))[2], std::strtod("-0.0732205", nullptr)));

  // OFF -> PLY (binary) -> OFF -> PLY (ascii) -> OBJ -> read back.
  Mesh ply_binary = convert(bunny, Format::ply, false);
  expect_same_geometry(bunny, ply_binary);
  Mesh off = convert(ply_binary, Format::off, true);
  expect_same_geometry(bunny, off);
  Mesh ply_ascii = convert(off, Format::ply, true);
  expect_same_geometry(bunny, ply_ascii);
  Mesh obj = convert(ply_ascii, Format::obj, true);
  expect_same_geometry(bunny, obj);
  // A closed triangle mesh: 3F = 2E.
  EXPECT_EQ(2 * obj.n_edges(), 3 * obj.n_faces());
}

TEST(MeshRealData, BunnyDracoLosslessAndStlAscii) {
  FEST_REQUIRE_TESTDATA(path, "meshes/bunny00.off");
  const Mesh bunny = formats::read_mesh(slurp(path), Format::off);
  expect_same_geometry(bunny, convert(bunny, Format::drc, false));
  Mesh stl = convert(bunny, Format::stl, true);
  EXPECT_EQ(stl.n_faces(), bunny.n_faces());
  EXPECT_LE(stl.n_vertices(), bunny.n_vertices());  // unused vertices cannot be in STL
}

TEST(MeshRealData, RawScanWithHolesAndNonManifoldVertices) {
  FEST_REQUIRE_TESTDATA(path, "meshes/bunny_scan.ply");
  const Mesh scan = formats::read_mesh(slurp(path), Format::ply);
  // Header of the file: "element vertex 1889", "element face 3851". Faces OpenMesh
  // cannot hold are counted, so added + skipped must be every face in the file.
  EXPECT_EQ(scan.n_vertices(), 1889u);
  EXPECT_EQ(scan.n_faces() + formats::skipped_faces(scan), 3851u);
  nlohmann::json info = formats::describe_mesh(scan);
  EXPECT_EQ(info["vertices"], 1889);
  EXPECT_EQ(info["triangles"], true);
  // What was kept round-trips exactly.
  for (Format format : {Format::ply, Format::off, Format::obj}) {
    SCOPED_TRACE(formats::format_name(format));
    expect_same_geometry(scan, convert(scan, format, false));
  }
}

TEST(MeshRealData, EveryOffMeshReadsAndRoundTripsThroughBinaryPly) {
  FEST_REQUIRE_TESTDATA(dir, "meshes");
  for (const char* name : {"cube.off", "icosahedron.off", "octahedron.off", "eight.off", "fandisk.off", "cow.off"}) {
    SCOPED_TRACE(name);
    Mesh mesh = formats::read_mesh(slurp(dir + "/" + name), Format::off);
    EXPECT_GT(mesh.n_faces(), 0u);
    expect_same_geometry(mesh, convert(mesh, Format::ply, false));
  }
  // Known solids: Euler characteristic 2, and their face counts.
  Mesh ico = formats::read_mesh(slurp(dir + "/icosahedron.off"), Format::off);
  EXPECT_EQ(ico.n_vertices(), 12u);
  EXPECT_EQ(ico.n_faces(), 20u);
  Mesh octa = formats::read_mesh(slurp(dir + "/octahedron.off"), Format::off);
  EXPECT_EQ(octa.n_vertices(), 6u);
  EXPECT_EQ(octa.n_faces(), 8u);
}

}  // namespace
}  // namespace fest::test
