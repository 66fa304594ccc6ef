// The .ebm container and the pipeline around the connectivity coder (docs/ebcode.md §5):
// prepare -> traverse -> code connectivity (running the decoder alongside) -> side
// sections -> quantised geometry in G order; and the exact inverse.
#include "edgebreaker/ebm.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/crc32.hpp"
#include "core/error.hpp"
#include "core/little_endian.hpp"
#include "edgebreaker/prepare.hpp"
#include "edgebreaker/range_coder.hpp"
#include "edgebreaker/state_machine.hpp"

namespace fest::edgebreaker {
namespace {

constexpr unsigned char magic[8] = {0x89, 'E', 'B', 'M', 0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::size_t max_elements = static_cast<std::size_t>(std::numeric_limits<int>::max() / 16);
// Below this many coded vertices the encoder codes GEOM both ways and compares (encode_ebm).
constexpr std::size_t geom_compare_below = 4096;

// ---- little-endian writing and bounded reading -------------------------------------

using little_endian::put_f32;
using little_endian::put_u16;
using little_endian::put_u32;
using little_endian::put_u8;
using little_endian::put_varint;

// What running out of a section's bytes means (little_endian::Reader): `what` names it.
struct SectionErrors {
  SectionErrors(const char* section) : what(section) {}  // NOLINT: a Reader is made from its section's name
  [[noreturn]] void truncated(std::size_t, std::size_t) const { throw bad_input("{} is truncated", what); }
  [[noreturn]] void varint_too_long(std::size_t) const { throw bad_input("{}: a number is too long", what); }
  const char* what;
};
using Reader = little_endian::Reader<SectionErrors>;

// ---- .ebm 2.x flags byte ----------------------------------------------------------------
// bit 0 geometry, 1 exclusion, 2 holes, 3 stitch, 4 events, 5 isolated, 6 several
// components, 7 reserved (0). Lossless is qp 0; the rest of 1.x's flags were never set.
namespace v2_bit {
constexpr unsigned geometry = 1u << 0, exclusion = 1u << 1, holes = 1u << 2, stitch = 1u << 3, events = 1u << 4,
                   isolated = 1u << 5, several = 1u << 6, reserved = 1u << 7;
}
constexpr std::pair<std::uint16_t, unsigned> v2_flag_map[] = {
    {ebm_flags::geometry, v2_bit::geometry}, {ebm_flags::exclusion, v2_bit::exclusion}, {ebm_flags::holes, v2_bit::holes},
    {ebm_flags::stitch, v2_bit::stitch},     {ebm_flags::events, v2_bit::events},       {ebm_flags::isolated, v2_bit::isolated}};

unsigned v2_flags_of(std::uint16_t flags, bool several) {
  unsigned out = several ? v2_bit::several : 0u;
  for (const auto& [v1, v2] : v2_flag_map)
    if (flags & v1) out |= v2;
  return out;
}

void put_section(std::string& out, const char* tag, const std::string& payload) {
  out.append(tag, 4);
  put_u32(out, static_cast<std::uint32_t>(payload.size()));
  out += payload;
}

// ---- hole flags: one adaptive bit per G vertex, context min(valence, 16) -------------

std::vector<int> valences(const std::vector<Triangle>& triangles, int vertex_count) {
  std::vector<int> v(static_cast<std::size_t>(vertex_count), 0);
  for (const Triangle& t : triangles)
    for (int x : t) ++v[static_cast<std::size_t>(x)];
  return v;
}

std::string encode_hole_flags(const std::vector<char>& dummy, const std::vector<int>& valence) {
  RangeEncoder enc;
  std::array<std::uint16_t, 17> p;
  p.fill(probability_half);
  for (std::size_t g = 0; g < dummy.size(); ++g)
    enc.bit(p[static_cast<std::size_t>(std::min(valence[g], 16))], dummy[g] ? 1 : 0);
  return enc.finish();
}

std::vector<char> decode_hole_flags(std::string_view bytes, const std::vector<int>& valence) {
  RangeDecoder dec(bytes);
  std::array<std::uint16_t, 17> p;
  p.fill(probability_half);
  std::vector<char> dummy(valence.size(), 0);
  for (std::size_t g = 0; g < dummy.size(); ++g) {
    dummy[g] = static_cast<char>(dec.bit(p[static_cast<std::size_t>(std::min(valence[g], 16))]));
    if (dec.overrun() > 12) break;
  }
  if (dec.truncated()) throw bad_input("hole section is truncated");
  return dummy;
}

// ---- quantisation ---------------------------------------------------------------------

// Lossless: float bits as monotone signed integers.
std::int64_t monotone(float f) {
  std::uint32_t i;
  std::memcpy(&i, &f, 4);
  const auto s = static_cast<std::int32_t>(i);
  return s < 0 ? static_cast<std::int64_t>(s ^ 0x7FFFFFFF) : s;
}
float from_monotone(std::int64_t m) {
  auto s = static_cast<std::int32_t>(m);
  if (s < 0) s ^= 0x7FFFFFFF;
  std::uint32_t i = static_cast<std::uint32_t>(s);
  float f;
  std::memcpy(&f, &i, 4);
  return f;
}

float float_down(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
float float_up(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// clamp(llround(t), 0, top) for finite t, without the library call (a tenth of the
// encoder's quantisation cost): below 2^62 the cast truncates to floor(t) for t > 0, and
// t - floor(t) is exact, so "fraction >= 1/2 rounds up" is llround's half-away-from-zero.
std::int64_t round_to_step(double t, std::int64_t top) {
  if (!(t > 0)) return 0;  // llround of anything <= 0.5 below zero clamps to 0 as well
  if (t >= static_cast<double>(top)) return top;
  const auto r = static_cast<std::int64_t>(t);
  return std::min(r + (t - static_cast<double>(r) >= 0.5 ? 1 : 0), top);
}

struct Quantiser {
  std::array<float, 4> box{};
  int bits = 14;
  // 2^bits - 1, exactly (bits <= 30); an integer shift, since ldexp per coordinate was a
  // tenth of the encoder's instructions.
  double steps() const { return static_cast<double>((std::uint64_t{1} << bits) - 1u); }
  QPoint quantise(const std::array<double, 3>& x) const {
    QPoint q{};
    for (std::size_t k = 0; k < 3; ++k) {
      if (bits == 0) {
        q[k] = monotone(static_cast<float>(x[k]));
      } else if (box[3] <= 0) {
        q[k] = 0;
      } else {
        const double t = (x[k] - static_cast<double>(box[k])) / static_cast<double>(box[3]) * steps();
        q[k] = round_to_step(t, static_cast<std::int64_t>((std::uint64_t{1} << bits) - 1u));
      }
    }
    return q;
  }
  std::array<double, 3> restore(const QPoint& q) const {
    std::array<double, 3> x{};
    for (std::size_t k = 0; k < 3; ++k)
      x[k] = bits == 0 ? static_cast<double>(from_monotone(q[k]))
                       : static_cast<double>(box[k]) + static_cast<double>(q[k]) * static_cast<double>(box[3]) / steps();
    return x;
  }
};

std::array<float, 4> bounding_box(const std::vector<std::array<double, 3>>& p) {
  if (p.empty()) return {0, 0, 0, 0};
  std::array<double, 3> lo = p[0], hi = p[0];
  for (const auto& x : p)
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  std::array<float, 4> box{};
  double extent = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    box[k] = float_down(lo[k]);
    extent = std::max(extent, hi[k] - static_cast<double>(box[k]));
  }
  box[3] = float_up(extent);
  return box;
}

// ---- the pieces both directions agree on ------------------------------------------------

// Output numbering of G vertices: non-dummy, non-copy vertices in G order; a copy takes
// its original's number (stitch) or its own in G order (no stitch); dummies get -1.
struct Numbering {
  std::vector<int> output;   // per G vertex
  std::vector<int> same_as;  // per G vertex: the first G vertex of its stitch group if earlier
  int count = 0;
};

// `plain`: no dummies and no stitch pairs, so every G vertex is its own output vertex
// (what the loops below give then, without them).
// `no_copies`: no stitch pairs (original_of all -1), so only the dummies are left out.
Numbering number_vertices(const std::vector<char>& dummy, const std::vector<int>& original_of, bool stitch,
                          bool plain = false, bool no_copies = false) {
  const std::size_t n = dummy.size();
  Numbering num;
  if (plain) {
    num.output.resize(n);
    for (std::size_t g = 0; g < n; ++g) num.output[g] = static_cast<int>(g);
    num.same_as.assign(n, -1);
    num.count = static_cast<int>(n);
    return num;
  }
  if (no_copies) {
    num.output.resize(n);
    for (std::size_t g = 0; g < n; ++g) num.output[g] = dummy[g] ? -1 : num.count++;
    num.same_as.assign(n, -1);
    return num;
  }
  num.output.assign(n, -1);
  num.same_as.assign(n, -1);
  for (std::size_t g = 0; g < n; ++g)
    if (!dummy[g] && (original_of[g] < 0 || !stitch)) num.output[g] = num.count++;
  std::vector<int> first(n, -1);  // per group root (the original): first G member
  for (std::size_t g = 0; g < n; ++g) {
    if (dummy[g]) continue;
    const int root = original_of[g] >= 0 ? original_of[g] : static_cast<int>(g);
    if (stitch && original_of[g] >= 0) num.output[g] = num.output[static_cast<std::size_t>(root)];
    int& f = first[static_cast<std::size_t>(root)];
    if (f == -1)
      f = static_cast<int>(g);
    else
      num.same_as[g] = f;
  }
  return num;
}

// What the position coder needs of the connectivity, the same on both sides of the stream:
// the parallelogram of each G vertex, the dummies (no position) and the stitched copies.
GeometryPlan geometry_plan(const DecodedConnectivity& dec, const std::vector<char>& dummy, const Numbering& num) {
  GeometryPlan plan;
  plan.parallelogram = dec.parallelogram;
  plan.unusable = dummy;
  plan.same_as = num.same_as;
  plan.triangles = &dec.triangles;
  plan.opposite = &dec.opposite;
  return plan;
}

const char* conn_mode_name(int mode) {
  switch (mode) {
    case 0: return "raw";
    case 1: return "static";
    case 2: return "adaptive";
    default: return "?";
  }
}


// ---- per-vertex attributes (docs/ebcode.md §5) -------------------------------------------

// kind 1 normal (3 components over [-1, 1]), 2 colour (3 bytes, exact), 3 texcoord (2
// components over their own box). One section each: NRML, COLR, TEXC.
struct Attribute {
  int kind = 0;
  int bits = 0;
  int components = 3;
  std::array<float, 3> box{};  // min of the first two components, extent
  const char* tag() const { return kind == 1 ? "NRML" : kind == 2 ? "COLR" : "TEXC"; }
  const char* name() const { return kind == 1 ? "normal" : kind == 2 ? "color" : "texcoord"; }
  // 2^bits - 1, exactly (bits <= 30); an integer shift, since ldexp per coordinate was a
  // tenth of the encoder's instructions.
  double steps() const { return static_cast<double>((std::uint64_t{1} << bits) - 1u); }
  double lo(std::size_t k) const { return kind == 1 ? -1.0 : kind == 2 ? 0.0 : static_cast<double>(box[k]); }
  double extent() const { return kind == 1 ? 2.0 : kind == 2 ? 255.0 : static_cast<double>(box[2]); }
  QPoint quantise(const double* x) const {
    QPoint q{0, 0, 0};
    for (std::size_t k = 0; k < static_cast<std::size_t>(components); ++k) {
      const double t = extent() > 0 ? (x[k] - lo(k)) / extent() * steps() : 0.0;
      q[k] = std::clamp<std::int64_t>(std::llround(std::isfinite(t) ? t : 0.0), 0, static_cast<std::int64_t>(steps()));
    }
    return q;
  }
  double restore(const QPoint& q, std::size_t k) const { return lo(k) + static_cast<double>(q[k]) * extent() / steps(); }
};

std::vector<Attribute> attributes_of(const MeshSoup& mesh, const EncodeOptions& options) {
  std::vector<Attribute> out;
  const std::size_t n = mesh.positions.size();
  if (!mesh.normals.empty()) {
    if (mesh.normals.size() != n) throw bad_input("{} normals for {} vertices", mesh.normals.size(), n);
    Attribute a;
    a.kind = 1;
    a.bits = options.qn;
    out.push_back(a);
  }
  if (!mesh.colors.empty()) {
    if (mesh.colors.size() != n) throw bad_input("{} colours for {} vertices", mesh.colors.size(), n);
    Attribute a;
    a.kind = 2;
    a.bits = 8;
    out.push_back(a);
  }
  if (!mesh.texcoords.empty()) {
    if (mesh.texcoords.size() != n) throw bad_input("{} texture coordinates for {} vertices", mesh.texcoords.size(), n);
    Attribute a;
    a.kind = 3;
    a.bits = options.qt;
    a.components = 2;
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t k = 0; k < 2; ++k) {
        const double x = mesh.texcoords[v][k];
        if (!std::isfinite(x)) throw bad_input("vertex {} has a texture coordinate that is not finite", v);
        lo[k] = v == 0 ? x : std::min(lo[k], x);
        hi[k] = v == 0 ? x : std::max(hi[k], x);
      }
    a.box[0] = float_down(lo[0]);
    a.box[1] = float_down(lo[1]);
    a.box[2] = float_up(std::max(hi[0] - static_cast<double>(a.box[0]), hi[1] - static_cast<double>(a.box[1])));
    out.push_back(a);
  }
  return out;
}

void attribute_values(const MeshSoup& mesh, const Attribute& a, std::size_t v, double* x) {
  if (a.kind == 1)
    for (std::size_t k = 0; k < 3; ++k) x[k] = mesh.normals[v][k];
  else if (a.kind == 2)
    for (std::size_t k = 0; k < 3; ++k) x[k] = mesh.colors[v][k];
  else
    for (std::size_t k = 0; k < 2; ++k) x[k] = mesh.texcoords[v][k];
}


}  // namespace

void reseal_ebm(std::string& bytes) {
  if (bytes.size() < 8) return;
  const std::uint32_t crc = crc32_of(std::string_view(bytes).substr(0, bytes.size() - 4));
  for (int k = 0; k < 4; ++k) bytes[bytes.size() - 4 + static_cast<std::size_t>(k)] = static_cast<char>((crc >> (8 * k)) & 0xFFu);
}

bool is_ebm(std::string_view bytes) { return bytes.size() >= 8 && std::memcmp(bytes.data(), magic, 8) == 0; }

Clers mesh_symbols(const MeshSoup& mesh, bool strict) {
  const PreparedMesh prepared =
      prepare_mesh(mesh.triangles, static_cast<int>(mesh.positions.size()), strict);
  return traverse(prepared.table).code.clers;
}

std::string encode_ebm(const MeshSoup& mesh, const EncodeOptions& options, EncodeStats* stats) {
  if (options.qp < 0 || options.qp > 30) throw usage_error("position quantisation bits {} outside 0..30", options.qp);
  if (options.qn < 1 || options.qn > 30) throw usage_error("normal quantisation bits {} outside 1..30", options.qn);
  if (options.qt < 1 || options.qt > 30) throw usage_error("texture-coordinate quantisation bits {} outside 1..30", options.qt);
  if (options.version != 1 && options.version != 2) throw usage_error(".ebm version {} cannot be written (1 or 2)", options.version);
  if (options.geom_version != 0 && options.geom_version != 2 && options.geom_version != 3)
    throw usage_error("GEOM version {} cannot be written (2 or 3)", options.geom_version);
  if (options.geom_version == 3 && (options.version != 2 || options.qp == 0))
    throw usage_error("GEOM version 3 needs an .ebm 2 container and quantised positions");
  if (mesh.positions.size() > max_elements) throw bad_input("{} vertices, more than supported", mesh.positions.size());
  if (options.geometry)
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      for (double x : mesh.positions[v])
        if (!std::isfinite(x)) throw bad_input("vertex {} has a coordinate that is not finite ({})", v, x);
  if (options.geometry && options.qp == 0)
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      for (double x : mesh.positions[v])
        if (static_cast<double>(static_cast<float>(x)) != x)
          throw bad_input("lossless positions (0 quantisation bits) store float32 exactly, but vertex {} has the double coordinate {}", v, x);

  const PreparedMesh prepared = prepare_mesh(mesh.triangles, static_cast<int>(mesh.positions.size()), options.strict);
  const Traversal trav = traverse(prepared.table);

  // Connectivity, with the decoder run alongside (contexts, and the G-order result).
  const std::size_t symbols = trav.code.clers.size();
  std::optional<ConnEncoded> conn;
  int conn_mode = 0;
  bool verified = false;  // the symbols decode the same whatever the coder: check once
  const auto consider = [&](ConnMode mode) {
    // The decoded connectivity is the same whatever the coder: built (and checked) once.
    ConnEncoded c = encode_connectivity(trav.code, mode, options.model_id, options.verify && !verified, !conn,
                                        options.predictor == Predictor::multi);
    verified = true;
    if (!conn) {
      conn = std::move(c);
      conn_mode = static_cast<int>(mode);
    } else if (c.bytes.size() < conn->bytes.size()) {
      conn->bytes = std::move(c.bytes);
      conn->exclusion = c.exclusion;
      conn_mode = static_cast<int>(mode);
    }
  };
  switch (options.conn) {
    case ConnChoice::raw: consider(ConnMode::raw); break;
    case ConnChoice::adaptive: consider(ConnMode::adaptive); break;
    case ConnChoice::static_model:
      try {
        consider(ConnMode::static_model);
      } catch (const Error& e) {
        if (e.status() != Status::failure) throw;
        throw bad_input("{}: use the adaptive coder, or let the encoder choose", e.what());
      }
      break;
    case ConnChoice::automatic:
      consider(ConnMode::adaptive);
      try {
        consider(ConnMode::static_model);
      } catch (const Error& e) {
        if (e.status() != Status::failure) throw;  // a violation: keep the adaptive code
      }
      break;
  }
  const DecodedConnectivity& dec = conn->decoded;

  // Self-check: the decoder's faces are the prepared faces in traversal order.
  const int g_count = dec.vertex_count;
  if (g_count != static_cast<int>(trav.vertex_order.size()) || dec.triangles.size() != trav.triangle_order.size())
    throw runtime_failure("internal: decoded connectivity has other counts than the input");
  for (std::size_t k = 0; k < dec.triangles.size(); ++k) {
    const int t = trav.triangle_order[k];
    std::array<int, 3> want{};
    for (int j = 0; j < 3; ++j) want[static_cast<std::size_t>(j)] = prepared.table.V[static_cast<std::size_t>(3 * t + j)];
    const Triangle& got = dec.triangles[k];
    bool same = false;
    for (int r = 0; r < 3 && !same; ++r)
      same = trav.vertex_order[static_cast<std::size_t>(got[static_cast<std::size_t>(r)])] == want[0] &&
             trav.vertex_order[static_cast<std::size_t>(got[static_cast<std::size_t>((r + 1) % 3)])] == want[1] &&
             trav.vertex_order[static_cast<std::size_t>(got[static_cast<std::size_t>((r + 2) % 3)])] == want[2];
    if (!same) throw runtime_failure("internal: self-verification failed at face {}", k);
  }

  // Per G vertex: dummy, copy (-> original's G id), input vertex.
  std::vector<int> g_of_table(static_cast<std::size_t>(prepared.table.vertex_count), -1);
  for (int g = 0; g < g_count; ++g) g_of_table[static_cast<std::size_t>(trav.vertex_order[static_cast<std::size_t>(g)])] = g;
  std::vector<char> dummy(static_cast<std::size_t>(g_count), 0);
  std::vector<int> original_of(static_cast<std::size_t>(g_count), -1);
  std::vector<int> input_of(static_cast<std::size_t>(g_count), -1);
  std::vector<std::pair<int, int>> stitch_pairs;  // (copy G, original G)
  for (int g = 0; g < g_count; ++g) {
    const int tv = trav.vertex_order[static_cast<std::size_t>(g)];
    if (prepared.is_dummy(tv)) {
      dummy[static_cast<std::size_t>(g)] = 1;
    } else if (tv >= prepared.input_vertices) {
      const int orig = prepared.copy_of[static_cast<std::size_t>(tv - prepared.input_vertices)];
      input_of[static_cast<std::size_t>(g)] = orig;
      if (options.stitch) {
        original_of[static_cast<std::size_t>(g)] = g_of_table[static_cast<std::size_t>(orig)];
        stitch_pairs.emplace_back(g, original_of[static_cast<std::size_t>(g)]);
      }
    } else {
      input_of[static_cast<std::size_t>(g)] = tv;
    }
  }
  const Numbering num = number_vertices(dummy, original_of, options.stitch);
  const std::vector<int> isolated = options.drop_isolated ? std::vector<int>{} : prepared.isolated;

  std::size_t out_faces = 0;
  for (const Triangle& t : dec.triangles)
    if (!dummy[static_cast<std::size_t>(t[0])] && !dummy[static_cast<std::size_t>(t[1])] &&
        !dummy[static_cast<std::size_t>(t[2])])
      ++out_faces;

  // Geometry.
  const ResidualCoding coding = options.version == 1 ? ResidualCoding::tree_v1 : ResidualCoding::distance_v2;
  Quantiser quant;
  quant.bits = options.qp;
  quant.box = options.box ? *options.box : bounding_box(mesh.positions);
  if (options.box && !(quant.box[3] >= 0)) throw usage_error("quantisation box: the extent must be >= 0");
  std::string geom, isol;
  bool geom_tokens = false;  // GEOM version 3, written as .ebm 2.1
  double max_error = 0, sum_sq = 0;
  std::size_t n_coords = 0;
  if (options.geometry) {
    // Every input vertex quantised once: for the G order, the isolated ones and the errors.
    std::vector<QPoint> qv(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) qv[v] = quant.quantise(mesh.positions[v]);
    std::vector<QPoint> q(static_cast<std::size_t>(g_count), QPoint{0, 0, 0});
    for (int g = 0; g < g_count; ++g)
      if (!dummy[static_cast<std::size_t>(g)]) q[static_cast<std::size_t>(g)] = qv[static_cast<std::size_t>(input_of[static_cast<std::size_t>(g)])];
    const GeometryPlan plan = geometry_plan(dec, dummy, num);
    // .ebm 2.x: GEOM version 3 (one rANS token per residual; docs/ebcode.md §5-§6). It
    // decodes without a branch on the data, which is worth a little size: on the bench
    // meshes it is 1 % smaller to 2.5 % larger than version 2 (which adapts; 3's tables
    // are stored). Below 4096 coded vertices the tables weigh more, so both are coded and
    // the smaller is kept (3 on a tie): such a mesh decodes in well under a millisecond
    // either way, and its bytes are what a user compares (no larger than Draco's; with a
    // slack of 1/32 in favour of 3, elephant-with-holes came out 32 bytes above it).
    // Above, coding both would cost a fifth of the encoding time (docs/ebcode.md §6), so 3
    // is written.
    std::optional<std::string> tokens;
    if (options.version == 2 && options.geom_version != 2) tokens = encode_position_tokens(q, plan, options.qp, options.predictor);
    std::size_t coded = 0;
    for (int g = 0; g < g_count; ++g)
      coded += !plan.unusable[static_cast<std::size_t>(g)] && plan.same_as[static_cast<std::size_t>(g)] < 0 ? 1 : 0;
    if (tokens && (options.geom_version == 3 || coded >= geom_compare_below)) {
      geom = std::move(*tokens);
      geom_tokens = true;
    } else {
      geom = encode_positions(q, plan, options.qp, options.predictor, coding);
      if (tokens && tokens->size() <= geom.size()) {
        geom = std::move(*tokens);
        geom_tokens = true;
      }
    }
    std::vector<QPoint> iq;
    for (int v : isolated) iq.push_back(qv[static_cast<std::size_t>(v)]);
    if (!iq.empty()) isol = encode_point_list(iq, options.qp, coding);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const auto back = quant.restore(qv[v]);
      for (std::size_t k = 0; k < 3; ++k) {
        const double e = std::fabs(back[k] - mesh.positions[v][k]);
        max_error = std::max(max_error, e);
        sum_sq += e * e;
        ++n_coords;
      }
    }
  }

