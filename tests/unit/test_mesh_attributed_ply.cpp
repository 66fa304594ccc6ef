// formats/mesh/attributed_ply: PLY with named per-vertex and per-face properties written
// and read back exactly, the same data as ascii, and malformed files refused.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/mesh/attributed_ply.hpp"

namespace fest::formats {
namespace {

AttributedPly sample() {
  AttributedPly p;
  p.comments = {"object 0 floor", "hello"};
  p.vertex = {{"x", "double", {0, 1, 1, 0.1}}, {"y", "double", {0, 0, 1, 1}}, {"z", "float", {0, 0, 0, 0.5}},
              {"rad_r", "float", {1.5, 2, 3, 4}}, {"red", "uchar", {0, 255, 7, 9}}};
  p.faces = {{0, 1, 2}, {0, 2, 3}};
  p.face = {{"object_id", "int", {3, -1}}, {"level", "uchar", {0, 2}}};
  return p;
}

TEST(AttributedPly, BinaryRoundTrip) {
  const AttributedPly a = sample();
  const AttributedPly b = read_attributed_ply(write_attributed_ply(a));
  EXPECT_EQ(b.comments, a.comments);
  EXPECT_EQ(b.faces, a.faces);
  ASSERT_EQ(b.vertex.size(), a.vertex.size());
  for (std::size_t k = 0; k < a.vertex.size(); ++k) {
    EXPECT_EQ(b.vertex[k].name, a.vertex[k].name);
    EXPECT_EQ(b.vertex[k].type, a.vertex[k].type);
    EXPECT_EQ(b.vertex[k].values, a.vertex[k].values);
  }
  ASSERT_EQ(b.face.size(), 2u);
  EXPECT_EQ(b.face[0].values, a.face[0].values);
  EXPECT_EQ(b.face[1].values, a.face[1].values);
}

TEST(AttributedPly, AsciiAndBigEndian) {
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty float refl_r\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0.25\n";
  const AttributedPly a = read_attributed_ply(ascii);
  ASSERT_EQ(a.faces.size(), 1u);
  EXPECT_EQ(a.face[0].name, "refl_r");
  EXPECT_EQ(a.face[0].values[0], 0.25);
  std::string be = "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty short x\nproperty short y\n"
                   "property short z\nend_header\n";
  be += std::string("\x01\x02\x00\x03\xff\xfe", 6);
  const AttributedPly b = read_attributed_ply(be);
  EXPECT_EQ(b.vertex[0].values[0], 258);
  EXPECT_EQ(b.vertex[1].values[0], 3);
  EXPECT_EQ(b.vertex[2].values[0], -2);
}

TEST(AttributedPly, MalformedIsBadInput) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (const std::string& body : {std::string("0 0 0\n3 0 1 2\n"), std::string("0 0 0\n3 0 0\n"),
                                  std::string("0 0\n"), std::string("0 0 0\n3 0 0 0 9\n")}) {
    try {
      read_attributed_ply(head + body);
      ADD_FAILURE() << "accepted " << body;
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input);
    }
  }
  AttributedPly p = sample();
  p.vertex[1].values.pop_back();
  EXPECT_THROW(write_attributed_ply(p), Error);
}

}  // namespace
}  // namespace fest::formats
