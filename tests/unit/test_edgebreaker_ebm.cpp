// The whole .ebm pipeline on general meshes (docs/ebcode.md §5): several components, holes,
// handles and non-manifold input come back with the input's vertex count and exactly its
// faces (as position triples, orientation kept), and the container rejects damage.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>

#include "edgebreaker/ebm.hpp"
#include "edgebreaker/state_machine.hpp"
#include "expect_error.hpp"
#include "test_edgebreaker_meshes.hpp"

namespace {

using namespace fest::edgebreaker;
using fest::test::expect_bad_input;
using Point = std::array<double, 3>;

// Vertex i at a distinct float position, so a decoded vertex is known by its position.
MeshSoup with_positions(const std::vector<Triangle>& triangles, int vertex_count) {
  MeshSoup m;
  for (int i = 0; i < vertex_count; ++i)
    m.positions.push_back({static_cast<double>(i % 7) * 0.5, static_cast<double>((i / 7) % 7) * 0.25,
                           static_cast<double>(i / 49) * 0.125 + 1.0});
  m.triangles = triangles;
  return m;
}

// Faces as position triples, rotated to start at the smallest: orientation is kept,
// vertex numbering forgotten. Degenerate faces are left out (the coder drops them).
std::vector<std::array<Point, 3>> face_set(const MeshSoup& m) {
  std::vector<std::array<Point, 3>> out;
  for (const Triangle& t : m.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    std::array<Point, 3> f{m.positions[static_cast<std::size_t>(t[0])], m.positions[static_cast<std::size_t>(t[1])],
                           m.positions[static_cast<std::size_t>(t[2])]};
    const auto first = std::min_element(f.begin(), f.end()) - f.begin();
    std::rotate(f.begin(), f.begin() + first, f.end());
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Point> point_set(const MeshSoup& m) {
  std::vector<Point> p = m.positions;
  std::sort(p.begin(), p.end());
  return p;
}

// Both container versions: 2.0 (written by default) and 1.0 (still written on request,
// and read for the streams that exist).
void expect_exact_round_trip(const MeshSoup& in, ConnChoice conn = ConnChoice::automatic,
                             Predictor predictor = Predictor::parallelogram) {
  for (int version : {2, 1}) {
    SCOPED_TRACE(version);
    EncodeOptions o;
    o.qp = 0;  // lossless: positions identify vertices
    o.conn = conn;
    o.predictor = predictor;
    o.version = version;
    EncodeStats stats;
    const std::string bytes = encode_ebm(in, o, &stats);
    EXPECT_EQ(static_cast<int>(bytes[8]), version);
    const MeshSoup out = decode_ebm(bytes);
    EXPECT_EQ(out.positions.size(), in.positions.size());
    EXPECT_EQ(point_set(out), point_set(in));
    EXPECT_EQ(face_set(out), face_set(in));
  }
}

TEST(EdgebreakerEbm, ClosedMeshesRoundTripWithEveryCoder) {
  for (ConnChoice c : {ConnChoice::automatic, ConnChoice::static_model, ConnChoice::adaptive, ConnChoice::raw}) {
    const auto m = fest::test::eb::subdivided_icosahedron(2);
    expect_exact_round_trip(with_positions(m.triangles, m.vertex_count), c);
    const auto t = fest::test::eb::tetrahedron();
    expect_exact_round_trip(with_positions(t.triangles, t.vertex_count), c);
  }
}

// A torus from an n x m grid (genus 1): 2 handle events.
std::vector<Triangle> torus(int n, int m) {
  std::vector<Triangle> t;
  const auto id = [&](int i, int j) { return (i % n) * m + (j % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return t;
}

TEST(EdgebreakerEbm, EveryPredictorRoundTrips) {
  const auto m = fest::test::eb::subdivided_icosahedron(2);
  std::vector<Triangle> t = m.triangles;
  t.push_back({0, 1, 60});  // a fin: holes, dummies and copies around the predictions
  for (Predictor p : {Predictor::parallelogram, Predictor::multi, Predictor::delta, Predictor::none})
    expect_exact_round_trip(with_positions(t, m.vertex_count), ConnChoice::automatic, p);
}

// docs/ebcode.md §5: colours exact, normals and texture coordinates within half a step, kept
// through holes, stitching and isolated vertices.
TEST(EdgebreakerEbm, VertexAttributesComeBackWithTheirVertices) {
  std::vector<Triangle> t = fest::test::eb::subdivided_icosahedron(1).triangles;
  t.push_back({0, 1, 40});  // a fin: a hole, a dummy and copies
  MeshSoup m = with_positions(t, 43);  // 41, 42 isolated
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    const double a = 0.3 * static_cast<double>(v);
    m.normals.push_back({std::cos(a), std::sin(a) * 0.6, std::sin(a) * 0.8});
    m.colors.push_back({static_cast<std::uint8_t>(v * 5), static_cast<std::uint8_t>(255 - v), 7});
    m.texcoords.push_back({0.01 * static_cast<double>(v), 2.0 - 0.02 * static_cast<double>(v)});
  }
  EncodeOptions o;
  o.qp = 0;
  o.qn = 10;
  o.qt = 12;
  const std::string bytes = encode_ebm(m, o);
  EXPECT_EQ(read_ebm_header(bytes).attribute_names, (std::vector<std::string>{"normal", "color", "texcoord"}));
  const MeshSoup out = decode_ebm(bytes);
  ASSERT_EQ(out.positions.size(), m.positions.size());
  std::map<Point, std::size_t> input_of;  // positions are distinct and exact at qp 0
  for (std::size_t v = 0; v < m.positions.size(); ++v) input_of[m.positions[v]] = v;
  const double normal_step = 2.0 / (std::ldexp(1.0, 10) - 1), tex_step = 1.99 / (std::ldexp(1.0, 12) - 1);
  for (std::size_t v = 0; v < out.positions.size(); ++v) {
    const std::size_t i = input_of.at(out.positions[v]);
    EXPECT_EQ(out.colors[v], m.colors[i]);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_LE(std::fabs(out.normals[v][k] - m.normals[i][k]), normal_step / 2 + 1e-12);
    for (std::size_t k = 0; k < 2; ++k) EXPECT_LE(std::fabs(out.texcoords[v][k] - m.texcoords[i][k]), tex_step / 2 * 1.0001);
  }
}

TEST(EdgebreakerEbm, HandlesGiveTwoEventsPerGenus) {
  const MeshSoup m = with_positions(torus(6, 5), 30);
  EncodeOptions o;
  o.qp = 0;
  EncodeStats stats;
  const std::string bytes = encode_ebm(m, o, &stats);
  EXPECT_EQ(stats.events, 2u);
  EXPECT_EQ(read_ebm_header(bytes).events, 2u);
  expect_exact_round_trip(m);
  // #C = v - 3k and #E - #S = k - 2g (docs/ebcode.md §1).
  EXPECT_EQ(stats.histogram[0], 30u - 3u);
  EXPECT_EQ(static_cast<long>(stats.histogram[2]) - static_cast<long>(stats.histogram[4]), 1 - 2);
}

TEST(EdgebreakerEbm, ComponentsHolesAndIsolatedVertices) {
  // Two disjoint tetrahedra, an open single triangle, an open strip, and two unused vertices.
  std::vector<Triangle> t{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  for (const Triangle& f : std::vector<Triangle>{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}})
    t.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  t.push_back({8, 9, 10});
  t.push_back({11, 12, 13});
  t.push_back({12, 14, 13});
  const MeshSoup m = with_positions(t, 17);  // 15 and 16 are isolated
  EncodeOptions o;
  o.qp = 0;
  EncodeStats stats;
  encode_ebm(m, o, &stats);
  EXPECT_EQ(stats.components, 4u);
  EXPECT_EQ(stats.holes, 2u);
  EXPECT_EQ(stats.isolated, 2u);
  expect_exact_round_trip(m);
}

// Non-manifold cases (docs/ebcode.md §5): each comes back with the same vertex count and faces.
TEST(EdgebreakerEbm, NonManifoldInputIsRestoredExactly) {
  const std::vector<Triangle> tetra{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  std::vector<Triangle> bowtie = tetra;  // two tetrahedra sharing vertex 0
  for (const Triangle& f : tetra) {
    Triangle g = f;
    for (int& v : g) v = v == 0 ? 0 : v + 3;
    bowtie.push_back(g);
  }
  const std::vector<Triangle> fin{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};                // three faces on one edge
  const std::vector<Triangle> flipped{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 2, 3}};  // last face flipped
  std::vector<Triangle> duplicated = tetra;
  duplicated.push_back({0, 1, 2});
  // A Moebius strip: a band of 5 quads whose ends are glued with a half twist.
  const std::vector<Triangle> moebius{{0, 1, 3}, {0, 3, 2}, {2, 3, 5}, {2, 5, 4}, {4, 5, 7},
                                      {4, 7, 6}, {6, 7, 9}, {6, 9, 8}, {8, 9, 0}, {8, 0, 1}};
  struct Case {
    const char* name;
    std::vector<Triangle> faces;
    int vertices;
  };
  for (const Case& c : std::vector<Case>{{"bowtie", bowtie, 7}, {"fin", fin, 5}, {"flipped", flipped, 4},
                                         {"duplicated", duplicated, 4}, {"moebius", moebius, 10}}) {
    SCOPED_TRACE(c.name);
    const MeshSoup m = with_positions(c.faces, c.vertices);
    expect_exact_round_trip(m);
    // Without stitching the copies stay: the vertex count grows by the number of pairs.
    EncodeOptions o;
    o.qp = 0;
    EncodeStats stats;
    const std::string bytes = encode_ebm(m, o, &stats);
    const MeshSoup split = decode_ebm(bytes, false);
    EXPECT_EQ(split.positions.size(), static_cast<std::size_t>(c.vertices) + stats.stitch);
    EXPECT_EQ(face_set(split), face_set(m));
  }
}

TEST(EdgebreakerEbm, DegenerateFacesAreDroppedOrRejected) {
  const MeshSoup m = with_positions({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {1, 1, 2}}, 4);
  EncodeOptions o;
  EncodeStats stats;
  const MeshSoup out = decode_ebm(encode_ebm(m, o, &stats));
  EXPECT_EQ(stats.dropped_degenerate, 1u);
  EXPECT_EQ(out.triangles.size(), 4u);
  o.strict = true;
  expect_bad_input([&] { encode_ebm(m, o); }, "repeats a vertex");
}

TEST(EdgebreakerEbm, BadMeshInput) {
  EncodeOptions o;
  expect_bad_input([&] { encode_ebm(with_positions({{0, 1, 5}}, 3), o); }, "outside");
  MeshSoup nan = with_positions({{0, 1, 2}}, 3);
  nan.positions[1][2] = std::nan("");
  expect_bad_input([&] { encode_ebm(nan, o); }, "not finite");
}

// Quantised: every coordinate within half a step of the input (docs/ebcode.md §5).
TEST(EdgebreakerEbm, QuantisationErrorIsAtMostHalfAStep) {
  const auto s = fest::test::eb::subdivided_icosahedron(3);
  MeshSoup m;
  m.triangles = s.triangles;
  for (int i = 0; i < s.vertex_count; ++i)
    m.positions.push_back({std::sin(i * 0.7) * 3.1, std::cos(i * 1.3) * 2.2 + 0.001 * i, std::sin(i * 0.11) - 7});
  for (int bits : {4, 11, 14, 20}) {
    EncodeOptions o;
    o.qp = bits;
    o.predictor = bits == 11 ? Predictor::multi : Predictor::parallelogram;
    const std::string bytes = encode_ebm(m, o);
    const EbmHeader h = read_ebm_header(bytes);
    const MeshSoup out = decode_ebm(bytes);
    const double half_step = h.box[3] / (2.0 * (std::ldexp(1.0, bits) - 1));
    // Vertices come back in G order; match them through the faces.
    ASSERT_EQ(out.triangles.size(), m.triangles.size());
    const EncodeOptions exact{};
    (void)exact;
    std::map<int, Point> seen;
    const auto sorted_in = face_set(m);
    double worst = 0;
    for (std::size_t f = 0; f < out.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const Point& p = out.positions[static_cast<std::size_t>(out.triangles[f][static_cast<std::size_t>(k)])];
        double best = 1e300;
        for (const Point& q : m.positions)
          best = std::min(best, std::max({std::fabs(p[0] - q[0]), std::fabs(p[1] - q[1]), std::fabs(p[2] - q[2])}));
        worst = std::max(worst, best);
      }
    EXPECT_LE(worst, half_step * (1 + 1e-9)) << bits;
  }
}

TEST(EdgebreakerEbm, DamagedStreamsAreRejected) {
  const auto s = fest::test::eb::subdivided_icosahedron(2);
  for (int version : {2, 1}) {
    SCOPED_TRACE(version);
    EncodeOptions o;
    o.version = version;
    const std::string good = encode_ebm(with_positions(s.triangles, s.vertex_count), o);
    for (std::size_t n = 0; n < good.size(); n += 37) expect_bad_input([&] { decode_ebm(good.substr(0, n)); });
    std::string flipped = good;
    flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
    expect_bad_input([&] { decode_ebm(flipped); }, "CRC mismatch");
    std::string v3 = good;
    v3[8] = 3;
    expect_bad_input([&] { decode_ebm(v3); }, "major version 3");
  }
  expect_bad_input([&] { decode_ebm("not an ebm stream at all"); }, "magic");
}

// ebm(5), version 2.0: a closed single-component mesh without side information costs
// magic 8 + version 2 + flags 1 + modes 1 + varint symbols + qp 1 + box 16, then the CONN
// length as a varint, CONN and GEOM (the last section, no length), and the CRC 4.
TEST(EdgebreakerEbm, CompactContainerLayout) {
  const auto t = fest::test::eb::tetrahedron();
  EncodeStats st2, st1;
  EncodeOptions o;
  const std::string v2 = encode_ebm(with_positions(t.triangles, t.vertex_count), o, &st2);
  o.version = 1;
  const std::string v1 = encode_ebm(with_positions(t.triangles, t.vertex_count), o, &st1);
  ASSERT_EQ(st2.symbols, 3u);
  const std::size_t conn = st2.section_bytes.at("CONN"), geom = st2.section_bytes.at("GEOM");
  ASSERT_LT(conn, 128u);
  EXPECT_EQ(v2.size(), 8 + 2 + 1 + 1 + 1 + 1 + 16 + 1 + conn + geom + 4);
  EXPECT_EQ(v2[10], 0x03);  // geometry and exclusion
  // 1.0's container (everything but the section payloads) has 4 more bytes of version and
  // flags, a 4-byte header length, 13 one-byte varints, an 8-byte tag and length per section, END!.
  const auto container = [](const std::string& bytes, const EncodeStats& st) {
    std::size_t payload = 0;
    for (const auto& [tag, n] : st.section_bytes) payload += n;
    return bytes.size() - payload;
  };
  EXPECT_EQ(container(v2, st2), 35u);
  EXPECT_EQ(container(v1, st1), 8 + 2 + 2 + 4 + 13 + 16 + 2 * 8 + 4 + 4u);
  const EbmHeader h = read_ebm_header(v2);
  EXPECT_EQ(h.major, 2);
  EXPECT_EQ(h.vertices, 4u);  // not stored in 2.0: rebuilt by decoding
  EXPECT_EQ(h.faces, 4u);
  EXPECT_EQ(h.components, 1u);
  EXPECT_EQ(h.section_bytes.at("GEOM"), geom);
}

}  // namespace

namespace {

// Hostile streams behind a valid CRC (what the fuzz target explores): random byte
// changes in the header and the sections, resealed, must give a clean bad_input or a
// mesh whose indices are all in range -- never a crash, a hang or a huge allocation.
// 2.0's header fields out of range, behind a valid CRC: each is named in the error.
TEST(EdgebreakerEbm, CompactHeaderFieldsAreChecked) {
  const auto t = fest::test::eb::tetrahedron();
  const std::string good = encode_ebm(with_positions(t.triangles, t.vertex_count), EncodeOptions{});
  ASSERT_EQ(good[8], 2);
  const auto with = [&](std::size_t at, char value) {
    std::string bad = good;
    bad[at] = value;
    reseal_ebm(bad);
    return bad;
  };
  expect_bad_input([&] { decode_ebm(with(9, 2)); }, "version 2.2");
  expect_bad_input([&] { decode_ebm(with(10, static_cast<char>(0x83))); }, "reserved flag");
  expect_bad_input([&] { decode_ebm(with(11, 0x03)); }, "modes byte");
  expect_bad_input([&] { decode_ebm(with(11, 0x42)); }, "modes byte");
  // flag bit 6 (several components) with the symbol count read as the component count
  expect_bad_input([&] { decode_ebm(with(10, 0x43)); });
  // the holes flag without holes: its count is read from the next byte (qp 14) and the
  // sections no longer match
  expect_bad_input([&] { decode_ebm(with(10, 0x07)); });
  expect_bad_input([&] { decode_ebm(with(13, 31)); }, "quantisation bits 31");
  expect_bad_input([&] { decode_ebm(good.substr(0, 14)); }, "CRC");
}

// Version 2.0 has no redundant fields (no tags, no counts the decoder rebuilds), so fewer
// mutations are caught by a consistency check there: most that hit the range-coded
// positions give another valid mesh, which only the CRC (bypassed here) can tell.
void expect_mutations_rejected_cleanly(int version, int at_least);
TEST(EdgebreakerEbm, ResealedMutationsAreRejectedCleanly) {
  expect_mutations_rejected_cleanly(1, 1000);
  expect_mutations_rejected_cleanly(2, 300);
}

void expect_mutations_rejected_cleanly(int version, int at_least) {
  SCOPED_TRACE(version);
  std::vector<Triangle> t = fest::test::eb::subdivided_icosahedron(2).triangles;
  t.push_back({0, 1, 50});  // some side information: a fin makes a hole and copies
  EncodeOptions options;
  options.version = version;
  const std::string good = encode_ebm(with_positions(t, 162), options);
  std::mt19937 rng(11);
  int rejected = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string bad = good;
    const int changes = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < changes; ++k) {
      const std::size_t at = 8 + rng() % (bad.size() - 16);
      bad[at] = static_cast<char>(rng() & 0xFF);
    }
    reseal_ebm(bad);
    try {
      const MeshSoup m = decode_ebm(bad);
      for (const Triangle& f : m.triangles)
        for (int v : f) ASSERT_TRUE(v >= 0 && static_cast<std::size_t>(v) < m.positions.size());
    } catch (const fest::Error& e) {
      ASSERT_EQ(e.status(), fest::Status::bad_input) << e.what();
      ++rejected;
    }
  }
  EXPECT_GT(rejected, at_least);
}

}  // namespace

namespace {

// Committed streams (tests/data/ebm, also the fuzz seeds) stay readable: the format is an
// interface. Counts are the source meshes' (CGAL's icosahedron, eight, mushroom; a
// tetrahedron; two tetrahedra sharing a vertex).
TEST(EdgebreakerEbm, CommittedStreamsDecode) {
  const std::string dir = std::string(FEST_TEST_DATA_DIR) + "/ebm/";
  const auto slurp = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  struct Case {
    const char* file;
    std::size_t vertices, faces;
  };
  for (const Case& c : std::vector<Case>{{"tetrahedron", 4, 4},
                                         {"tetrahedron_raw_lossless", 4, 4},
                                         {"icosahedron_static", 12, 20},
                                         {"eight_genus2", 315, 634},
                                         {"eight_multi", 315, 634},
                                         {"mushroom_hole", 2337, 4608},
                                         {"bowtie_stitch", 7, 8},
                                         {"tetrahedron_attributes", 4, 4}}) {
    SCOPED_TRACE(c.file);
    // X.ebm is a 1.0 stream (committed before 2.0 existed), X_v2.ebm the same mesh, options
    // and box written as 2.0: both decode to exactly the same mesh, stitched or not.
    const std::string v1 = slurp(dir + c.file + ".ebm"), v2 = slurp(dir + c.file + "_v2.ebm");
    ASSERT_FALSE(v1.empty());
    ASSERT_FALSE(v2.empty());
    EXPECT_EQ(v1[8], 1);
    EXPECT_EQ(v2[8], 2);
    EXPECT_LT(v2.size(), v1.size());
    for (bool stitch : {true, false}) {
      const MeshSoup m = decode_ebm(v1, stitch);
      if (stitch) {
        EXPECT_EQ(m.positions.size(), c.vertices);
        EXPECT_EQ(m.triangles.size(), c.faces);
      }
      const MeshSoup m2 = decode_ebm(v2, stitch);
      EXPECT_EQ(m2.positions, m.positions);
      EXPECT_EQ(m2.triangles, m.triangles);
      EXPECT_EQ(m2.normals, m.normals);
      EXPECT_EQ(m2.colors, m.colors);
      EXPECT_EQ(m2.texcoords, m.texcoords);
    }
    // The 1.0 writer is kept byte for byte: re-encoding the decoded mesh with the stream's
    // own options gives the committed bytes back.
    const EbmHeader h = read_ebm_header(v1);
    EncodeOptions o;
    o.version = 1;
    o.qp = h.qp;
    o.box = h.box;
    o.predictor = static_cast<Predictor>(h.predictor);
    o.conn = h.conn_mode == 0 ? ConnChoice::raw : h.conn_mode == 1 ? ConnChoice::static_model : ConnChoice::adaptive;
    if (h.conn_mode == 1) o.model_id = h.model_id;
    EXPECT_EQ(encode_ebm(decode_ebm(v1), o), v1);
    o.version = 2;
    EXPECT_EQ(encode_ebm(decode_ebm(v1), o), v2);
  }
}

}  // namespace