  // Attributes, in G order with the positions' plan (parallelogram in their own domain).
  const std::vector<Attribute> attrs = attributes_of(mesh, options);
  std::vector<std::string> attr_payloads;
  for (const Attribute& a : attrs) {
    std::vector<QPoint> q(static_cast<std::size_t>(g_count), QPoint{0, 0, 0});
    double x[3] = {0, 0, 0};
    for (int g = 0; g < g_count; ++g)
      if (!dummy[static_cast<std::size_t>(g)]) {
        attribute_values(mesh, a, static_cast<std::size_t>(input_of[static_cast<std::size_t>(g)]), x);
        q[static_cast<std::size_t>(g)] = a.quantise(x);
      }
    GeometryPlan plan;
    plan.parallelogram = dec.parallelogram;
    plan.unusable = dummy;
    plan.same_as = num.same_as;
    const std::string main = encode_positions(q, plan, a.bits, Predictor::parallelogram, coding);
    std::vector<QPoint> iq;
    for (int v : isolated) {
      attribute_values(mesh, a, static_cast<std::size_t>(v), x);
      iq.push_back(a.quantise(x));
    }
    std::string payload;
    put_varint(payload, main.size());
    payload += main;
    if (!iq.empty()) payload += encode_point_list(iq, a.bits, coding);
    attr_payloads.push_back(std::move(payload));
  }

