#include "terrainlod/tile_codec.hpp"

#include <algorithm>
#include <cstring>
#include <map>

#include "core/error.hpp"
#include "terrainlod/bitstream.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {
namespace {

constexpr char kMagic[4] = {'F', 'T', 'L', 'T'};
constexpr std::uint8_t kVersion = 1;

// Position of lattice point (X, Y) on the border loop (counter-clockwise from the
// south-west corner), or -1 inside.
int border_index(int X, int Y, int n) {
  if (Y == 0 && X < n) return X;
  if (X == n && Y < n) return n + Y;
  if (Y == n && X > 0) return 2 * n + (n - X);
  if (X == 0 && Y > 0) return 3 * n + (n - Y);
  return -1;
}

std::pair<int, int> border_point(int index, int n) {
  if (index < n) return {index, 0};
  if (index < 2 * n) return {n, index - n};
  if (index < 3 * n) return {n - (index - 2 * n), n};
  return {0, n - (index - 3 * n)};
}

// Low end of a side (where its fine points start counting).
std::pair<int, int> side_start(int side, int n) {
  switch (side) {
    case kEast: return {n, 0};
    case kNorth: return {0, n};
    default: return {0, 0};
  }
}

template <typename T>
void put_le(std::string& s, T v) {
  for (std::size_t b = 0; b < sizeof(T); ++b) s.push_back(static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * b)) & 0xff));
}
void put_f32(std::string& s, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  put_le(s, u);
}
template <typename T>
T get_le(std::string_view s, std::size_t at) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < sizeof(T); ++b) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(s[at + b])) << (8 * b);
  return static_cast<T>(v);
}
float get_f32(std::string_view s, std::size_t at) {
  const std::uint32_t u = get_le<std::uint32_t>(s, at);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// Greedy strips over the triangle adjacency: each emitted as (p0, p1, p2), continued
// across (p1, p2) if that neighbour is free, else across (p0, p2), else restarted.
struct StripTriangle {
  bool restart;
  int side;  // 0: shares (p1, p2); 1: shares (p0, p2)
  std::array<int, 3> v;
};

std::vector<StripTriangle> strip_order(const std::vector<std::array<int, 3>>& tris) {
  // Directed edge -> triangle in an open-addressing table (one allocation, no hash nodes);
  // a repeated key (only in a non-manifold input) keeps the last triangle, as map
  // assignment did.
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
  std::size_t size = 16;
  while (size < 6 * tris.size()) size *= 2;  // load <= 1/2
  constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::vector<std::pair<std::uint64_t, int>> table(size, {kEmpty, -1});
  auto slot = [&](std::uint64_t k) {
    std::size_t i = static_cast<std::size_t>((k * 0x9e3779b97f4a7c15ull) >> 20) & (size - 1);
    while (table[i].first != kEmpty && table[i].first != k) i = (i + 1) & (size - 1);
    return i;
  };
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint64_t k = key(tris[t][e], tris[t][(e + 1) % 3]);
      table[slot(k)] = {k, static_cast<int>(t)};
    }
  std::vector<std::uint8_t> used(tris.size(), 0);
  auto find_edge = [&](std::uint64_t k) { return table[slot(k)].second; };  // -1 at an empty slot
  // The free triangle across edge {a, b} (the neighbour holds it as b -> a), or -1.
  auto across = [&](int a, int b) {
    for (auto k : {key(b, a), key(a, b)}) {
      const int t = find_edge(k);
      if (t >= 0 && !used[static_cast<std::size_t>(t)]) return t;
    }
    return -1;
  };
  auto third = [&](int t, int a, int b) {
    for (int v : tris[static_cast<std::size_t>(t)])
      if (v != a && v != b) return v;
    return -1;
  };
  std::vector<StripTriangle> out;
  for (std::size_t s = 0; s < tris.size(); ++s) {
    if (used[s]) continue;
    used[s] = 1;
    std::array<int, 3> p = tris[s];
    for (int r = 0; r < 3; ++r) {  // a rotation whose (p1, p2) edge leads on, if any
      if (across(p[1], p[2]) >= 0) break;
      p = {p[1], p[2], p[0]};
    }
    out.push_back({true, 0, p});
    for (;;) {
      int t = across(p[1], p[2]), side = 0;
      if (t < 0) t = across(p[0], p[2]), side = 1;
      if (t < 0) break;
      used[static_cast<std::size_t>(t)] = 1;
      p = side == 0 ? std::array<int, 3>{p[1], p[2], third(t, p[1], p[2])}
                    : std::array<int, 3>{p[0], p[2], third(t, p[0], p[2])};
      out.push_back({false, side, p});
    }
  }
  return out;
}

