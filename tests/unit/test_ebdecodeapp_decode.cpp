// fest_ebdecode_app called with typed options: a tetrahedron coded by lib/edgebreaker
// decodes through the command to an OFF file with the same faces, orientation kept.

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "commands.hpp"
#include "edgebreaker/ebm.hpp"

namespace {

using Point = std::array<double, 3>;
using Face = std::array<Point, 3>;

void normalise(Face& f) { std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end()); }

fest::TriangleSoup tetrahedron() {
  fest::TriangleSoup t;
  t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return t;
}

std::set<Face> faces_of(const fest::TriangleSoup& soup) {
  std::set<Face> out;
  for (const auto& t : soup.triangles) {
    Face f{soup.positions[static_cast<std::size_t>(t[0])], soup.positions[static_cast<std::size_t>(t[1])],
           soup.positions[static_cast<std::size_t>(t[2])]};
    normalise(f);
    out.insert(f);
  }
  return out;
}

// The faces of a triangle OFF file as position triples (read here, independently of formats/).
std::set<Face> faces_of_off(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  std::vector<Point> p(nv);
  for (auto& q : p) in >> q[0] >> q[1] >> q[2];
  std::set<Face> out;
  for (std::size_t i = 0; i < nf; ++i) {
    std::size_t n = 0, a = 0, b = 0, c = 0;
    in >> n >> a >> b >> c;
    EXPECT_EQ(n, 3u);
    Face f{p.at(a), p.at(b), p.at(c)};
    normalise(f);
    out.insert(f);
  }
  EXPECT_TRUE(in) << "truncated OFF " << path;
  return out;
}

}  // namespace

TEST(EbdecodeApp, TetrahedronDecodesToTheSameFaces) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "ebdecodeapp";
  std::filesystem::create_directories(dir);
  fest::edgebreaker::EncodeOptions e;
  e.qp = 0;  // float32 exactly
  std::ofstream(dir / "tet.ebm", std::ios::binary) << fest::edgebreaker::encode_ebm(tetrahedron(), e);

  fest::ebdecode_tool::DecodeOptions o;
  o.input = (dir / "tet.ebm").string();
  o.output = (dir / "tet.out").string();
  fest::ebdecode_tool::parse_output_format("off", o);
  ASSERT_EQ(fest::ebdecode_tool::decode_command(o), 0);
  EXPECT_EQ(faces_of_off(dir / "tet.out"), faces_of(tetrahedron()));
}