  // Header and sections (ebm(5)).
  std::uint16_t flags = 0;
  if (options.geometry) flags |= ebm_flags::geometry;
  if (options.qp == 0) flags |= ebm_flags::lossless;
  if (!stitch_pairs.empty()) flags |= ebm_flags::stitch;
  if (prepared.holes > 0) flags |= ebm_flags::holes;
  if (!trav.code.events.empty()) flags |= ebm_flags::events;
  if (!isolated.empty()) flags |= ebm_flags::isolated;
  if (conn->exclusion) flags |= ebm_flags::exclusion;
  std::vector<std::pair<const char*, std::string>> sections;  // in file order
  if (!stitch_pairs.empty()) {
    std::string s;
    int previous = 0;
    for (const auto& [copy, orig] : stitch_pairs) {  // copies ascend in G order
      put_varint(s, static_cast<std::uint64_t>(copy - previous));
      put_varint(s, static_cast<std::uint64_t>(orig));
      previous = copy;
    }
    sections.emplace_back("STCH", std::move(s));
  }
  if (!trav.code.events.empty()) {
    std::string s;
    std::uint32_t previous = 0;
    for (const HandleEvent& e : trav.code.events) {
      put_varint(s, e.source - previous);
      put_varint(s, e.source - e.split);
      put_u8(s, e.right_edge ? 1 : 0);
      previous = e.source;
    }
    sections.emplace_back("HNDL", std::move(s));
  }
  sections.emplace_back("CONN", conn->bytes);
  if (prepared.holes > 0) sections.emplace_back("HOLE", encode_hole_flags(dummy, valences(dec.triangles, g_count)));
  if (options.geometry) sections.emplace_back("GEOM", std::move(geom));
  // 1.x writes ISOL only when it is not empty; 2.x whenever positions of isolated
  // vertices exist, since its sections are implied by the flags.
  if (options.version == 1 ? !isol.empty() : options.geometry && !isolated.empty()) sections.emplace_back("ISOL", std::move(isol));
  for (std::size_t k = 0; k < attrs.size(); ++k) sections.emplace_back(attrs[k].tag(), std::move(attr_payloads[k]));

