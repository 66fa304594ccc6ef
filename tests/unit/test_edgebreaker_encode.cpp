// The forward traversal (lib/edgebreaker/encode.cpp). Expected strings are the
// golden strings (recorded by an independent prototype; docs/ebcode.md §1); expected
// counts follow from Euler's formula (docs/ebcode.md §1): for a closed genus-0 mesh with v vertices
// and t = 2v - 4 triangles there are t - 1 symbols, v - 3 of them C, and #E - #S = 1.
#include <gtest/gtest.h>

#include <algorithm>

#include "edgebreaker/clers.hpp"
#include "test_edgebreaker_meshes.hpp"

using namespace fest::edgebreaker;
namespace eb = fest::test::eb;

namespace {

long count(const Clers& s, Symbol x) { return static_cast<long>(std::count(s.begin(), s.end(), x)); }

void expect_counting_identities(const eb::Faces& m) {
  const Encoded e = encode(m.triangles, m.vertex_count);
  const long v = m.vertex_count, t = static_cast<long>(m.triangles.size());
  ASSERT_EQ(t, 2 * v - 4);
  EXPECT_EQ(static_cast<long>(e.clers.size()), t - 1);
  EXPECT_EQ(count(e.clers, Symbol::C), v - 3);
  EXPECT_EQ(count(e.clers, Symbol::E) - count(e.clers, Symbol::S), 1);
  EXPECT_EQ(e.clers.back(), Symbol::E);  // the traversal ends by closing its last loop
  // The visit order is a permutation that starts with triangle 0's corners.
  ASSERT_EQ(static_cast<long>(e.vertex_order.size()), v);
  EXPECT_EQ(e.vertex_order[0], m.triangles[0][0]);
  EXPECT_EQ(e.vertex_order[1], m.triangles[0][1]);
  EXPECT_EQ(e.vertex_order[2], m.triangles[0][2]);
  std::vector<int> sorted = e.vertex_order;
  std::sort(sorted.begin(), sorted.end());
  for (long i = 0; i < v; ++i) EXPECT_EQ(sorted[static_cast<std::size_t>(i)], i);
}

}  // namespace

TEST(EdgebreakerEncode, GoldenStringsOfSmallPolyhedra) {
  const eb::Faces tetra = eb::tetrahedron();
  EXPECT_EQ(to_string(encode(tetra.triangles, tetra.vertex_count).clers), "CRE");
  const eb::Faces octa = eb::cgal_octahedron(), ico = eb::cgal_icosahedron(), cube = eb::cgal_cube();
  EXPECT_EQ(to_string(encode(octa.triangles, octa.vertex_count).clers), "CCRCRRE");
  EXPECT_EQ(to_string(encode(ico.triangles, ico.vertex_count).clers), "CCCRCCRCRCRCRRCRRRE");
  EXPECT_EQ(to_string(encode(cube.triangles, cube.vertex_count).clers), "CCCCRRCRRLE");
}

// Two triangles on three vertices: one symbol, and it must be E (no vertex is left for C).
TEST(EdgebreakerEncode, SmallestSphereIsE) {
  const eb::Faces m = eb::double_triangle();
  const Encoded e = encode(m.triangles, m.vertex_count);
  EXPECT_EQ(to_string(e.clers), "E");
  EXPECT_EQ(e.vertex_order, (std::vector<int>{0, 1, 2}));
}

TEST(EdgebreakerEncode, CountingIdentities) {
  for (const eb::Faces& m : {eb::double_triangle(), eb::tetrahedron(), eb::cgal_octahedron(), eb::cgal_cube(),
                             eb::cgal_icosahedron(), eb::subdivided_icosahedron(1), eb::subdivided_icosahedron(4)})
    expect_counting_identities(m);
  expect_counting_identities(eb::scrambled(eb::subdivided_icosahedron(3), 7));
}

// The traversal sees only connectivity and the root (triangle 0, corner 0): renaming
// vertices changes the visit order by the same renaming and the string not at all.
TEST(EdgebreakerEncode, RenamingVerticesKeepsTheString) {
  const eb::Faces m = eb::subdivided_icosahedron(2);
  eb::Faces renamed = m;
  std::vector<int> name(static_cast<std::size_t>(m.vertex_count));
  for (int i = 0; i < m.vertex_count; ++i) name[static_cast<std::size_t>(i)] = (i * 37 + 11) % m.vertex_count;
  ASSERT_EQ(m.vertex_count, 162);  // 37 is prime to 162, so i -> 37i + 11 is a bijection
  for (Triangle& f : renamed.triangles)
    for (int& v : f) v = name[static_cast<std::size_t>(v)];
  const Encoded a = encode(m.triangles, m.vertex_count), b = encode(renamed.triangles, renamed.vertex_count);
  EXPECT_EQ(a.clers, b.clers);
  for (std::size_t i = 0; i < a.vertex_order.size(); ++i)
    EXPECT_EQ(name[static_cast<std::size_t>(a.vertex_order[i])], b.vertex_order[i]);
}

// Chapter 5.3 / docs/ebcode.md §3: in decoding order C never follows E or L, nor any of the 17
// triangulations of a triangle with 1-3 interior vertices. In forward order that is:
// the string never contains "C" followed by a reversed pattern. With Gumhold's left-first
// split order all 19 hold on real meshes (docs/ebcode.md §1); a right-first traversal breaks them.
TEST(EdgebreakerEncode, ChapterExclusionPatternsHold) {
  const eb::Faces m = eb::subdivided_icosahedron(4);
  const std::string s = to_string(encode(m.triangles, m.vertex_count).clers);
  ASSERT_NE(s.find('S'), std::string::npos);  // the split order is exercised
  for (std::string p : {"E",       "L",       "ESC",     "ELSCC",   "ERSCC",   "ERCSC",   "ELLSCCC",
                        "ELRSCCC", "ELRCCSC", "ERRCSCC", "EESSCCC", "ERCRSCC", "ERRCCSC", "ERRSCCC",
                        "ERCRCSC", "EESCSCC", "ERCLSCC", "ERLSCCC", "ELRCSCC"}) {
    std::reverse(p.begin(), p.end());
    EXPECT_EQ(s.find("C" + p), std::string::npos) << "C follows " << p;
  }
}
