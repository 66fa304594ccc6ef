// PLY positions are float32 unless float32 would lose precision the input had
// (CoordinatePrecision in mesh_io.hpp): judged by how the input stored them.
#include <cstdlib>
#include <sstream>
#include <string>

#include "test_mesh_helpers.hpp"
#include "testdata.hpp"

namespace fest::test {
namespace {

using formats::CoordinatePrecision;
using formats::Format;

std::string ply_with(const Mesh& m, CoordinatePrecision precision = CoordinatePrecision::automatic,
                     bool ascii = false) {
  formats::MeshWriteOptions options;
  options.precision = precision;
  options.ascii = ascii;
  return formats::write_mesh(m, Format::ply, options);
}

bool declares(const std::string& ply, const std::string& line) {
  return ply.substr(0, ply.find("end_header")).find(line + "\n") != std::string::npos;
}

TEST(MeshPrecision, ShortDecimalTextIsFloat) {
  // 0.1 is not a float, but the text "0.1" reads back from the nearest float.
  const Mesh m = formats::read_mesh("OFF\n3 1 0\n0.1 0.2 0.3\n1 0 0\n0 1 -1234567\n3 0 1 2\n", Format::off);
  const std::string ply = ply_with(m);
  EXPECT_TRUE(declares(ply, "property float x"));
  const Mesh back = formats::read_mesh(ply, Format::ply);
  EXPECT_EQ(back.point(Mesh::VertexHandle(0))[0], static_cast<double>(0.1f));
  EXPECT_EQ(back.point(Mesh::VertexHandle(2))[2], -1234567.0);
  // --precision double keeps the decimal's double.
  EXPECT_TRUE(declares(ply_with(m, CoordinatePrecision::float64), "property double x"));
  EXPECT_EQ(formats::read_mesh(ply_with(m, CoordinatePrecision::float64), Format::ply).point(Mesh::VertexHandle(0))[0],
            0.1);
}

TEST(MeshPrecision, LongDecimalTextIsDouble) {
  for (const char* obj : {"v 0 0 0.123456789\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "v 16777217 0 0\nv 1 0 0\nv 0 1 0\n"}) {
    const Mesh m = formats::read_mesh(obj, Format::obj);
    EXPECT_TRUE(declares(ply_with(m), "property double x")) << obj;
    EXPECT_TRUE(declares(ply_with(m, CoordinatePrecision::float32), "property float x")) << obj;
  }
}

TEST(MeshPrecision, BinaryInputKeepsItsStorage) {
  Mesh doubles;
  doubles.add_vertex(Mesh::Point(0.1, 0, 0));  // a double that is not a float
  doubles.add_vertex(Mesh::Point(1, 0, 0));
  const std::string double_ply = ply_with(doubles);
  ASSERT_TRUE(declares(double_ply, "property double x"));
  // Read back, the file stored doubles: still double (0.1 as a double is not a float).
  EXPECT_TRUE(declares(ply_with(formats::read_mesh(double_ply, Format::ply)), "property double x"));
  // Doubles that are all exactly floats lose nothing as floats.
  Mesh exact;
  exact.add_vertex(Mesh::Point(0.5, 0.25, 3));
  EXPECT_TRUE(declares(ply_with(formats::read_mesh(ply_with(exact, CoordinatePrecision::float64), Format::ply)),
                       "property float x"));
}

TEST(MeshPrecision, CoordinatesComputedAfterReadingStayDouble) {
  Mesh floats;
  floats.add_vertex(Mesh::Point(0.5, 0.25, 3));
  Mesh m = formats::read_mesh(ply_with(floats), Format::ply);  // a float PLY
  m.point(Mesh::VertexHandle(0))[0] = 1.0 / 3.0;               // a tool computes a new value
  EXPECT_TRUE(declares(ply_with(m), "property double x"));
}

TEST(MeshPrecision, AsciiPlyTextOfForcedFloatsIsTheFloats) {
  const Mesh m = formats::read_mesh("v 0.123456789 0 0\nv 0.1 0 0\n", Format::obj);
  const std::string ascii = ply_with(m, CoordinatePrecision::float32, true);
  EXPECT_TRUE(declares(ascii, "property float x"));
  const Mesh back = formats::read_mesh(ascii, Format::ply);
  EXPECT_EQ(back.point(Mesh::VertexHandle(0))[0], static_cast<double>(0.123456789f));
  EXPECT_EQ(back.point(Mesh::VertexHandle(1))[0], 0.1);  // its text reads back from the float
}

TEST(MeshPrecision, BunnyOffBecomesAFloatPlyThatKeepsEveryDecimal) {
  FEST_REQUIRE_TESTDATA(path, "meshes/bunny00.off");
  const std::string text = slurp(path);
  const Mesh bunny = formats::read_mesh(text, Format::off);
  const std::string ply = ply_with(bunny);
  ASSERT_TRUE(declares(ply, "property float x"));
  const Mesh back = formats::read_mesh(ply, Format::ply);
  // Anchor: the file's own text. Each float read back is the float nearest to the text.
  std::istringstream in(text);
  std::string header;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> header >> nv >> nf >> ne;
  ASSERT_EQ(nv, back.n_vertices());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < nv; ++i)
    for (int k = 0; k < 3; ++k) {
      std::string token;
      in >> token;
      const float nearest = std::strtof(token.c_str(), nullptr);
      differ += back.point(Mesh::VertexHandle(static_cast<int>(i)))[k] != static_cast<double>(nearest);
    }
  EXPECT_EQ(differ, 0u);
}

}  // namespace
}  // namespace fest::test