  std::string out(reinterpret_cast<const char*>(magic), 8);
  std::map<std::string, std::size_t> sizes;
  const std::uint64_t model = conn_mode == static_cast<int>(ConnMode::static_model) ? static_cast<std::uint64_t>(options.model_id) : 0u;
  if (options.version == 1) {
    std::string header;
    put_varint(header, static_cast<std::uint64_t>(num.count) + isolated.size());
    put_varint(header, out_faces);
    put_varint(header, static_cast<std::uint64_t>(trav.components));
    put_varint(header, prepared.holes);
    put_varint(header, stitch_pairs.size());
    put_varint(header, trav.code.events.size());
    put_varint(header, isolated.size());
    put_varint(header, symbols);
    put_varint(header, static_cast<std::uint64_t>(conn_mode));
    put_varint(header, model);
    put_varint(header, static_cast<std::uint64_t>(options.qp));
    put_varint(header, static_cast<std::uint64_t>(options.predictor));
    put_varint(header, attrs.size());
    for (float f : quant.box) put_f32(header, f);
    for (const Attribute& a : attrs) {
      put_u8(header, static_cast<unsigned>(a.kind));
      put_u8(header, static_cast<unsigned>(a.bits));
      for (float f : a.box) put_f32(header, f);
    }
    put_u8(out, 1);
    put_u8(out, 0);
    put_u16(out, flags);
    put_u32(out, static_cast<std::uint32_t>(header.size()));
    out += header;
    for (const auto& [tag, payload] : sections) {
      put_section(out, tag, payload);
      sizes[tag] = payload.size();
    }
    out += "END!";
  } else {
    // 2.0: what the flags say is absent or default costs nothing; the output counts are
    // what the decoder rebuilds; sections are implied by the flags, each with a varint
    // length except the last, which runs to the CRC.
    const bool several = trav.components > 1;
    put_u8(out, 2);
    put_u8(out, geom_tokens ? 1 : 0);  // 2.1: 2.0 with GEOM version 3
    put_u8(out, v2_flags_of(flags, several));
    put_u8(out, static_cast<unsigned>(conn_mode) | static_cast<unsigned>(options.predictor) << 2 |
                    static_cast<unsigned>(attrs.size()) << 4);
    put_varint(out, symbols);
    if (several) put_varint(out, static_cast<std::uint64_t>(trav.components));
    if (prepared.holes > 0) put_varint(out, prepared.holes);
    if (!stitch_pairs.empty()) put_varint(out, stitch_pairs.size());
    if (!trav.code.events.empty()) put_varint(out, trav.code.events.size());
    if (!isolated.empty()) put_varint(out, isolated.size());
    if (conn_mode == static_cast<int>(ConnMode::static_model)) put_u8(out, static_cast<unsigned>(model));
    if (options.geometry) {
      put_u8(out, static_cast<unsigned>(options.qp));
      for (float f : quant.box) put_f32(out, f);
    }
    for (const Attribute& a : attrs) {
      put_u8(out, static_cast<unsigned>(a.kind));
      put_u8(out, static_cast<unsigned>(a.bits));
      if (a.kind == 3)
        for (float f : a.box) put_f32(out, f);
    }
    for (std::size_t k = 0; k < sections.size(); ++k) {
      if (k + 1 < sections.size()) put_varint(out, sections[k].second.size());
      out += sections[k].second;
      sizes[sections[k].first] = sections[k].second.size();
    }
  }
  put_u32(out, crc32_of(out));

