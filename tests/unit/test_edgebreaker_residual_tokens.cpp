// GEOM version 3, .ebm 2.1 (lib/edgebreaker/residual_tokens.hpp, docs/ebcode.md §5): one rANS
// token per residual with stored tables and raw low bits. The residuals come back exactly
// at every quantisation, damage is seen, and a whole .ebm written with it decodes to the
// same mesh as one written with GEOM version 2 (.ebm 2.0), whose bytes stay as they were.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

#include "edgebreaker/ebm.hpp"
#include "edgebreaker/residual_tokens.hpp"
#include "expect_error.hpp"
#include "test_edgebreaker_meshes.hpp"

namespace {

using namespace fest::edgebreaker;
using fest::test::expect_bad_input;

std::vector<std::int64_t> decode_all(const std::string& section, int bits, std::size_t n, bool* complete) {
  const ResidualTokenDecoder decoder(section, bits);
  ResidualTokenReader in = decoder.reader();
  std::vector<std::int64_t> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(in.get(static_cast<int>(i % 3)));
  *complete = in.complete();
  return out;
}

// Residuals of a smooth surface (Laplacian-like, varying in scale) plus the extremes
// of the wrapped range, -2^(bits-1) and 2^(bits-1) - 1.
std::vector<std::int64_t> residuals(int bits, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  const std::int64_t half = std::int64_t{1} << (bits - 1);
  std::vector<std::int64_t> r;
  for (std::size_t i = 0; i < n; ++i) {
    // Scales over the top eight lengths: a flat spread over all 30 makes tables that cannot
    // be described with 11-bit frequencies (the encoder then keeps GEOM version 2).
    const int low = std::max(0, bits - 8);
    const double scale = std::ldexp(1.0, low + static_cast<int>(rng() % static_cast<unsigned>(bits - low)));
    std::exponential_distribution<double> e(1.0 / scale);
    auto v = static_cast<std::int64_t>(e(rng));
    if (rng() & 1u) v = -v;
    r.push_back(std::clamp(v, -half, half - 1));
  }
  r.push_back(-half);
  r.push_back(half - 1);
  r.push_back(0);
  return r;
}

TEST(EdgebreakerResidualTokens, ResidualsRoundTripAtEveryQuantisation) {
  for (int bits = 1; bits <= 30; ++bits) {
    SCOPED_TRACE(bits);
    for (std::size_t n : {std::size_t{3}, std::size_t{30}, std::size_t{3000}}) {
      const std::vector<std::int64_t> r = residuals(bits, n - 3, static_cast<unsigned>(bits * 7 + n));
      const auto section = encode_residual_tokens(r, bits);
      ASSERT_TRUE(section.has_value());
      bool complete = false;
      EXPECT_EQ(decode_all(*section, bits, r.size(), &complete), r);
      EXPECT_TRUE(complete);
    }
  }
}

TEST(EdgebreakerResidualTokens, DamageIsSeen) {
  const std::vector<std::int64_t> r = residuals(14, 3000, 5);
  const std::string good = *encode_residual_tokens(r, 14);
  // Too few or too many coordinates read, a cut stream, changed bytes: either the tables
  // are refused or the streams do not end where the positions do. Never a read outside.
  bool complete = true;
  decode_all(good, 14, r.size() - 3, &complete);
  EXPECT_FALSE(complete);
  decode_all(good, 14, r.size() + 3, &complete);
  EXPECT_FALSE(complete);
  int seen = 0, tried = 0;
  std::mt19937 rng(9);
  for (int trial = 0; trial < 300; ++trial) {
    std::string bad = good;
    if (trial % 3 == 0) {
      bad.resize(rng() % bad.size());
    } else {
      bad[rng() % bad.size()] ^= static_cast<char>(1 + rng() % 255);
    }
    ++tried;
    try {
      decode_all(bad, 14, r.size(), &complete);
      if (!complete) ++seen;
    } catch (const fest::Error& e) {
      ASSERT_EQ(e.status(), fest::Status::bad_input) << e.what();
      ++seen;
    }
  }
  // A change in the raw bits alone changes values without breaking the streams' ends.
  EXPECT_GT(seen, tried / 3);
  expect_bad_input([&] { ResidualTokenDecoder(good, 0); }, "1..30");
  expect_bad_input([&] { ResidualTokenDecoder(std::string("\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\x01", 11), 14); });
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

EncodeOptions options_of(const EbmHeader& h, int geom_version) {
  EncodeOptions o;
  o.qp = h.qp;
  o.box = h.box;
  o.predictor = static_cast<Predictor>(h.predictor);
  o.conn = h.conn_mode == 0 ? ConnChoice::raw : h.conn_mode == 1 ? ConnChoice::static_model : ConnChoice::adaptive;
  if (h.conn_mode == 1) o.model_id = h.model_id;
  o.geom_version = geom_version;
  return o;
}

void expect_same_mesh(const MeshSoup& a, const MeshSoup& b) {
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.colors, b.colors);
  EXPECT_EQ(a.texcoords, b.texcoords);
}

// The committed 2.0 streams (written by ebcode before 2.1 existed) re-encoded with GEOM
// version 3: .ebm 2.1, smaller GEOM on the larger meshes, and the same decoded mesh through
// holes, stitch pairs, handles, several predictors and attributes; with GEOM version 2
// forced, the committed bytes come back (2.0 is still written byte for byte).
TEST(EdgebreakerResidualTokens, WholeStreamsDecodeAsVersionTwo) {
  const std::string dir = std::string(FEST_TEST_DATA_DIR) + "/ebm/";
  for (const char* name : {"tetrahedron", "icosahedron_static", "eight_genus2", "eight_multi", "mushroom_hole",
                           "bowtie_stitch", "tetrahedron_attributes"}) {
    SCOPED_TRACE(name);
    const std::string v20 = slurp(dir + name + "_v2.ebm");
    ASSERT_FALSE(v20.empty());
    const EbmHeader h = read_ebm_header(v20);
    const MeshSoup mesh = decode_ebm(v20);
    EXPECT_EQ(encode_ebm(mesh, options_of(h, 2)), v20);
    const std::string v21 = encode_ebm(mesh, options_of(h, 3));
    EXPECT_EQ(v21[8], 2);
    EXPECT_EQ(v21[9], 1);
    for (bool stitch : {true, false}) expect_same_mesh(decode_ebm(v21, stitch), decode_ebm(v20, stitch));
    // Automatic on these small meshes (below 4096 coded vertices): the smaller GEOM, 3 on
    // a tie.
    const std::string chosen = encode_ebm(mesh, options_of(h, 0));
    const std::size_t geom2 = read_ebm_header(v20).section_bytes.at("GEOM"), geom3 = read_ebm_header(v21).section_bytes.at("GEOM");
    EXPECT_EQ(chosen, geom3 <= geom2 ? v21 : v20);
  }
}

// Committed 2.1 streams (tests/data/ebm/*_v21.ebm, also fuzz seeds) stay readable and
// decode to the same mesh as the 1.0 and 2.0 streams of the same mesh and options.
TEST(EdgebreakerResidualTokens, CommittedStreamsDecode) {
  const std::string dir = std::string(FEST_TEST_DATA_DIR) + "/ebm/";
  for (const char* name : {"eight_multi", "mushroom_hole"}) {
    SCOPED_TRACE(name);
    const std::string v10 = slurp(dir + name + ".ebm"), v21 = slurp(dir + name + "_v21.ebm");
    ASSERT_FALSE(v21.empty());
    EXPECT_EQ(v21[9], 1);
    for (bool stitch : {true, false}) expect_same_mesh(decode_ebm(v21, stitch), decode_ebm(v10, stitch));
    EXPECT_EQ(encode_ebm(decode_ebm(v21), options_of(read_ebm_header(v21), 3)), v21);
  }
}

// Holes, copies, isolated vertices and all three attributes in one 2.1 stream: only GEOM
// changes (ISOL and the attribute sections stay 2.0's), and every predictor decodes to the
// same mesh as from 2.0.
TEST(EdgebreakerResidualTokens, EverythingElseAsInVersionTwo) {
  std::vector<Triangle> t = fest::test::eb::subdivided_icosahedron(2).triangles;
  t.push_back({0, 1, 160});  // a fin: a hole, a dummy and copies
  MeshSoup m;
  for (int v = 0; v < 165; ++v) {  // 162 .. 164 isolated
    const double a = 0.3 * v;
    m.positions.push_back({std::sin(a), std::cos(0.7 * a), std::sin(0.2 * a) + 0.01 * v});
    m.normals.push_back({std::cos(a), std::sin(a) * 0.6, std::sin(a) * 0.8});
    m.colors.push_back({static_cast<std::uint8_t>(v * 5), static_cast<std::uint8_t>(255 - v), 7});
    m.texcoords.push_back({0.01 * v, 2.0 - 0.02 * v});
  }
  m.triangles = t;
  for (Predictor p : {Predictor::parallelogram, Predictor::multi, Predictor::delta, Predictor::none}) {
    SCOPED_TRACE(static_cast<int>(p));
    EncodeOptions o;
    o.qp = 9;
    o.predictor = p;
    o.geom_version = 2;
    const std::string v20 = encode_ebm(m, o);
    o.geom_version = 3;
    EncodeStats stats;
    const std::string v21 = encode_ebm(m, o, &stats);
    EXPECT_EQ(stats.geom_version, 3);
    ASSERT_EQ(v21[9], 1);
    const EbmHeader h20 = read_ebm_header(v20), h21 = read_ebm_header(v21);
    EXPECT_EQ(h21.section_bytes.at("ISOL"), h20.section_bytes.at("ISOL"));
    EXPECT_EQ(h21.section_bytes.at("NRML"), h20.section_bytes.at("NRML"));
    EXPECT_EQ(h21.vertices, 165u);
    for (bool stitch : {true, false}) expect_same_mesh(decode_ebm(v21, stitch), decode_ebm(v20, stitch));
  }
}

TEST(EdgebreakerResidualTokens, OptionsAndHeaderAreChecked) {
  const auto t = fest::test::eb::subdivided_icosahedron(2);
  MeshSoup m;
  for (int i = 0; i < t.vertex_count; ++i) m.positions.push_back({std::sin(i * 1.0), std::cos(i * 0.7), std::sin(i * 0.3)});
  m.triangles = t.triangles;
  EncodeOptions o;
  o.geom_version = 3;
  o.qp = 0;
  EXPECT_NE(fest::test::usage_message([&] { encode_ebm(m, o); }).find("GEOM version 3"), std::string::npos);
  o.qp = 12;
  o.version = 1;
  EXPECT_NE(fest::test::usage_message([&] { encode_ebm(m, o); }).find("GEOM version 3"), std::string::npos);
  o.version = 2;
  o.geom_version = 4;
  EXPECT_NE(fest::test::usage_message([&] { encode_ebm(m, o); }).find("GEOM version 4"), std::string::npos);
  o.geom_version = 3;
  const std::string v21 = encode_ebm(m, o);
  ASSERT_EQ(v21[9], 1);
  // From 4096 coded vertices on, the default writes version 3 without coding version 2.
  const auto big = fest::test::eb::subdivided_icosahedron(5);
  MeshSoup b;
  for (int i = 0; i < big.vertex_count; ++i) b.positions.push_back({std::sin(i * 1.0), std::cos(i * 0.7), std::sin(i * 0.3)});
  b.triangles = big.triangles;
  ASSERT_GE(b.positions.size(), 4096u);
  EXPECT_EQ(encode_ebm(b, EncodeOptions{})[9], 1);
  // A 2.0 stream relabelled 2.1 (resealed) is refused or fails the streams' end check.
  o.geom_version = 2;
  std::string relabelled = encode_ebm(m, o);
  relabelled[9] = 1;
  reseal_ebm(relabelled);
  expect_bad_input([&] { decode_ebm(relabelled); });
  // 2.1 without positions, or with lossless ones: refused by name.
  EncodeOptions none;
  none.geometry = false;
  std::string flat = encode_ebm(m, none);
  flat[9] = 1;
  reseal_ebm(flat);
  expect_bad_input([&] { decode_ebm(flat); }, "2.1");
}

}  // namespace
