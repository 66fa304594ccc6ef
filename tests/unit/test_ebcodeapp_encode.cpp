// fest_ebcode_app called with typed options: a tetrahedron (OFF) encoded to .ebm decodes
// to the same faces, orientation kept; the flag-value parsers refuse unknown names.

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "edgebreaker/ebm.hpp"

namespace {

using Point = std::array<double, 3>;
using Face = std::array<Point, 3>;

// Faces as position triples rotated to start at the smallest: the face set up to vertex
// numbering, with orientation.
std::set<Face> faces_of(const fest::TriangleSoup& soup) {
  std::set<Face> out;
  for (const auto& t : soup.triangles) {
    Face f{soup.positions[static_cast<std::size_t>(t[0])], soup.positions[static_cast<std::size_t>(t[1])],
           soup.positions[static_cast<std::size_t>(t[2])]};
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    out.insert(f);
  }
  return out;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One folder per test: ctest runs the tests of this file as parallel processes, and a
// shared tet.off was rewritten by one while another read it.
std::filesystem::path test_dir() {
  return std::filesystem::path(::testing::TempDir()) / "ebcodeapp" /
         ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

std::filesystem::path write_tetrahedron() {
  const std::filesystem::path dir = test_dir();
  std::filesystem::create_directories(dir);
  const auto path = dir / "tet.off";
  std::ofstream(path) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
  return path;
}

fest::TriangleSoup tetrahedron() {
  fest::TriangleSoup t;
  t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return t;
}

}  // namespace

TEST(EbcodeApp, TetrahedronRoundTripsThroughEbm) {
  fest::ebcode_tool::EncodeOptions o;
  o.input = write_tetrahedron().string();
  o.output = (test_dir() / "tet.ebm").string();
  o.conn = fest::edgebreaker::ConnChoice::static_model;
  o.qp = 0;  // float32 exactly: the unit coordinates come back as they went in
  ASSERT_EQ(fest::ebcode_tool::encode_command(o), 0);
  const fest::TriangleSoup back = fest::edgebreaker::decode_ebm(slurp(o.output));
  EXPECT_EQ(back.positions.size(), 4u);
  EXPECT_EQ(faces_of(back), faces_of(tetrahedron()));
}

TEST(EbcodeApp, SymbolsOfTheTetrahedronAreCRE) {
  fest::ebcode_tool::EncodeOptions o;
  o.input = write_tetrahedron().string();
  o.output = (test_dir() / "tet.clers").string();
  o.symbols = true;
  ASSERT_EQ(fest::ebcode_tool::encode_command(o), 0);
  EXPECT_EQ(slurp(o.output), "CRE\n");
}

TEST(EbcodeApp, FlagValuesBecomeTypedOptions) {
  using namespace fest::ebcode_tool;
  EXPECT_EQ(parse_conn("adaptive"), fest::edgebreaker::ConnChoice::adaptive);
  EXPECT_EQ(parse_predictor("multi"), fest::edgebreaker::Predictor::multi);
  EXPECT_EQ(parse_box("1,2,3,4"), (std::array<float, 4>{1, 2, 3, 4}));
  EXPECT_EQ(parse_length_limit("-", "--lmax"), -1);
  EXPECT_EQ(parse_model_format("inc"), ModelFormat::inc);
  try {
    parse_conn("fast");
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    EXPECT_NE(std::string(e.what()).find("--conn"), std::string::npos) << e.what();
  }
}

// lib/edgebreaker says "strict coding"; the command names the flag the user typed.
TEST(EbcodeApp, StrictRefusalNamesTheFlag) {
  std::filesystem::create_directories(test_dir());
  const auto path = test_dir() / "fin.off";
  std::ofstream(path) << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n";
  fest::ebcode_tool::EncodeOptions o;
  o.input = path.string();
  o.output = (test_dir() / "fin.ebm").string();
  o.strict = true;
  try {
    fest::ebcode_tool::encode_command(o);
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_EQ(std::string(e.what()), "the mesh has a boundary (--strict)");
  }
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

TEST(EbcodeApp, LosslessRefusalNamesTheFlag) {
  std::filesystem::create_directories(test_dir());
  const auto path = test_dir() / "double.off";
  std::ofstream(path) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1.1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
  fest::ebcode_tool::EncodeOptions o;
  o.input = path.string();
  o.output = (test_dir() / "double.ebm").string();
  o.qp = 0;
  try {
    fest::ebcode_tool::encode_command(o);
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_EQ(std::string(e.what()), "--qp 0 stores float32 exactly, but vertex 3 has the double coordinate 1.1");
  }
}

TEST(EbcodeApp, DomainPhrasesBecomeFlags) {
  const fest::Error e = fest::ebcode_tool::in_flag_terms(
      fest::bad_input("the static model cannot code this mesh: use the adaptive coder, or let the encoder choose"));
  EXPECT_EQ(e.status(), fest::Status::bad_input);
  EXPECT_EQ(std::string(e.what()), "the static model cannot code this mesh: use --conn adaptive or auto");
}
