#include "terrainlod/tile_codec.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "terrainlod/bitstream.hpp"
#include "terrainlod/tile_parent.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {
namespace {

constexpr char kMagic[4] = {'F', 'T', 'L', 'T'};
// Version 2 added the coding byte (offset 62); version 1 tiles (62-byte header) are
// standalone and still read.
constexpr std::uint8_t kVersion = 2;
constexpr std::size_t kVersion1HeaderBytes = 62;

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
  explicit EdgeGraph(int vertices)
      : slots_(static_cast<std::size_t>(vertices) * kInline), count_(static_cast<std::size_t>(vertices), 0),
        extra_(static_cast<std::size_t>(vertices)) {}
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
      const std::size_t i = static_cast<std::size_t>(c);
      const int* first = &slots_[i * kInline];
      out.insert(out.end(), first, first + std::min<int>(count_[i], kInline));
      out.insert(out.end(), extra_[i].begin(), extra_[i].end());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

 private:
  // Most vertices have few neighbours: they live in a fixed block per vertex, the rest
  // (fans) spill into a vector (no allocation per vertex in the common case).
  static constexpr int kInline = 8;
  void link(int a, int b) {
    const std::size_t i = static_cast<std::size_t>(a);
    int* first = &slots_[i * kInline];
    const int inline_count = std::min<int>(count_[i], kInline);
    if (std::find(first, first + inline_count, b) != first + inline_count) return;
    auto& more = extra_[i];
    if (std::find(more.begin(), more.end(), b) != more.end()) return;
    if (inline_count < kInline) first[inline_count] = b;
    else more.push_back(b);
    if (count_[i] < kInline) ++count_[i];
  }
  std::vector<int> slots_;
  std::vector<std::uint8_t> count_;
  std::vector<std::vector<int>> extra_;
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


// Bits of `values` Rice coded with the best parameter, plus the parameter's 6 bits (escapes
// counted as best_rice_k counts them: the comparison only needs to be consistent).
std::uint64_t rice_cost(const std::vector<std::uint64_t>& values) { return 6 + rice_bits(values, best_rice_k(values)); }

std::int64_t floor_shift(std::int64_t v, int bits) { return v >> bits; }  // arithmetic: floor(v / 2^bits)
std::int64_t scale(std::int64_t v, int bits) { return v * (std::int64_t{1} << bits); }

// A decoded height code within the format's range: +-kMaxHeightCode for finest codes G,
// that shifted right by k for interior codes H.
std::int64_t checked_height(std::int64_t code, std::int64_t limit, const std::string& name) {
  if (code > limit || code < -limit) throw bad_input("{}: height code {} is beyond the format's range (+-{})", name, code, limit);
  return code;
}

// Height predictors of the progressive coding (one flag bit each in the vertex section).
enum HeightMode : std::uint64_t { kFromNeighbours = 0, kFromParentSurface = 1 };

// The border loop's heights G, by loop index.
std::vector<std::int64_t> border_heights(const Tile& tile) {
  const int n = tile.n();
  std::vector<std::int64_t> g(static_cast<std::size_t>(4 * n), kUnknownHeight);
  for (const auto& v : tile.vertices) {
    const int b = border_index(v.X, v.Y, n);
    if (b >= 0) g[static_cast<std::size_t>(b)] = v.code;
  }
  return g;
}

// Prediction of border point b's G: the previous point on the loop, or the parent's
// surface there (when it covers the point).
std::int64_t predict_border(const std::vector<std::int64_t>& G, int b, int n, HeightMode mode, const ParentView* pv) {
  if (mode == kFromParentSurface && pv) {
    const auto [X, Y] = border_point(b, n);
    const std::int64_t s2 = pv->surface_at(X, Y);
    if (s2 != kUnknownHeight) return floor_shift(s2, 1);
  }
  return G[static_cast<std::size_t>(b) - 1];
}

// Prediction of a new interior vertex's H: the parallelogram's (`guess`), or the parent's
// surface at the vertex on this level's lattice, floor(P / 2^k) = floor(2 P / 2^(k+1)).
std::int64_t predict_height(const TileVertex& v, std::int64_t guess, int k, HeightMode mode, const ParentView* pv) {
  if (mode == kFromParentSurface && pv) {
    const std::int64_t s2 = pv->surface_at(v.X, v.Y);
    if (s2 != kUnknownHeight) return floor_shift(s2, k + 1);
  }
  return guess;
}

std::string tile_name(const TileId& id) { return fmt::format("tile {}/{}/{}", id.level, id.x, id.y); }

// A decoded height code: its prediction plus a Rice-coded residual, refused outside
// [-limit, limit] (tile.hpp's format limits). Predictions combine at most three codes in
// range (|p| < 2^55), so checking the residual first keeps the sum inside 64 bits.
std::int64_t add_height_residual(std::int64_t prediction, std::uint64_t coded, std::int64_t limit, const std::string& name) {
  const std::int64_t residual = unzigzag(coded);
  if (residual > 8 * kMaxHeightCode || residual < -8 * kMaxHeightCode)
    throw bad_input("{}: a height residual of {} is beyond the format's range", name, residual);
  return checked_height(prediction + residual, limit, name);
}

// A lattice coordinate from its prediction and a residual, both checked before the sum.
int add_lattice_residual(int prediction, std::uint64_t coded, int n, const std::string& name) {
  const std::int64_t residual = unzigzag(coded);
  if (residual <= -n || residual >= n) throw bad_input("{}: interior vertex off the tile's interior", name);
  return prediction + static_cast<int>(residual);
}

// The coding of `tile` with its triangles in the given strip order (vertex ids of the
// tile), standalone (pv null) or relative to its parent; nullopt where the tile disagrees
// with its parent (a height the parent fixes differs), so only standalone coding fits.
std::optional<std::string> encode_with_strips(const Tile& tile, const std::vector<StripTriangle>& strips, const ParentView* pv,
                                              TileSizes* sizes) {
  // What the decoder refuses is never written (tile.hpp's format limits).
  if (tile.lattice_bits < 0 || tile.lattice_bits > kMaxLatticeBits || tile.fine_bits > kMaxLatticeBits ||
      tile.k < 0 || tile.k > kMaxHeightBits)
    throw runtime_failure("tile encoder: lattice or quantum beyond the format's limits");
  for (const TileVertex& v : tile.vertices) {
    const std::int64_t limit = tile.on_border(v) ? kMaxHeightCode : kMaxHeightCode >> tile.k;
    if (v.code > limit || v.code < -limit) throw runtime_failure("tile encoder: height code beyond the format's range");
  }
  const int n = tile.n();
  const int nb = 4 * n;
  const bool progressive = pv != nullptr;
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
  const std::vector<std::int64_t> border_G = border_heights(tile);
  const std::int64_t g0 = border_G[0];

  // Progressive: what the parent gives. Inherited vertices inside the tile that it keeps
  // (same lattice point, same height) become "present"; the others are coded as new.
  std::vector<std::pair<std::uint64_t, int>> inherited_fields;  // (value, bits) in parent order
  std::vector<std::uint8_t> border_known(static_cast<std::size_t>(nb), 0);
  border_known[0] = 1;  // G0 is in the header
  std::vector<int> inherited_of(tile.vertices.size(), -1);  // index among the present inherited
  int present = 0;
  if (progressive) {
    if (pv->n != n) throw runtime_failure("tile encoder: parent view of another lattice");
    for (int b = 0; b < nb; ++b) {
      const std::int64_t given = pv->border_G[static_cast<std::size_t>(b)];
      if (given == kUnknownHeight) continue;
      if (given != border_G[static_cast<std::size_t>(b)]) return std::nullopt;
      border_known[static_cast<std::size_t>(b)] = 1;
    }
    std::vector<int> at(static_cast<std::size_t>(n + 1) * (n + 1), -1);
    for (std::size_t v = 0; v < tile.vertices.size(); ++v)
      if (renum[v] < 0) at[static_cast<std::size_t>(tile.vertices[v].Y) * (n + 1) + tile.vertices[v].X] = static_cast<int>(v);
    const int d = pv->parent_k - tile.k;
    for (const InheritedVertex& iv : pv->inherited) {
      if (iv.parent_border) continue;  // its G is the parent's
      if (iv.child_border) {           // G = H_parent 2^k_p + k_p low bits
        const int b = border_index(iv.X, iv.Y, n);
        const std::int64_t G = border_G[static_cast<std::size_t>(b)];
        if (floor_shift(G, pv->parent_k) != iv.code) return std::nullopt;
        inherited_fields.push_back({static_cast<std::uint64_t>(G - scale(iv.code, pv->parent_k)), pv->parent_k});
        border_known[static_cast<std::size_t>(b)] = 1;
        continue;
      }
      const int v = at[static_cast<std::size_t>(iv.Y) * (n + 1) + iv.X];
      const std::int64_t code = v >= 0 ? tile.vertices[static_cast<std::size_t>(v)].code : 0;
      const bool kept = v >= 0 && (d >= 0 ? floor_shift(code, d) == iv.code : code == floor_shift(iv.code, -d));
      inherited_fields.push_back({kept ? 1 : 0, 1});
      if (!kept) continue;
      if (d > 0) inherited_fields.push_back({static_cast<std::uint64_t>(code - scale(iv.code, d)), d});
      inherited_of[static_cast<std::size_t>(v)] = present++;
    }
  }

  const int total = static_cast<int>(tile.vertices.size());
  // First pass: walk the strips in the decoder's terms (new ids), noting every reference
  // and, for each new interior vertex, its predictor (parallelogram across the shared
  // edge when the strip continues, else the last referenced vertex).
  std::vector<int> interior;   // old ids in new order
  std::vector<Predictor> preds;
  struct Ref {
    bool fresh = false;
    bool inherited = false;                      // progressive: an inherited vertex's first use
    std::uint64_t inherited_delta = 0;           // zig-zag of the present index minus the expected one
    int candidate = -1, candidates = 0;          // index among the context's neighbours
    std::uint64_t distance = 0;                  // else: introduced this many vertices before the last
  };
  std::vector<Ref> refs;
  refs.reserve(strips.size() + 2 * static_cast<std::size_t>(std::count_if(strips.begin(), strips.end(), [](const StripTriangle& s) { return s.restart; })));
  EdgeGraph graph(total);
  int next = nb, last = -1, last_inherited = -1;
  auto ref = [&](int old, Predictor pred, std::initializer_list<int> context) {
    int& r = renum[static_cast<std::size_t>(old)];
    Ref x;
    if (r < 0) {
      r = next++;
      interior.push_back(old);
      x.fresh = true;
      const int inh = inherited_of[static_cast<std::size_t>(old)];
      if (inh >= 0) {
        x.inherited = true;
        x.inherited_delta = zigzag(inh - (last_inherited + 1));
        last_inherited = inh;
      } else {
        preds.push_back(pred.a < 0 ? Predictor{last, -1, -1} : pred);
      }
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
  // Where the inherited vertices enter: before each, the number of new vertices introduced
  // since the previous one (a run length: cheaper than a kind bit per new vertex when few
  // parent vertices are kept, as cheap when most are).
  std::vector<std::uint64_t> distances, inherited_deltas, gaps;
  std::uint64_t run = 0;
  for (const auto& r : refs) {
    if (!r.fresh && r.candidate < 0) distances.push_back(r.distance);
    if (r.inherited) inherited_deltas.push_back(r.inherited_delta), gaps.push_back(run), run = 0;
    else if (r.fresh) ++run;
  }
  BitWriter conn;
  const int k_ref = best_rice_k(distances);
  conn.put(static_cast<std::uint64_t>(k_ref), 6);
  const int k_inh = progressive ? best_rice_k(inherited_deltas) : 0, k_gap = progressive ? best_rice_k(gaps) : 0;
  if (progressive) {
    conn.put(static_cast<std::uint64_t>(k_inh), 6);
    conn.put(static_cast<std::uint64_t>(k_gap), 6);
    if (!gaps.empty()) conn.put_rice(gaps[0], k_gap);
  }
  {
    std::size_t r = 0, inherited_seen = 0;
    auto put_ref = [&]() {
      const Ref& x = refs[r++];
      conn.put(x.fresh ? 1 : 0, 1);
      if (x.fresh) {
        if (x.inherited) {
          conn.put_rice(x.inherited_delta, k_inh);
          if (++inherited_seen < gaps.size()) conn.put_rice(gaps[inherited_seen], k_gap);
        }
        return;
      }
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
  // Border heights still to send (all but G0 standalone; those the parent does not give
  // progressively), under each predictor.
  std::array<std::vector<std::uint64_t>, 2> border_res;
  for (int b = 1; b < nb; ++b) {
    if (border_known[static_cast<std::size_t>(b)]) continue;
    border_res[kFromNeighbours].push_back(zigzag(border_G[static_cast<std::size_t>(b)] - predict_border(border_G, b, n, kFromNeighbours, pv)));
    if (progressive)
      border_res[kFromParentSurface].push_back(zigzag(border_G[static_cast<std::size_t>(b)] - predict_border(border_G, b, n, kFromParentSurface, pv)));
  }
  std::vector<std::uint64_t> xy_res;
  std::array<std::vector<std::uint64_t>, 2> h_res;
  {
    std::size_t j = 0;  // index into preds (new vertices only)
    for (std::size_t i = 0; i < interior.size(); ++i) {
      const int old = interior[i];
      if (inherited_of[static_cast<std::size_t>(old)] >= 0) continue;
      const TileVertex& v = tile.vertices[static_cast<std::size_t>(old)];
      const TileVertex guess = predict(ordered, preds[j++], n, tile.k, g0);
      xy_res.push_back(zigzag(v.X - guess.X));
      xy_res.push_back(zigzag(v.Y - guess.Y));
      h_res[kFromNeighbours].push_back(zigzag(v.code - guess.code));
      if (progressive) h_res[kFromParentSurface].push_back(zigzag(v.code - predict_height(v, guess.code, tile.k, kFromParentSurface, pv)));
    }
  }
  // Standalone coding has only the neighbours; progressive takes the cheaper per tile.
  const HeightMode border_mode = progressive && rice_cost(border_res[kFromParentSurface]) < rice_cost(border_res[kFromNeighbours])
                                     ? kFromParentSurface : kFromNeighbours;
  const HeightMode height_mode = progressive && rice_cost(h_res[kFromParentSurface]) < rice_cost(h_res[kFromNeighbours])
                                     ? kFromParentSurface : kFromNeighbours;
  BitWriter vert;
  if (progressive) {
    vert.put(border_mode, 1);
    vert.put(height_mode, 1);
  }
  const int k_b = best_rice_k(border_res[border_mode]), k_xy = best_rice_k(xy_res), k_h = best_rice_k(h_res[height_mode]);
  vert.put(static_cast<std::uint64_t>(k_b), 6);
  vert.put(static_cast<std::uint64_t>(k_xy), 6);
  vert.put(static_cast<std::uint64_t>(k_h), 6);
  std::size_t inherited_bit_count = 0;
  for (const auto& [value, bits] : inherited_fields) {
    vert.put(value, bits);
    inherited_bit_count += static_cast<std::size_t>(bits);
  }
  for (auto u : border_res[border_mode]) vert.put_rice(u, k_b);
  for (std::size_t i = 0; i < xy_res.size() / 2; ++i) {
    vert.put_rice(xy_res[2 * i], k_xy);
    vert.put_rice(xy_res[2 * i + 1], k_xy);
    vert.put_rice(h_res[height_mode][i], k_h);
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
  put_le<std::uint8_t>(out, static_cast<std::uint8_t>(progressive ? TileCoding::progressive : TileCoding::standalone));
  if (out.size() != kTileHeaderBytes) throw runtime_failure("tile header is {} bytes", out.size());
  if (sizes) {
    *sizes = {out.size(), vbytes.size(), cbytes.size(), rbytes.size()};
    sizes->coding = progressive ? TileCoding::progressive : TileCoding::standalone;
    sizes->inherited_bits = inherited_bit_count;
    sizes->inherited_present = static_cast<std::size_t>(present);
  }
  return out + vbytes + cbytes + rbytes;
}

// Decodes a tile; `parent` (decoded) is needed for progressive coding; `strips`, if given,
// receives the stream's triangles in the decoded vertex ids, as they were coded.
// The magic, the version (1 or the current one) and a whole header: the version, or
// bad_input saying what is wrong.
unsigned checked_version(std::string_view bytes) {
  if (bytes.size() < kVersion1HeaderBytes)
    throw bad_input("tile is truncated: {} of at least {} header bytes", bytes.size(), kVersion1HeaderBytes);
  if (bytes.substr(0, 4) != std::string_view(kMagic, 4)) throw bad_input("not a terrainlod tile (bad magic)");
  const unsigned version = get_le<std::uint8_t>(bytes, 4);
  if (version != 1 && version != kVersion)
    throw bad_input("terrainlod tile version {} is not supported (this is version {}, which also reads 1)", version, kVersion);
  const std::size_t header = version == 1 ? kVersion1HeaderBytes : kTileHeaderBytes;
  if (bytes.size() < header) throw bad_input("tile is truncated: {} of {} header bytes", bytes.size(), header);
  return version;
}

Tile decode_with_strips(std::string_view bytes, const Tile* parent, std::vector<StripTriangle>* strips) {
  const unsigned version = checked_version(bytes);
  const std::size_t header = version == 1 ? kVersion1HeaderBytes : kTileHeaderBytes;
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
  const unsigned coding = version == 1 ? 0u : get_le<std::uint8_t>(bytes, 62);
  const std::string name = tile_name(tile.id);
  if (tile.lattice_bits > kMaxLatticeBits || tile.fine_bits > kMaxLatticeBits)
    throw bad_input("{}: a lattice of 2^{} steps per side is beyond the format's 2^{}", name,
                    std::max(tile.lattice_bits, tile.fine_bits), kMaxLatticeBits);
  if (tile.k > kMaxHeightBits || tile.refinable > 15) throw bad_input("{}: header out of range", name);
  checked_height(g0, kMaxHeightCode, name);
  const std::int64_t h_limit = kMaxHeightCode >> tile.k;  // interior codes H = floor(G / 2^k)
  if (coding > 1) throw bad_input("{}: unknown coding {}", name, coding);
  const bool progressive = coding == static_cast<unsigned>(TileCoding::progressive);
  const std::size_t expected = header + lv + lc + lr;
  if (bytes.size() < expected) throw bad_input("{} is truncated: {} of {} bytes", name, bytes.size(), expected);
  const int n = tile.n(), nb = 4 * n;
  if (n_interior > static_cast<std::uint64_t>(n - 1) * static_cast<std::uint64_t>(n - 1) ||
      n_tris > 2ull * static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n))
    throw bad_input("{}: {} interior vertices and {} triangles do not fit its lattice", name, n_interior, n_tris);
  const int total = nb + static_cast<int>(n_interior);
  std::optional<ParentView> pv;
  if (progressive) {
    if (tile.id.level == 0) throw bad_input("{}: the root cannot be coded relative to a parent", name);
    if (!parent) {
      const TileId up = parent_id(tile.id);
      throw bad_input("{} is coded relative to its parent {}/{}/{}, which is not at hand", name, up.level, up.x, up.y);
    }
    pv = parent_view(*parent, tile.id, tile.lattice_bits);
  }
  tile.vertices.resize(static_cast<std::size_t>(total));

  // The vertex section's head: predictors, Rice parameters and (progressive) what the
  // parent gives: border heights, and the inherited interior vertices the tile keeps.
  BitReader vert(bytes.substr(header, lv), "tile vertex section");
  HeightMode border_mode = kFromNeighbours, height_mode = kFromNeighbours;
  if (progressive) {
    border_mode = static_cast<HeightMode>(vert.get(1));
    height_mode = static_cast<HeightMode>(vert.get(1));
  }
  const int k_b = static_cast<int>(vert.get(6)), k_xy = static_cast<int>(vert.get(6)), k_h = static_cast<int>(vert.get(6));
  if (k_b > 40 || k_xy > 40 || k_h > 40) throw bad_input("{}: bad Rice parameter", name);
  std::vector<std::int64_t> G(static_cast<std::size_t>(nb), kUnknownHeight);
  std::vector<TileVertex> present;  // inherited interior vertices kept, in parent order
  if (progressive) {
    G = pv->border_G;
    const int d = pv->parent_k - tile.k;
    for (const InheritedVertex& iv : pv->inherited) {
      if (iv.parent_border) continue;
      if (iv.child_border) {
        G[static_cast<std::size_t>(border_index(iv.X, iv.Y, n))] =
            checked_height(scale(iv.code, pv->parent_k) + static_cast<std::int64_t>(vert.get(pv->parent_k)), kMaxHeightCode, name);
        continue;
      }
      if (!vert.get(1)) continue;
      const std::int64_t code = d >= 0 ? scale(iv.code, d) + static_cast<std::int64_t>(vert.get(d)) : floor_shift(iv.code, -d);
      present.push_back({iv.X, iv.Y, checked_height(code, h_limit, name)});
    }
    if (G[0] != kUnknownHeight && G[0] != g0) throw bad_input("{}: its corner height disagrees with its parent's", name);
  }
  G[0] = g0;

  // Connectivity: it names the predictors of the new vertices and where the inherited
  // ones enter the numbering.
  BitReader conn(bytes.substr(header + lv, lc), "tile connectivity section");
  const int k_ref = static_cast<int>(conn.get(6));
  const int k_inh = progressive ? static_cast<int>(conn.get(6)) : 0, k_gap = progressive ? static_cast<int>(conn.get(6)) : 0;
  if (k_ref > 40 || k_inh > 40 || k_gap > 40) throw bad_input("{}: bad Rice parameter", name);
  int next = nb, last = -1, last_inherited = -1;
  const int n_present = static_cast<int>(present.size());
  int inherited_left = n_present;
  std::uint64_t gap = n_present > 0 ? conn.get_rice(k_gap) : 0;  // new vertices before the next inherited one
  std::vector<std::uint8_t> present_used(present.size(), 0);
  std::vector<Predictor> preds;
  std::vector<int> new_ids;
  EdgeGraph graph(total);
  auto get_ref = [&](Predictor pred, std::initializer_list<int> context) {
    int r;
    if (conn.get(1)) {
      if (next >= total) throw bad_input("{}: more new vertices than the header counts", name);
      r = next++;
      if (inherited_left > 0 && gap == 0) {
        const std::int64_t step = unzigzag(conn.get_rice(k_inh));
        if (step < -n_present - 1 || step > n_present) throw bad_input("{}: bad inherited vertex reference", name);
        const std::int64_t i = last_inherited + 1 + step;
        if (i < 0 || i >= n_present || present_used[static_cast<std::size_t>(i)])
          throw bad_input("{}: bad inherited vertex reference", name);
        present_used[static_cast<std::size_t>(i)] = 1;
        tile.vertices[static_cast<std::size_t>(r)] = present[static_cast<std::size_t>(i)];
        last_inherited = static_cast<int>(i);
        if (--inherited_left > 0) gap = conn.get_rice(k_gap);
      } else {
        if (inherited_left > 0) --gap;
        new_ids.push_back(r);
        preds.push_back(pred.a < 0 ? Predictor{last, -1, -1} : pred);
      }
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
  if (strips) strips->clear();
  std::array<int, 3> p{};
  for (std::uint32_t t = 0; t < n_tris; ++t) {
    const bool cont = conn.get(1) != 0;
    int side = 0;
    if (!cont) {
      const int a0 = get_ref({}, {});
      const int a1 = get_ref({}, {a0});
      const int a2 = get_ref({}, {a0, a1});
      p = {a0, a1, a2};
    } else {
      if (t == 0) throw bad_input("{}: strip continues before it starts", name);
      side = static_cast<int>(conn.get(1));
      const Predictor pred = side == 0 ? Predictor{p[1], p[2], p[0]} : Predictor{p[0], p[2], p[1]};
      const int v = side == 0 ? get_ref(pred, {p[1], p[2]}) : get_ref(pred, {p[0], p[2]});
      p = side == 0 ? std::array<int, 3>{p[1], p[2], v} : std::array<int, 3>{p[0], p[2], v};
    }
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2]) throw bad_input("{}: triangle repeats a vertex", name);
    if (cont) graph.add_strip_triangle(p);
    else graph.add_triangle(p);
    raw.push_back(p);
    if (strips) strips->push_back({!cont, side, p});
  }
  if (next != total) throw bad_input("{}: {} vertices never used", name, total - next);
  if (inherited_left != 0) throw bad_input("{}: {} kept inherited vertices never used", name, inherited_left);

  // The rest of the vertex section: border heights, then the new interior vertices.
  for (int b = 1; b < nb; ++b)
    if (G[static_cast<std::size_t>(b)] == kUnknownHeight)
      G[static_cast<std::size_t>(b)] =
          add_height_residual(predict_border(G, b, n, border_mode, pv ? &*pv : nullptr), vert.get_rice(k_b), kMaxHeightCode, name);
  for (int b = 0; b < nb; ++b) {
    const auto [X, Y] = border_point(b, n);
    tile.vertices[static_cast<std::size_t>(b)] = {X, Y, G[static_cast<std::size_t>(b)]};
  }
  for (std::size_t j = 0; j < new_ids.size(); ++j) {
    const TileVertex guess = predict(tile.vertices, preds[j], n, tile.k, g0);
    TileVertex& v = tile.vertices[static_cast<std::size_t>(new_ids[j])];
    v.X = add_lattice_residual(guess.X, vert.get_rice(k_xy), n, name);
    v.Y = add_lattice_residual(guess.Y, vert.get_rice(k_xy), n, name);
    if (v.X <= 0 || v.Y <= 0 || v.X >= n || v.Y >= n) throw bad_input("{}: interior vertex off the tile's interior", name);
    v.code = add_height_residual(predict_height(v, guess.code, tile.k, height_mode, pv ? &*pv : nullptr), vert.get_rice(k_h),
                                 h_limit, name);
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

  BitReader refine(bytes.substr(header + lv + lc, lr), "tile refinement section");
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
        prev = add_height_residual(prev, refine.get_rice(k), kMaxHeightCode, name);
        tile.fine_G[s].push_back(prev);
      }
    }
  }
  return tile;
}

// Progressive coding where the tile has a parent and agrees with it; standalone else.
std::string encode_relative(const Tile& tile, const std::vector<StripTriangle>& strips, const Tile* parent, TileSizes* sizes) {
  if (parent && tile.id.level > 0) {
    const ParentView pv = parent_view(*parent, tile.id, tile.lattice_bits);
    if (auto s = encode_with_strips(tile, strips, &pv, sizes)) return std::move(*s);
  }
  return *encode_with_strips(tile, strips, nullptr, sizes);
}

}  // namespace

TileCoding tile_coding(std::string_view bytes) {
  if (bytes.size() < kTileHeaderBytes || bytes.substr(0, 4) != std::string_view(kMagic, 4) ||
      get_le<std::uint8_t>(bytes, 4) != kVersion)
    return TileCoding::standalone;  // version 1 (or not a tile: decoding says why)
  return get_le<std::uint8_t>(bytes, 62) == static_cast<std::uint8_t>(TileCoding::progressive) ? TileCoding::progressive
                                                                                                : TileCoding::standalone;
}

std::string encode_tile(const Tile& tile, TileSizes* sizes) {
  return *encode_with_strips(tile, strip_order(tile.triangles), nullptr, sizes);
}

std::string encode_tile_progressive(const Tile& tile, const Tile* parent, TileSizes* sizes) {
  return encode_relative(tile, strip_order(tile.triangles), parent, sizes);
}

std::string recode_tile(std::string_view bytes, TileCoding coding, const Tile* parent, TileSizes* sizes) {
  std::vector<StripTriangle> strips;
  const Tile tile = decode_with_strips(bytes, parent, &strips);
  return coding == TileCoding::progressive ? encode_relative(tile, strips, parent, sizes)
                                           : *encode_with_strips(tile, strips, nullptr, sizes);
}

Tile decode_tile(std::string_view bytes, const Tile* parent) { return decode_with_strips(bytes, parent, nullptr); }

TileHeader read_tile_header(std::string_view bytes) {
  checked_version(bytes);
  // Both versions place these fields alike (version 2 only appended the coding byte).
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
