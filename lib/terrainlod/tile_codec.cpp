#include "terrainlod/tile_codec.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <unordered_map>

#include "core/error.hpp"
#include "terrainlod/bitstream.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {
namespace {

constexpr char kMagic[4] = {'F', 'T', 'L', 'T'};
constexpr std::uint8_t kVersion = 1;
constexpr int kWidthBits = 7;  // a field width 0..64

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

int width_of_deltas(const std::vector<std::int64_t>& values, std::int64_t start) {
  int w = 0;
  for (std::int64_t v : values) {
    w = std::max(w, bit_width(zigzag(v - start)));
    start = v;
  }
  return w;
}

// Greedy strips over the triangle adjacency: each emitted as (p0, p1, p2), continued
// across (p1, p2) if that neighbour is free, else across (p0, p2), else restarted.
struct StripTriangle {
  bool restart;
  int side;  // 0: shares (p1, p2); 1: shares (p0, p2)
  std::array<int, 3> v;
};

std::vector<StripTriangle> strip_order(const std::vector<std::array<int, 3>>& tris) {
  std::unordered_map<std::uint64_t, int> by_edge;  // directed edge -> triangle
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int e = 0; e < 3; ++e) by_edge[key(tris[t][e], tris[t][(e + 1) % 3])] = static_cast<int>(t);
  std::vector<std::uint8_t> used(tris.size(), 0);
  // The free triangle across edge {a, b} (the neighbour holds it as b -> a), or -1.
  auto across = [&](int a, int b) {
    for (auto k : {key(b, a), key(a, b)}) {
      auto it = by_edge.find(k);
      if (it != by_edge.end() && !used[static_cast<std::size_t>(it->second)]) return it->second;
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
  std::vector<int> interior;  // old ids in new order
  int next = nb;
  BitWriter conn;
  const int total = static_cast<int>(tile.vertices.size());
  const int ref_bits = bit_width(static_cast<std::uint64_t>(std::max(1, total - 1)));
  auto put_ref = [&](int old) {
    if (renum[static_cast<std::size_t>(old)] < 0) {
      renum[static_cast<std::size_t>(old)] = next++;
      interior.push_back(old);
      conn.put(1, 1);
    } else {
      conn.put(0, 1);
      conn.put(static_cast<std::uint64_t>(renum[static_cast<std::size_t>(old)]), ref_bits);
    }
  };
  for (const auto& s : strips) {
    conn.put(s.restart ? 0 : 1, 1);
    if (s.restart) {
      for (int v : s.v) put_ref(v);
    } else {
      conn.put(static_cast<std::uint64_t>(s.side), 1);
      put_ref(s.v[2]);
    }
  }
  if (next != total) throw runtime_failure("tile encoder: {} vertices unused by triangles", total - next);

  // Vertex section.
  std::vector<std::int64_t> border_G(static_cast<std::size_t>(nb));
  for (std::size_t v = 0; v < tile.vertices.size(); ++v)
    if (renum[v] < nb) border_G[static_cast<std::size_t>(renum[v])] = tile.vertices[v].code;
  const std::int64_t g0 = border_G[0];
  BitWriter vert;
  const int wb = width_of_deltas(border_G, g0);
  vert.put(static_cast<std::uint64_t>(wb), kWidthBits);
  for (int b = 1; b < nb; ++b) vert.put(zigzag(border_G[static_cast<std::size_t>(b)] - border_G[static_cast<std::size_t>(b) - 1]), wb);
  std::vector<std::int64_t> interior_H;
  for (int old : interior) interior_H.push_back(tile.vertices[static_cast<std::size_t>(old)].code);
  const std::int64_t h0 = g0 >> tile.k;
  const int wi = width_of_deltas(interior_H, h0);
  vert.put(static_cast<std::uint64_t>(wi), kWidthBits);
  std::int64_t prev = h0;
  for (std::size_t i = 0; i < interior.size(); ++i) {
    const TileVertex& v = tile.vertices[static_cast<std::size_t>(interior[i])];
    vert.put(static_cast<std::uint64_t>(v.X), tile.lattice_bits);
    vert.put(static_cast<std::uint64_t>(v.Y), tile.lattice_bits);
    vert.put(zigzag(v.code - prev), wi);
    prev = v.code;
  }

  // Refinement section.
  BitWriter refine;
  for (int s = kWest; s <= kNorth; ++s) {
    if (!(tile.refinable & (1u << s))) continue;
    const auto [sx, sy] = side_start(s, n);
    const std::int64_t start = border_G[static_cast<std::size_t>(border_index(sx, sy, n))];
    const int w = width_of_deltas(tile.fine_G[s], start);
    refine.put(static_cast<std::uint64_t>(w), kWidthBits);
    std::int64_t p = start;
    for (std::int64_t g : tile.fine_G[s]) {
      refine.put(zigzag(g - p), w);
      p = g;
    }
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

  BitReader vert(bytes.substr(kTileHeaderBytes, lv), "tile vertex section");
  tile.vertices.resize(static_cast<std::size_t>(total));
  const int wb = static_cast<int>(vert.get(kWidthBits));
  std::int64_t g = g0;
  for (int b = 0; b < nb; ++b) {
    if (b > 0) g += unzigzag(vert.get(wb));
    const auto [X, Y] = border_point(b, n);
    tile.vertices[static_cast<std::size_t>(b)] = {X, Y, g};
  }
  const int wi = static_cast<int>(vert.get(kWidthBits));
  std::int64_t h = g0 >> tile.k;
  for (int i = nb; i < total; ++i) {
    TileVertex& v = tile.vertices[static_cast<std::size_t>(i)];
    v.X = static_cast<int>(vert.get(tile.lattice_bits));
    v.Y = static_cast<int>(vert.get(tile.lattice_bits));
    if (v.X == 0 || v.Y == 0) throw bad_input("{}: interior vertex on the border", name);
    h += unzigzag(vert.get(wi));
    v.code = h;
  }

  BitReader conn(bytes.substr(kTileHeaderBytes + lv, lc), "tile connectivity section");
  const int ref_bits = bit_width(static_cast<std::uint64_t>(std::max(1, total - 1)));
  int next = nb;
  auto get_ref = [&]() {
    if (conn.get(1)) {
      if (next >= total) throw bad_input("{}: more new vertices than the header counts", name);
      return next++;
    }
    const int r = static_cast<int>(conn.get(ref_bits));
    if (r >= next) throw bad_input("{}: vertex {} referenced before it is introduced", name, r);
    return r;
  };
  std::array<int, 3> p{};
  for (std::uint32_t t = 0; t < n_tris; ++t) {
    const bool cont = conn.get(1) != 0;
    if (!cont) {
      p = {get_ref(), get_ref(), get_ref()};
    } else {
      if (t == 0) throw bad_input("{}: strip continues before it starts", name);
      const int side = static_cast<int>(conn.get(1));
      const int v = get_ref();
      p = side == 0 ? std::array<int, 3>{p[1], p[2], v} : std::array<int, 3>{p[0], p[2], v};
    }
    // Counter-clockwise by geometry.
    const auto &a = tile.vertices[static_cast<std::size_t>(p[0])], &b = tile.vertices[static_cast<std::size_t>(p[1])],
               &c = tile.vertices[static_cast<std::size_t>(p[2])];
    const long long area = static_cast<long long>(b.X - a.X) * (c.Y - a.Y) - static_cast<long long>(c.X - a.X) * (b.Y - a.Y);
    if (area == 0) throw bad_input("{}: degenerate triangle", name);
    tile.triangles.push_back(area > 0 ? p : std::array<int, 3>{p[0], p[2], p[1]});
  }
  if (next != total) throw bad_input("{}: {} vertices never used", name, total - next);

  BitReader refine(bytes.substr(kTileHeaderBytes + lv + lc, lr), "tile refinement section");
  if (tile.refinable) {
    const int step_ratio = (2 << tile.fine_bits) / n;  // fine lattice steps per coarse one
    if (step_ratio < 1 || (2 << tile.fine_bits) % n != 0) throw bad_input("{}: finer lattice does not refine this one", name);
    for (int s = kWest; s <= kNorth; ++s) {
      if (!(tile.refinable & (1u << s))) continue;
      const auto [sx, sy] = side_start(s, n);
      std::int64_t prev = tile.vertices[static_cast<std::size_t>(border_index(sx, sy, n))].code;
      const int w = static_cast<int>(refine.get(kWidthBits));
      const std::size_t count = static_cast<std::size_t>(step_ratio - 1) * static_cast<std::size_t>(n);
      for (std::size_t i = 0; i < count; ++i) {
        prev += unzigzag(refine.get(w));
        tile.fine_G[s].push_back(prev);
      }
    }
  }
  return tile;
}

}  // namespace fest::terrainlod