  if (stats) {
    stats->input_vertices = mesh.positions.size();
    stats->input_faces = mesh.triangles.size();
    stats->components = static_cast<std::size_t>(trav.components);
    stats->holes = prepared.holes;
    stats->stitch = prepared.copy_of.size();
    stats->events = trav.code.events.size();
    stats->isolated = prepared.isolated.size();
    stats->dropped_degenerate = prepared.dropped_degenerate;
    stats->symbols = symbols;
    stats->histogram = {};
    for (Symbol s : trav.code.clers) ++stats->histogram[static_cast<std::size_t>(s)];
    stats->genus_sum = static_cast<int>(trav.code.events.size() / 2);
    stats->conn_mode = conn_mode_name(conn_mode);
    stats->geom_version = !options.geometry ? 0 : options.version == 1 ? 1 : geom_tokens ? 3 : 2;
    stats->section_bytes = sizes;
    stats->total_bytes = out.size();
    stats->max_error = max_error;
    stats->rms_error = n_coords ? std::sqrt(sum_sq / static_cast<double>(n_coords)) : 0.0;
    stats->error_bound = options.qp == 0 ? 0.0 : static_cast<double>(quant.box[3]) / (2.0 * quant.steps());
  }
  return out;
}

namespace {

struct Parsed {
  EbmHeader header;
  std::map<std::string, std::string_view> sections;
  std::vector<Attribute> attributes;
};

void parse_attribute(Reader& hr, Parsed& p, std::uint64_t k, bool with_box) {
  Attribute a;
  a.kind = hr.u8();
  a.bits = hr.u8();
  if (with_box)
    for (float& f : a.box) f = hr.f32();
  a.components = a.kind == 3 ? 2 : 3;
  if (a.kind < 1 || a.kind > 3 || a.bits < 1 || a.bits > 30 || (a.kind == 2 && a.bits != 8))
    throw bad_input(".ebm header: attribute {} has kind {} and {} bits", k, a.kind, a.bits);
  for (const Attribute& b : p.attributes)
    if (b.kind == a.kind) throw bad_input(".ebm header: attribute kind {} twice", a.kind);
  if (!std::isfinite(a.box[0]) || !std::isfinite(a.box[1]) || !std::isfinite(a.box[2]) || !(a.box[2] >= 0))
    throw bad_input(".ebm header: attribute {} has a box that is not finite", k);
  p.attributes.push_back(a);
  p.header.attribute_names.push_back(a.name());
}

void check_crc(std::string_view bytes) {
  // The CRC covers everything before it: checked before any length is trusted.
  Reader tail(bytes.substr(bytes.size() - 4), ".ebm trailer");
  const std::uint32_t stored = tail.u32();
  const std::uint32_t computed = crc32_of(bytes.substr(0, bytes.size() - 4));
  if (stored != computed) throw bad_input("CRC mismatch (stored 0x{:08x}, computed 0x{:08x})", stored, computed);
}

// 1.x: u16 flags, a length-prefixed header record, tagged sections, END!, CRC.
void parse_v1(std::string_view bytes, Reader& r, Parsed& p) {
  EbmHeader& h = p.header;
  Reader tail(bytes.substr(bytes.size() - 8), ".ebm trailer");
  if (tail.bytes(4) != "END!") throw bad_input(".ebm stream is truncated (no END! trailer)");
  check_crc(bytes);

  h.flags = r.u16();
  const std::uint32_t header_len = r.u32();
  Reader hr(r.bytes(header_len), ".ebm header");
  h.vertices = hr.varint();
  h.faces = hr.varint();
  h.components = hr.varint();
  h.dummies = hr.varint();
  h.stitch = hr.varint();
  h.events = hr.varint();
  h.isolated = hr.varint();
  h.symbols = hr.varint();
  const auto small = [&](const char* what, std::uint64_t max) {
    const std::uint64_t v = hr.varint();
    if (v > max) throw bad_input(".ebm header: {} {} is out of range", what, v);
    return static_cast<int>(v);
  };
  h.conn_mode = small("connectivity mode", 2);
  h.model_id = small("model id", 255);
  h.qp = small("quantisation bits", 30);
  h.predictor = small("predictor", 3);
  h.attributes = hr.varint();
  if (h.attributes > 3) throw bad_input(".ebm header: {} attributes (at most normals, colours, texture coordinates)", h.attributes);
  for (float& f : h.box) f = hr.f32();
  for (std::uint64_t k = 0; k < h.attributes; ++k) parse_attribute(hr, p, k, true);
  // Later minor versions may append header fields: ignore them.
  while (r.left() > 8) {
    const std::string tag(r.bytes(4));
    const std::uint32_t len = r.u32();
    if (r.left() < static_cast<std::size_t>(len) + 8) throw bad_input(".ebm section {} is truncated", tag);
    const std::string_view payload = r.bytes(len);
    if (p.sections.count(tag)) throw bad_input(".ebm section {} occurs twice", tag);
    p.sections.emplace(tag, payload);
    h.section_bytes[tag] = len;
  }
  if (r.left() != 8) throw bad_input(".ebm stream is truncated");
}

// 2.x: u8 flags, u8 modes, varint counts the flags announce, and the sections they imply.
void parse_v2(std::string_view bytes, Parsed& p) {
  EbmHeader& h = p.header;
  check_crc(bytes);
  Reader r(bytes.substr(10, bytes.size() - 14), ".ebm stream");
  const unsigned f = r.u8();
  if (f & v2_bit::reserved) throw bad_input(".ebm header: reserved flag bit 7 is set");
  h.flags = 0;
  for (const auto& [v1, v2] : v2_flag_map)
    if (f & v2) h.flags = static_cast<std::uint16_t>(h.flags | v1);
  const unsigned modes = r.u8();
  h.conn_mode = static_cast<int>(modes & 3u);
  h.predictor = static_cast<int>((modes >> 2) & 3u);
  h.attributes = (modes >> 4) & 3u;
  if (h.conn_mode > 2 || (modes >> 6) != 0) throw bad_input(".ebm header: modes byte 0x{:02x} is out of range", modes);
  h.symbols = r.varint();
  h.components = h.symbols > 0 ? 1 : 0;
  if (f & v2_bit::several) {
    h.components = r.varint();
    if (h.components < 2) throw bad_input(".ebm header: the several-components flag with {} components", h.components);
  }
  const auto count = [&](unsigned bit, const char* what) {
    if (!(f & bit)) return std::uint64_t{0};
    const std::uint64_t v = r.varint();
    if (v == 0) throw bad_input(".ebm header: the {} flag with no {}", what, what);
    return v;
  };
  h.dummies = count(v2_bit::holes, "holes");
  h.stitch = count(v2_bit::stitch, "stitch");
  h.events = count(v2_bit::events, "events");
  h.isolated = count(v2_bit::isolated, "isolated");
  if (h.conn_mode == static_cast<int>(ConnMode::static_model)) h.model_id = r.u8();
  if (f & v2_bit::geometry) {
    h.qp = r.u8();
    if (h.qp > 30) throw bad_input(".ebm header: quantisation bits {} is out of range", h.qp);
    if (h.qp == 0) h.flags = static_cast<std::uint16_t>(h.flags | ebm_flags::lossless);
    for (float& x : h.box) x = r.f32();
  }
  for (std::uint64_t k = 0; k < h.attributes; ++k) {
    // Only texture coordinates have a box of their own; peek at the kind.
    Reader peek = r;
    const unsigned kind = peek.u8();
    parse_attribute(r, p, k, kind == 3);
  }
  std::vector<const char*> tags;
  if (h.stitch) tags.push_back("STCH");
  if (h.events) tags.push_back("HNDL");
  tags.push_back("CONN");
  if (h.dummies) tags.push_back("HOLE");
  if (f & v2_bit::geometry) tags.push_back("GEOM");
  if ((f & v2_bit::geometry) && h.isolated) tags.push_back("ISOL");
  for (const Attribute& a : p.attributes) tags.push_back(a.tag());
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const std::uint64_t len = k + 1 < tags.size() ? r.varint() : r.left();
    if (len > r.left()) throw bad_input(".ebm section {} is truncated", tags[k]);
    p.sections.emplace(tags[k], r.bytes(static_cast<std::size_t>(len)));
    h.section_bytes[tags[k]] = static_cast<std::size_t>(len);
  }
}

Parsed parse(std::string_view bytes) {
  if (!is_ebm(bytes)) throw bad_input("not an .ebm stream (bad magic)");
  if (bytes.size() < 8 + 2 + 4) throw bad_input(".ebm stream is truncated ({} bytes)", bytes.size());
  Parsed p;
  EbmHeader& h = p.header;
  h.total_bytes = bytes.size();
  Reader r(bytes.substr(8), ".ebm stream");
  h.major = r.u8();
  h.minor = r.u8();
  if (h.major == 1) {
    if (bytes.size() < 8 + 2 + 2 + 4 + 8) throw bad_input(".ebm stream is truncated ({} bytes)", bytes.size());
    parse_v1(bytes, r, p);
  } else if (h.major == 2) {
    if (h.minor > 1) throw bad_input(".ebm version 2.{} is not supported (this decoder reads 1.x, 2.0 and 2.1)", h.minor);
    parse_v2(bytes, p);
    // 2.1 differs from 2.0 only in GEOM (version 3), which codes quantised positions.
    if (h.minor == 1 && (!(h.flags & ebm_flags::geometry) || h.qp == 0))
      throw bad_input(".ebm 2.1 holds quantised positions (GEOM version 3), this stream has {}",
                      (h.flags & ebm_flags::geometry) ? "lossless ones" : "none");
  } else {
    throw bad_input(".ebm major version {} is not supported (this decoder reads versions 1 and 2)", h.major);
  }

  // Counts against what the bytes can hold, before anything is allocated from them.
  const auto bytes_of = [&](const char* tag) {
    const auto it = p.sections.find(tag);
    return it == p.sections.end() ? std::size_t{0} : it->second.size();
  };
  const std::size_t conn_bytes = bytes_of("CONN");
  if (!p.sections.count("CONN")) throw bad_input(".ebm stream has no CONN section");
  // Raw symbols take at least a bit each; the entropy coders can code a very regular mesh
  // in 1e-4 bits per symbol (the adaptive counts saturate at 65504 : 4), so their bound is
  // loose, and the decoder's memory grows with what it decodes, not with this count.
  const std::uint64_t symbol_bound =
      h.conn_mode == 0 ? 8 * (conn_bytes + 4) + 2 : (std::uint64_t{1} << 17) * (conn_bytes + 16);
  if (h.symbols > max_elements || h.symbols > symbol_bound)
    throw bad_input(".ebm header: {} symbols cannot come from {} connectivity bytes", h.symbols, conn_bytes);
  if (h.components > h.symbols + 1 || (h.symbols > 0 && h.components == 0))
    throw bad_input(".ebm header: {} components for {} symbols", h.components, h.symbols);
  if (h.events > h.symbols || h.events * 3 > bytes_of("HNDL"))
    throw bad_input(".ebm header: {} handle events in {} bytes", h.events, bytes_of("HNDL"));
  if (h.stitch > 3 * (h.symbols + h.components) || h.stitch * 2 > bytes_of("STCH"))
    throw bad_input(".ebm header: {} stitch pairs in {} bytes", h.stitch, bytes_of("STCH"));
  if (h.dummies > h.symbols + 3 * h.components)
    throw bad_input(".ebm header: {} holes for {} symbols", h.dummies, h.symbols);
  if (h.isolated > max_elements || h.isolated > 256 * (bytes_of("ISOL") + 16))
    throw bad_input(".ebm header: {} isolated vertices in {} bytes", h.isolated, bytes_of("ISOL"));
  if (h.vertices > max_elements || h.faces > max_elements) throw bad_input(".ebm header: counts out of range");
  if ((h.flags & ebm_flags::geometry) && (!std::isfinite(h.box[0]) || !std::isfinite(h.box[1]) ||
                                          !std::isfinite(h.box[2]) || !(h.box[3] >= 0) || !std::isfinite(h.box[3])))
    throw bad_input(".ebm header: the quantisation box is not finite");
  if (h.conn_mode == 1 && static_model_table(h.model_id) == nullptr)
    throw bad_input(".ebm header: unknown static model {}", h.model_id);
  return p;
}

}  // namespace