// The edges of the triangles coded so far: a reused vertex is usually a neighbour of the
// vertices it joins, so it is coded as an index among their known neighbours.
class EdgeGraph {
 public:
  // Up to kInline neighbours of a vertex sit in its own slot, the rest (a coarse tile's
  // fan) in an overflow list: a vector per vertex made allocation most of the decoding
  // time, and a linked pool made it pointer chasing.
  explicit EdgeGraph(int vertices) : slots_(static_cast<std::size_t>(vertices)) {}
  void add_triangle(const std::array<int, 3>& t) {
    for (int e = 0; e < 3; ++e) {
      link(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]);
      link(t[static_cast<std::size_t>((e + 1) % 3)], t[static_cast<std::size_t>(e)]);
    }
  }
  // A strip's next triangle (a, b, apex): its edge (a, b) is the previous triangle's.
  void add_strip_triangle(const std::array<int, 3>& t) {
    for (int e = 0; e < 2; ++e) {
      link(t[2], t[static_cast<std::size_t>(e)]);
      link(t[static_cast<std::size_t>(e)], t[2]);
    }
  }
  // Neighbours of the context vertices, without them, ascending.
  // The result lives in a buffer of the graph, valid until the next call.
  const std::vector<int>& candidates(std::initializer_list<int> context) const {
    std::vector<int>& out = scratch_;
    out.clear();
    for (int c : context) {
      const Slot& s = slots_[static_cast<std::size_t>(c)];
      auto take = [&](int v) {
        if (std::find(context.begin(), context.end(), v) == context.end()) out.push_back(v);
      };
      for (int i = 0; i < std::min<int>(s.count, kInline); ++i) take(s.inline_[i]);
      if (s.overflow >= 0)
        for (int v : overflow_[static_cast<std::size_t>(s.overflow)]) take(v);
    }
    // Insertion sort: a handful of values.
    for (std::size_t i = 1; i < out.size(); ++i)
      for (std::size_t j = i; j > 0 && out[j - 1] > out[j]; --j) std::swap(out[j - 1], out[j]);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

 private:
  static constexpr int kInline = 8;
  struct Slot {
    int inline_[kInline];
    int count = 0;
    int overflow = -1;  // index into overflow_ once count exceeds kInline
  };
  void link(int a, int b) {
    Slot& s = slots_[static_cast<std::size_t>(a)];
    for (int i = 0; i < std::min<int>(s.count, kInline); ++i)
      if (s.inline_[i] == b) return;
    if (s.overflow >= 0) {
      auto& more = overflow_[static_cast<std::size_t>(s.overflow)];
      if (std::find(more.begin(), more.end(), b) != more.end()) return;
    }
    if (s.count < kInline) {
      s.inline_[s.count] = b;
    } else {
      if (s.overflow < 0) {
        s.overflow = static_cast<int>(overflow_.size());
        overflow_.emplace_back();
      }
      overflow_[static_cast<std::size_t>(s.overflow)].push_back(b);
    }
    ++s.count;
  }
  std::vector<Slot> slots_;
  std::vector<std::vector<int>> overflow_;
  mutable std::vector<int> scratch_;
};

