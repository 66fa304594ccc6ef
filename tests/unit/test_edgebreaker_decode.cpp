// Spirale Reversi decoding (lib/edgebreaker/decode.cpp): round trips, the seed's Fig. 5.1
// string, and strings that must be rejected. Expected facts come from the mathematics:
// a decoded string of length t - 1 with v - 3 C's is a closed genus-0 surface of v
// vertices and t triangles, checked by test_edgebreaker_meshes.hpp's independent checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/error.hpp"
#include "edgebreaker/clers.hpp"
#include "expect_error.hpp"
#include "test_edgebreaker_meshes.hpp"

using namespace fest::edgebreaker;
using fest::test::expect_bad_input;
namespace eb = fest::test::eb;

namespace {

void expect_round_trip(const eb::Faces& m) {
  const Encoded e = encode(m.triangles, m.vertex_count);
  const std::vector<Triangle> d = decode(e.clers);
  ASSERT_EQ(d.size(), m.triangles.size());
  EXPECT_EQ(eb::sphere_defect(d, m.vertex_count), "");
  // Same oriented faces once decoded ids are mapped through the visit order.
  EXPECT_EQ(eb::canonical(eb::mapped(d, e.vertex_order)), eb::canonical(m.triangles));
  // The root survives exactly: the start triangle comes first with its corners in order.
  EXPECT_EQ(d[0], (Triangle{0, 1, 2}));
}

// Decoding either throws bad_input or yields a closed genus-0 surface that encodes back
// to the same string: the decoder's contract on arbitrary input.
void expect_rejected_or_exact(const Clers& s) {
  std::vector<Triangle> d;
  try {
    d = decode(s);
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    return;
  }
  const int v = static_cast<int>(std::count(s.begin(), s.end(), Symbol::C)) + 3;
  ASSERT_EQ(eb::sphere_defect(d, v), "") << to_string(s);
  EXPECT_EQ(encode(d, v).clers, s) << to_string(s);
}

}  // namespace

TEST(EdgebreakerDecode, RoundTripsAnalyticMeshes) {
  for (const eb::Faces& m : {eb::double_triangle(), eb::tetrahedron(), eb::cgal_octahedron(), eb::cgal_cube(),
                             eb::cgal_icosahedron(), eb::subdivided_icosahedron(1), eb::subdivided_icosahedron(2)})
    expect_round_trip(m);
}

// 2562 vertices, 5120 triangles.
TEST(EdgebreakerDecode, RoundTripsASubdividedSphere) {
  const eb::Faces m = eb::subdivided_icosahedron(4);
  ASSERT_EQ(m.vertex_count, 10 * 256 + 2);
  ASSERT_EQ(m.triangles.size(), 20u * 256u);
  expect_round_trip(m);
}

TEST(EdgebreakerDecode, RoundTripsScrambledMeshes) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    expect_round_trip(eb::scrambled(eb::cgal_icosahedron(), seed));
    expect_round_trip(eb::scrambled(eb::subdivided_icosahedron(3), seed));
  }
}

// Seed Fig. 5.1: 15 symbols, 7 C's, so v = 10 and t = 16 (docs/ebcode.md §1-2).
TEST(EdgebreakerDecode, SeedFigureString) {
  const Clers s = parse_clers("CCCRCCCRRRCSREE");
  const std::vector<Triangle> d = decode(s);
  EXPECT_EQ(d.size(), 16u);
  EXPECT_EQ(eb::sphere_defect(d, 10), "");
  EXPECT_EQ(to_string(encode(d, 10).clers), "CCCRCCCRRRCSREE");
}

TEST(EdgebreakerDecode, SingleEIsTheDoubleTriangle) {
  EXPECT_EQ(eb::canonical(decode(parse_clers("E"))), eb::canonical(eb::double_triangle().triangles));
}

TEST(EdgebreakerDecode, RejectsInvalidStrings) {
  const auto reject = [](const std::string& s, const std::string& needle) {
    expect_bad_input([&] { decode(parse_clers(s)); }, needle);
  };
  reject("", "empty");
  reject("EE", "#E - #S is 2");     // two loops never joined
  reject("CREE", "#E - #S is 2");
  reject("SE", "S without two open loops");  // an S with no E to match it
  reject("CSRE", "S without two open loops");
  reject("RE", "not 3 edges long");       // the last loop is not the start triangle
  reject("CE", "C on a loop of 3 edges");    // constraint 1a: no C right after E^-1
  reject("C", "C with no open loop");
  reject("L", "L with no open loop");
  reject("CCLRE", "invalid CLERS string");   // constraint 1b: no C right after L^-1
}

// A proper prefix of a valid string leaves 1 + #S - #E >= 1 loops of the forward traversal
// open, so #E - #S <= 0 and no prefix can be valid; dropping a leading C changes the vertex
// count without the string saying so.
TEST(EdgebreakerDecode, RejectsTruncatedStrings) {
  const eb::Faces m = eb::subdivided_icosahedron(2);
  const Clers s = encode(m.triangles, m.vertex_count).clers;
  for (std::size_t n = 0; n < s.size(); ++n)
    expect_bad_input([&] { decode(Clers(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(n))); }, "invalid CLERS");
  ASSERT_EQ(s[0], Symbol::C);
  expect_bad_input([&] { decode(Clers(s.begin() + 1, s.end())); }, "invalid CLERS");
}

// A stand-in for the fuzzer to come: random strings and random edits of a valid string
// never crash, hang or return something that is not the string's own mesh.
TEST(EdgebreakerDecode, ArbitraryStringsAreRejectedOrExact) {
  std::mt19937 rng(2024);
  const Symbol alphabet[5] = {Symbol::C, Symbol::L, Symbol::E, Symbol::R, Symbol::S};
  for (int trial = 0; trial < 3000; ++trial) {
    Clers s(1 + rng() % 40);
    for (Symbol& x : s) x = alphabet[rng() % 5];
    expect_rejected_or_exact(s);
  }
  const eb::Faces m = eb::subdivided_icosahedron(2);
  const Clers valid = encode(m.triangles, m.vertex_count).clers;
  for (int trial = 0; trial < 1000; ++trial) {
    Clers s = valid;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < edits; ++k) s[rng() % s.size()] = alphabet[rng() % 5];
    expect_rejected_or_exact(s);
  }
  // Long degenerate strings stay linear and are rejected.
  for (Symbol x : alphabet) expect_rejected_or_exact(Clers(200000, x));
  Clers long_random(200000);
  for (Symbol& x : long_random) x = alphabet[rng() % 5];
  expect_rejected_or_exact(long_random);
}