EbmHeader read_ebm_header(std::string_view bytes) {
  EbmHeader h = parse(bytes).header;
  if (h.major >= 2) decode_ebm(bytes, true, false, &h);  // 2.x does not store the output counts
  return h;
}

MeshSoup decode_ebm(std::string_view bytes, bool stitch, bool verify, EbmHeader* header_out) {
  const Parsed p = parse(bytes);
  const EbmHeader& h = p.header;
  const bool v1 = h.major == 1;
  const ResidualCoding coding = v1 ? ResidualCoding::tree_v1 : ResidualCoding::distance_v2;  // ISOL, attributes
  const ResidualCoding geom_coding = h.major == 2 && h.minor == 1 ? ResidualCoding::tokens_v3 : coding;
  const auto section = [&](const char* tag) {
    const auto it = p.sections.find(tag);
    return it == p.sections.end() ? std::string_view{} : it->second;
  };

  std::vector<HandleEvent> events;
  {
    Reader r(section("HNDL"), "HNDL section");
    std::uint64_t source = 0;
    for (std::uint64_t k = 0; k < h.events; ++k) {
      source += r.varint();
      const std::uint64_t back = r.varint();
      const unsigned side = r.u8();
      if (source >= h.symbols || back == 0 || back > source || side > 1)
        throw bad_input("HNDL section: event {} is out of range", k);
      events.push_back({static_cast<std::uint32_t>(source - back), static_cast<std::uint32_t>(source), side == 1});
    }
  }
  DecodedConnectivity dec;
  if (h.symbols == 0) {
    if (h.components != 0) throw bad_input(".ebm header: components without symbols");
  } else {
    dec = decode_connectivity(section("CONN"), static_cast<std::size_t>(h.symbols), std::move(events),
                              static_cast<ConnMode>(h.conn_mode), h.model_id, (h.flags & ebm_flags::exclusion) != 0,
                              verify, static_cast<Predictor>(h.predictor) == Predictor::multi, h.dummies > 0);
  }
  if (static_cast<std::uint64_t>(dec.components) != h.components)
    throw bad_input("connectivity has {} components, the header says {}", dec.components, h.components);
  const int g_count = dec.vertex_count;

  std::vector<char> dummy(static_cast<std::size_t>(g_count), 0);
  Numbering num;
  bool numbered = false;  // num made, and dec.triangles made the output faces, below
  if (h.dummies > 0) {
    // The decoder's counts: valences(dec.triangles, g_count) without a pass over the faces.
    dummy = decode_hole_flags(section("HOLE"), dec.valence);
    const auto n = static_cast<std::uint64_t>(std::count(dummy.begin(), dummy.end(), 1));
    if (n != h.dummies) throw bad_input("HOLE section marks {} dummy vertices, the header says {}", n, h.dummies);
    // A dummy's triangles form one fan around it: no two dummies share a triangle.
    if (h.stitch == 0 && static_cast<Predictor>(h.predictor) != Predictor::multi) {
      // Without stitch pairs the numbering depends on the dummies alone, so it is made
      // here, and the output faces (those without a dummy, renumbered) in the same pass as
      // the check, in place: one pass over the faces instead of two, and no second array
      // (docs/ebcode.md §6). Only the multi-way predictor reads the G faces later.
      num = number_vertices(dummy, {}, stitch, false, true);
      numbered = true;
      Triangle* face = dec.triangles.data();  // never ahead of the face being read
      const int* output = num.output.data();
      const char* d = dummy.data();
      for (const Triangle& t : dec.triangles) {
        const int on_dummies = d[t[0]] + d[t[1]] + d[t[2]];
        if (on_dummies != 0) {
          if (on_dummies > 1) throw bad_input("HOLE section: two dummy vertices share a triangle");
          continue;
        }
        *face++ = {output[t[0]], output[t[1]], output[t[2]]};
      }
      dec.triangles.resize(static_cast<std::size_t>(face - dec.triangles.data()));
    } else {
      for (const Triangle& t : dec.triangles)
        if (dummy[static_cast<std::size_t>(t[0])] + dummy[static_cast<std::size_t>(t[1])] + dummy[static_cast<std::size_t>(t[2])] > 1)
          throw bad_input("HOLE section: two dummy vertices share a triangle");
    }
  }
  std::vector<int> original_of(static_cast<std::size_t>(g_count), -1);
  {
    Reader r(section("STCH"), "STCH section");
    std::uint64_t copy = 0;
    for (std::uint64_t k = 0; k < h.stitch; ++k) {
      const std::uint64_t step = r.varint();
      if (k > 0 && step == 0) throw bad_input("STCH section: pair {} repeats a copy", k);
      copy += step;
      const std::uint64_t orig = r.varint();
      if (copy >= static_cast<std::uint64_t>(g_count) || orig >= static_cast<std::uint64_t>(g_count) || copy == orig)
        throw bad_input("STCH section: pair {} is out of range", k);
      if (dummy[static_cast<std::size_t>(copy)] || dummy[static_cast<std::size_t>(orig)])
        throw bad_input("STCH section: pair {} names a dummy vertex", k);
      original_of[static_cast<std::size_t>(copy)] = static_cast<int>(orig);
    }
    for (int g = 0; g < g_count && h.stitch > 0; ++g) {  // (without pairs there are no copies)
      const int o = original_of[static_cast<std::size_t>(g)];
      if (o >= 0 && original_of[static_cast<std::size_t>(o)] >= 0) throw bad_input("STCH section: a copy of a copy");
    }
  }
  const bool plain = h.dummies == 0 && h.stitch == 0;  // output vertex g is G vertex g
  if (!numbered) num = number_vertices(dummy, original_of, stitch, plain, h.stitch == 0);
  const std::uint64_t expected_vertices = h.vertices;
  const std::uint64_t stitched_count =
      static_cast<std::uint64_t>(stitch ? num.count : number_vertices(dummy, original_of, true, plain, h.stitch == 0).count);
  if (v1 && stitched_count + h.isolated != expected_vertices)
    throw bad_input("connectivity gives {} vertices, the header says {}", stitched_count + h.isolated, expected_vertices);

  MeshSoup out;
  const std::size_t output_count = static_cast<std::size_t>(num.count) + static_cast<std::size_t>(h.isolated);
  // One plan for the positions and every attribute (geometry_plan's fields, moved here
  // rather than copied: the decoder needs them for nothing else).
  GeometryPlan plan;
  plan.parallelogram = std::move(dec.parallelogram);
  plan.unusable = dummy;
  plan.same_as = std::move(num.same_as);
  plan.triangles = &dec.triangles;
  plan.opposite = &dec.opposite;
  if (h.flags & ebm_flags::geometry) {
    if (!p.sections.count("GEOM")) throw bad_input(".ebm stream has no GEOM section");
    Quantiser quant;
    quant.bits = h.qp;
    quant.box = h.box;
    const std::vector<QPoint> q =
        decode_positions(section("GEOM"), plan, h.qp, static_cast<Predictor>(h.predictor), geom_coding);
    if (plain && quant.bits != 0) {
      // Output vertex g is G vertex g: appended in order rather than zeroed and then
      // overwritten (the zeros were 1 % of the decode; docs/ebcode.md §6). The same
      // arithmetic as Quantiser::restore, its constants in locals.
      const double lo0 = quant.box[0], lo1 = quant.box[1], lo2 = quant.box[2], extent = quant.box[3], steps = quant.steps();
      std::vector<std::array<double, 3>> positions;
      positions.reserve(output_count);
      for (std::size_t g = 0; g < static_cast<std::size_t>(g_count); ++g) {
        const QPoint& x = q[g];
        positions.push_back({lo0 + static_cast<double>(x[0]) * extent / steps, lo1 + static_cast<double>(x[1]) * extent / steps,
                             lo2 + static_cast<double>(x[2]) * extent / steps});
      }
      positions.resize(output_count);  // the isolated vertices' places, written below
      out.positions = std::move(positions);
    } else {
      out.positions.assign(output_count, {0.0, 0.0, 0.0});
      for (int g = 0; g < g_count; ++g)
        if (num.output[static_cast<std::size_t>(g)] >= 0)
          out.positions[static_cast<std::size_t>(num.output[static_cast<std::size_t>(g)])] = quant.restore(q[static_cast<std::size_t>(g)]);
    }
    if (h.isolated > 0) {
      const std::vector<QPoint> iq = decode_point_list(section("ISOL"), static_cast<std::size_t>(h.isolated), h.qp, coding);
      for (std::size_t k = 0; k < iq.size(); ++k) out.positions[static_cast<std::size_t>(num.count) + k] = quant.restore(iq[k]);
    }
  } else {
    out.positions.assign(output_count, {0.0, 0.0, 0.0});
  }
  for (const Attribute& a : p.attributes) {
    if (!p.sections.count(a.tag())) throw bad_input(".ebm stream has no {} section", a.tag());
    Reader r(section(a.tag()), a.tag());
    const std::uint64_t main_len = r.varint();
    if (main_len > r.left()) throw bad_input("{} section is truncated", a.tag());
    const std::string_view main = r.bytes(static_cast<std::size_t>(main_len));
    const std::string_view rest = r.bytes(r.left());
    const std::vector<QPoint> q = decode_positions(main, plan, a.bits, Predictor::parallelogram, coding);
    const std::vector<QPoint> iq = h.isolated > 0 ? decode_point_list(rest, static_cast<std::size_t>(h.isolated), a.bits, coding)
                                                   : std::vector<QPoint>{};
    const std::size_t n = output_count;
    const auto store = [&](std::size_t v, const QPoint& x) {
      if (a.kind == 1) {
        out.normals[v] = {a.restore(x, 0), a.restore(x, 1), a.restore(x, 2)};
      } else if (a.kind == 2) {
        out.colors[v] = {static_cast<std::uint8_t>(x[0]), static_cast<std::uint8_t>(x[1]), static_cast<std::uint8_t>(x[2])};
      } else {
        out.texcoords[v] = {a.restore(x, 0), a.restore(x, 1)};
      }
    };
    if (a.kind == 1) out.normals.assign(n, {0.0, 0.0, 0.0});
    if (a.kind == 2) out.colors.assign(n, {0, 0, 0});
    if (a.kind == 3) out.texcoords.assign(n, {0.0, 0.0});
    for (int g = 0; g < g_count; ++g)
      if (num.output[static_cast<std::size_t>(g)] >= 0)
        store(static_cast<std::size_t>(num.output[static_cast<std::size_t>(g)]), q[static_cast<std::size_t>(g)]);
    for (std::size_t k = 0; k < iq.size(); ++k) store(static_cast<std::size_t>(num.count) + k, iq[k]);
  }
  if (plain) {
    out.triangles = std::move(dec.triangles);  // nothing to drop or renumber
  } else if (numbered) {
    out.triangles = std::move(dec.triangles);  // compacted and renumbered with the dummy check
  } else {
    // Written through a pointer (push_back's capacity test per face was a tenth of this).
    out.triangles.resize(dec.triangles.size());
    Triangle* face = out.triangles.data();
    const int* output = num.output.data();
    for (const Triangle& t : dec.triangles) {
      if (dummy[static_cast<std::size_t>(t[0])] || dummy[static_cast<std::size_t>(t[1])] || dummy[static_cast<std::size_t>(t[2])]) continue;
      *face++ = {output[t[0]], output[t[1]], output[t[2]]};
    }
    out.triangles.resize(static_cast<std::size_t>(face - out.triangles.data()));
  }
  if (v1 && out.triangles.size() != h.faces)
    throw bad_input("connectivity gives {} faces, the header says {}", out.triangles.size(), h.faces);
  if (header_out) {
    *header_out = h;
    header_out->vertices = stitched_count + h.isolated;  // 1.x: equal to the stored counts
    header_out->faces = out.triangles.size();
  }
  return out;
}

}  // namespace fest::edgebreaker