// Where a new interior vertex is expected: a + b - c (parallelogram), a alone (c < 0), or
// nothing (a < 0: the tile's centre and the corner's height).
struct Predictor {
  int a = -1, b = -1, c = -1;
};

// Height of a vertex on the interior lattice (border heights are finest-lattice G).
std::int64_t interior_code(const TileVertex& v, int n, int k) {
  const bool border = v.X == 0 || v.Y == 0 || v.X == n || v.Y == n;
  return border ? (v.code >> k) : v.code;
}

TileVertex predict(const std::vector<TileVertex>& vs, const Predictor& p, int n, int k, std::int64_t g0) {
  TileVertex g{n / 2, n / 2, g0 >> k};
  if (p.a >= 0 && p.c >= 0) {
    const TileVertex &a = vs[static_cast<std::size_t>(p.a)], &b = vs[static_cast<std::size_t>(p.b)],
                     &c = vs[static_cast<std::size_t>(p.c)];
    g = {a.X + b.X - c.X, a.Y + b.Y - c.Y, interior_code(a, n, k) + interior_code(b, n, k) - interior_code(c, n, k)};
  } else if (p.a >= 0) {
    const TileVertex& a = vs[static_cast<std::size_t>(p.a)];
    g = {a.X, a.Y, interior_code(a, n, k)};
  }
  g.X = std::clamp(g.X, 1, n - 1);
  g.Y = std::clamp(g.Y, 1, n - 1);
  return g;
}

}  // namespace

std::string encode_tile(const Tile& tile, TileSizes* sizes) {
  const int n = tile.n();
  const int nb = 4 * n;
  // New numbering: border loop first, then interior vertices by first use in the strips.
  std::vector<int> renum(tile.vertices.size(), -1);
  std::vector<std::uint8_t> seen_border(static_cast<std::size_t>(nb), 0);
  for (std::size_t v = 0; v < tile.vertices.size(); ++v) {
    const int b = border_index(tile.vertices[v].X, tile.vertices[v].Y, n);
    if (b < 0) continue;
    if (seen_border[static_cast<std::size_t>(b)]) throw runtime_failure("tile encoder: border point repeated");
    seen_border[static_cast<std::size_t>(b)] = 1;
    renum[v] = b;
  }
  if (std::count(seen_border.begin(), seen_border.end(), 1) != nb)
    throw runtime_failure("tile encoder: border lattice incomplete");
  const std::vector<StripTriangle> strips = strip_order(tile.triangles);
  const int total = static_cast<int>(tile.vertices.size());
  // First pass: walk the strips in the decoder's terms (new ids), noting every reference
  // and, for each new interior vertex, its predictor (parallelogram across the shared
  // edge when the strip continues, else the last referenced vertex).
  std::vector<int> interior;   // old ids in new order
  std::vector<Predictor> preds;
  struct Ref {
    bool fresh = false;
    int candidate = -1, candidates = 0;  // index among the context's neighbours
    std::uint64_t distance = 0;          // else: introduced this many vertices before the last
  };
  std::vector<Ref> refs;
  EdgeGraph graph(total);
  int next = nb, last = -1;
  auto ref = [&](int old, Predictor pred, std::initializer_list<int> context) {
    int& r = renum[static_cast<std::size_t>(old)];
    Ref x;
    if (r < 0) {
      r = next++;
      interior.push_back(old);
      preds.push_back(pred.a < 0 ? Predictor{last, -1, -1} : pred);
      x.fresh = true;
    } else {
      const std::vector<int>& cand = graph.candidates(context);
      const auto it = std::lower_bound(cand.begin(), cand.end(), r);
      x.candidates = static_cast<int>(cand.size());
      if (it != cand.end() && *it == r) x.candidate = static_cast<int>(it - cand.begin());
      else x.distance = static_cast<std::uint64_t>(next - 1 - r);
    }
    refs.push_back(x);
    last = r;
    return r;
  };
  std::array<int, 3> prev{};
  for (const auto& st : strips) {
    if (st.restart) {
      const int a0 = ref(st.v[0], {}, {});
      const int a1 = ref(st.v[1], {}, {a0});
      const int a2 = ref(st.v[2], {}, {a0, a1});
      prev = {a0, a1, a2};
    } else {
      const Predictor pred = st.side == 0 ? Predictor{prev[1], prev[2], prev[0]} : Predictor{prev[0], prev[2], prev[1]};
      const int x = st.side == 0 ? ref(st.v[2], pred, {prev[1], prev[2]}) : ref(st.v[2], pred, {prev[0], prev[2]});
      prev = st.side == 0 ? std::array<int, 3>{prev[1], prev[2], x} : std::array<int, 3>{prev[0], prev[2], x};
    }
    if (st.restart) graph.add_triangle(prev);
    else graph.add_strip_triangle(prev);
  }
  if (next != total) throw runtime_failure("tile encoder: {} vertices unused by triangles", total - next);
  std::vector<std::uint64_t> distances;
  for (const auto& r : refs)
    if (!r.fresh && r.candidate < 0) distances.push_back(r.distance);
  BitWriter conn;
  const int k_ref = best_rice_k(distances);
  conn.put(static_cast<std::uint64_t>(k_ref), 6);
  {
    std::size_t r = 0;
    auto put_ref = [&]() {
      const Ref& x = refs[r++];
      conn.put(x.fresh ? 1 : 0, 1);
      if (x.fresh) return;
      if (x.candidates > 0) conn.put(x.candidate >= 0 ? 1 : 0, 1);
      if (x.candidate >= 0) conn.put(static_cast<std::uint64_t>(x.candidate), bit_width(static_cast<std::uint64_t>(x.candidates - 1)));
      else conn.put_rice(x.distance, k_ref);
    };
    for (const auto& st : strips) {
      conn.put(st.restart ? 0 : 1, 1);
      if (st.restart) {
        put_ref(), put_ref(), put_ref();
      } else {
        conn.put(static_cast<std::uint64_t>(st.side), 1);
        put_ref();
      }
    }
  }

  // Vertex section: positions and heights in new order (border loop, then interior).
  std::vector<TileVertex> ordered(static_cast<std::size_t>(total));
  for (std::size_t v = 0; v < tile.vertices.size(); ++v) ordered[static_cast<std::size_t>(renum[v])] = tile.vertices[v];
  std::vector<std::int64_t> border_G(static_cast<std::size_t>(nb));
  for (int b = 0; b < nb; ++b) border_G[static_cast<std::size_t>(b)] = ordered[static_cast<std::size_t>(b)].code;
  const std::int64_t g0 = border_G[0];
  std::vector<std::uint64_t> border_res, xy_res, h_res;
  for (int b = 1; b < nb; ++b) border_res.push_back(zigzag(border_G[static_cast<std::size_t>(b)] - border_G[static_cast<std::size_t>(b) - 1]));
  for (std::size_t i = 0; i < interior.size(); ++i) {
    const TileVertex& v = ordered[static_cast<std::size_t>(nb) + i];
    const TileVertex guess = predict(ordered, preds[i], n, tile.k, g0);
    xy_res.push_back(zigzag(v.X - guess.X));
    xy_res.push_back(zigzag(v.Y - guess.Y));
    h_res.push_back(zigzag(v.code - guess.code));
  }
  BitWriter vert;
  const int k_b = best_rice_k(border_res), k_xy = best_rice_k(xy_res), k_h = best_rice_k(h_res);
  vert.put(static_cast<std::uint64_t>(k_b), 6);
  vert.put(static_cast<std::uint64_t>(k_xy), 6);
  vert.put(static_cast<std::uint64_t>(k_h), 6);
  for (auto u : border_res) vert.put_rice(u, k_b);
  for (std::size_t i = 0; i < interior.size(); ++i) {
    vert.put_rice(xy_res[2 * i], k_xy);
    vert.put_rice(xy_res[2 * i + 1], k_xy);
    vert.put_rice(h_res[i], k_h);
  }

  // Refinement section.
  BitWriter refine;
  for (int s = kWest; s <= kNorth; ++s) {
    if (!(tile.refinable & (1u << s))) continue;
    const auto [sx, sy] = side_start(s, n);
    const std::int64_t start = border_G[static_cast<std::size_t>(border_index(sx, sy, n))];
    std::vector<std::uint64_t> res;
    std::int64_t p = start;
    for (std::int64_t g : tile.fine_G[s]) {
      res.push_back(zigzag(g - p));
      p = g;
    }
    const int k = best_rice_k(res);
    refine.put(static_cast<std::uint64_t>(k), 6);
    for (auto u : res) refine.put_rice(u, k);
  }

  const std::string vbytes = vert.take(), cbytes = conn.take(), rbytes = refine.take();
  std::string out(kMagic, 4);
  put_le<std::uint8_t>(out, kVersion);
  put_le<std::uint8_t>(out, static_cast<std::uint8_t>(tile.id.level));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(tile.id.x));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(tile.id.y));
  put_le<std::uint8_t>(out, static_cast<std::uint8_t>(tile.lattice_bits));
  put_le<std::uint8_t>(out, static_cast<std::uint8_t>(tile.fine_bits));
  put_le<std::uint8_t>(out, static_cast<std::uint8_t>(tile.k));
  put_le<std::uint8_t>(out, static_cast<std::uint8_t>(tile.refinable));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(interior.size()));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(tile.triangles.size()));
  put_le<std::int64_t>(out, g0);
  put_f32(out, tile.eps);
  put_f32(out, tile.err);
  put_f32(out, tile.z_min);
  put_f32(out, tile.z_max);
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(vbytes.size()));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(cbytes.size()));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(rbytes.size()));
  if (out.size() != kTileHeaderBytes) throw runtime_failure("tile header is {} bytes", out.size());
  if (sizes) *sizes = {out.size(), vbytes.size(), cbytes.size(), rbytes.size()};
  return out + vbytes + cbytes + rbytes;
}

Tile decode_tile(std::string_view bytes) {
  if (bytes.size() < kTileHeaderBytes) throw bad_input("tile is truncated: {} of at least {} header bytes", bytes.size(), kTileHeaderBytes);
  if (bytes.substr(0, 4) != std::string_view(kMagic, 4)) throw bad_input("not a terrainlod tile (bad magic)");
  if (get_le<std::uint8_t>(bytes, 4) != kVersion)
    throw bad_input("terrainlod tile version {} is not supported (this is version {})", get_le<std::uint8_t>(bytes, 4), kVersion);
  Tile tile;
  tile.id.level = get_le<std::uint8_t>(bytes, 5);
  tile.id.x = static_cast<int>(get_le<std::uint32_t>(bytes, 6));
  tile.id.y = static_cast<int>(get_le<std::uint32_t>(bytes, 10));
  tile.lattice_bits = get_le<std::uint8_t>(bytes, 14);
  tile.fine_bits = get_le<std::uint8_t>(bytes, 15);
  tile.k = get_le<std::uint8_t>(bytes, 16);
  tile.refinable = get_le<std::uint8_t>(bytes, 17);
  const std::uint32_t n_interior = get_le<std::uint32_t>(bytes, 18);
  const std::uint32_t n_tris = get_le<std::uint32_t>(bytes, 22);
  const std::int64_t g0 = get_le<std::int64_t>(bytes, 26);
  tile.eps = get_f32(bytes, 34);
  tile.err = get_f32(bytes, 38);
  tile.z_min = get_f32(bytes, 42);
  tile.z_max = get_f32(bytes, 46);
  const std::size_t lv = get_le<std::uint32_t>(bytes, 50), lc = get_le<std::uint32_t>(bytes, 54),
                    lr = get_le<std::uint32_t>(bytes, 58);
  const std::string name = fmt::format("tile {}/{}/{}", tile.id.level, tile.id.x, tile.id.y);
  if (tile.lattice_bits > 16 || tile.fine_bits > 16 || tile.k > 62 || tile.refinable > 15)
    throw bad_input("{}: header out of range", name);
  const std::size_t expected = kTileHeaderBytes + lv + lc + lr;
  if (bytes.size() < expected) throw bad_input("{} is truncated: {} of {} bytes", name, bytes.size(), expected);
  const int n = tile.n(), nb = 4 * n;
  if (n_interior > static_cast<std::uint64_t>(n - 1) * static_cast<std::uint64_t>(n - 1) ||
      n_tris > 2ull * static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n))
    throw bad_input("{}: {} interior vertices and {} triangles do not fit its lattice", name, n_interior, n_tris);
  const int total = nb + static_cast<int>(n_interior);

  // Connectivity first: it names the predictors of the new vertices.
  BitReader conn(bytes.substr(kTileHeaderBytes + lv, lc), "tile connectivity section");
  const int k_ref = static_cast<int>(conn.get(6));
  int next = nb, last = -1;
  std::vector<Predictor> preds;
  EdgeGraph graph(total);
  auto get_ref = [&](Predictor pred, std::initializer_list<int> context) {
    int r;
    if (conn.get(1)) {
      if (next >= total) throw bad_input("{}: more new vertices than the header counts", name);
      r = next++;
      preds.push_back(pred.a < 0 ? Predictor{last, -1, -1} : pred);
    } else {
      const std::vector<int>& cand = graph.candidates(context);
      if (!cand.empty() && conn.get(1)) {
        const std::uint64_t i = conn.get(bit_width(cand.size() - 1));
        if (i >= cand.size()) throw bad_input("{}: bad neighbour reference", name);
        r = cand[i];
      } else {
        const std::uint64_t d = conn.get_rice(k_ref);
        if (d >= static_cast<std::uint64_t>(next)) throw bad_input("{}: vertex referenced before it is introduced", name);
        r = next - 1 - static_cast<int>(d);
      }
    }
    last = r;
    return r;
  };
  std::vector<std::array<int, 3>> raw;
  raw.reserve(n_tris);
  preds.reserve(n_interior);
  std::array<int, 3> p{};
  for (std::uint32_t t = 0; t < n_tris; ++t) {
    const bool cont = conn.get(1) != 0;
    if (!cont) {
      const int a0 = get_ref({}, {});
      const int a1 = get_ref({}, {a0});
      const int a2 = get_ref({}, {a0, a1});
      p = {a0, a1, a2};
    } else {
      if (t == 0) throw bad_input("{}: strip continues before it starts", name);
      const int side = static_cast<int>(conn.get(1));
      const Predictor pred = side == 0 ? Predictor{p[1], p[2], p[0]} : Predictor{p[0], p[2], p[1]};
      const int v = side == 0 ? get_ref(pred, {p[1], p[2]}) : get_ref(pred, {p[0], p[2]});
      p = side == 0 ? std::array<int, 3>{p[1], p[2], v} : std::array<int, 3>{p[0], p[2], v};
    }
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2]) throw bad_input("{}: triangle repeats a vertex", name);
    if (cont) graph.add_strip_triangle(p);
    else graph.add_triangle(p);
    raw.push_back(p);
  }
  if (next != total) throw bad_input("{}: {} vertices never used", name, total - next);

  BitReader vert(bytes.substr(kTileHeaderBytes, lv), "tile vertex section");
  tile.vertices.resize(static_cast<std::size_t>(total));
  const int k_b = static_cast<int>(vert.get(6)), k_xy = static_cast<int>(vert.get(6)), k_h = static_cast<int>(vert.get(6));
  if (k_b > 40 || k_xy > 40 || k_h > 40) throw bad_input("{}: bad Rice parameter", name);
  std::int64_t g = g0;
  for (int b = 0; b < nb; ++b) {
    if (b > 0) g += unzigzag(vert.get_rice(k_b));
    const auto [X, Y] = border_point(b, n);
    tile.vertices[static_cast<std::size_t>(b)] = {X, Y, g};
  }
  for (int i = nb; i < total; ++i) {
    const TileVertex guess = predict(tile.vertices, preds[static_cast<std::size_t>(i - nb)], n, tile.k, g0);
    TileVertex& v = tile.vertices[static_cast<std::size_t>(i)];
    v.X = guess.X + static_cast<int>(unzigzag(vert.get_rice(k_xy)));
    v.Y = guess.Y + static_cast<int>(unzigzag(vert.get_rice(k_xy)));
    if (v.X <= 0 || v.Y <= 0 || v.X >= n || v.Y >= n) throw bad_input("{}: interior vertex off the tile's interior", name);
    v.code = guess.code + unzigzag(vert.get_rice(k_h));
  }
  tile.triangles.reserve(raw.size());
  for (const auto& q : raw) {
    // Counter-clockwise by geometry.
    const auto &a = tile.vertices[static_cast<std::size_t>(q[0])], &b = tile.vertices[static_cast<std::size_t>(q[1])],
               &c = tile.vertices[static_cast<std::size_t>(q[2])];
    const long long area = static_cast<long long>(b.X - a.X) * (c.Y - a.Y) - static_cast<long long>(c.X - a.X) * (b.Y - a.Y);
    if (area == 0) throw bad_input("{}: degenerate triangle", name);
    tile.triangles.push_back(area > 0 ? q : std::array<int, 3>{q[0], q[2], q[1]});
  }

  BitReader refine(bytes.substr(kTileHeaderBytes + lv + lc, lr), "tile refinement section");
  if (tile.refinable) {
    const int step_ratio = (2 << tile.fine_bits) / n;  // fine lattice steps per coarse one
    if (step_ratio < 1 || (2 << tile.fine_bits) % n != 0) throw bad_input("{}: finer lattice does not refine this one", name);
    for (int s = kWest; s <= kNorth; ++s) {
      if (!(tile.refinable & (1u << s))) continue;
      const auto [sx, sy] = side_start(s, n);
      std::int64_t prev = tile.vertices[static_cast<std::size_t>(border_index(sx, sy, n))].code;
      const int k = static_cast<int>(refine.get(6));
      if (k > 40) throw bad_input("{}: bad Rice parameter", name);
      const std::size_t count = static_cast<std::size_t>(step_ratio - 1) * static_cast<std::size_t>(n);
      for (std::size_t i = 0; i < count; ++i) {
        prev += unzigzag(refine.get_rice(k));
        tile.fine_G[s].push_back(prev);
      }
    }
  }
  return tile;
}

TileHeader read_tile_header(std::string_view bytes) {
  if (bytes.size() < kTileHeaderBytes) throw bad_input("tile is truncated: {} of at least {} header bytes", bytes.size(), kTileHeaderBytes);
  if (bytes.substr(0, 4) != std::string_view(kMagic, 4)) throw bad_input("not a terrainlod tile (bad magic)");
  if (get_le<std::uint8_t>(bytes, 4) != kVersion)
    throw bad_input("terrainlod tile version {} is not supported (this is version {})", get_le<std::uint8_t>(bytes, 4), kVersion);
  TileHeader h;
  h.id = {get_le<std::uint8_t>(bytes, 5), static_cast<int>(get_le<std::uint32_t>(bytes, 6)),
          static_cast<int>(get_le<std::uint32_t>(bytes, 10))};
  h.eps = get_f32(bytes, 34);
  h.err = get_f32(bytes, 38);
  h.z_min = get_f32(bytes, 42);
  h.z_max = get_f32(bytes, 46);
  return h;
}

}  // namespace fest::terrainlod
