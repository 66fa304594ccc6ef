#include "terrainlod/nodata_mask.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/little_endian.hpp"

namespace fest::terrainlod {
namespace {

constexpr char kMagic[4] = {'F', 'T', 'N', 'M'};
constexpr std::uint8_t kVersion = 1;
constexpr std::size_t kHeadBytes = 4 + 1 + 4 + 4 + 8;
constexpr int kMaxSide = 1 << 24;  // samples per side: far beyond any pyramid (levels <= 30, tiles <= 4096)

using little_endian::get_le;
using little_endian::put_le;

void put_varint(std::string& s, std::uint32_t v) {
  while (v >= 0x80) {
    s.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  s.push_back(static_cast<char>(v));
}

// A LEB128 value of at most 32 bits in at most 5 bytes (no overlong forms past that).
std::uint32_t get_varint(std::string_view s, std::size_t& at) {
  std::uint64_t v = 0;
  for (int shift = 0; shift < 35; shift += 7) {
    if (at >= s.size()) throw bad_input("nodata mask is truncated");
    const auto byte = static_cast<unsigned char>(s[at++]);
    v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
    if (!(byte & 0x80)) {
      if (v > 0xffffffffull) break;
      return static_cast<std::uint32_t>(v);
    }
  }
  throw bad_input("nodata mask has a number over 32 bits");
}

// floor(a / b) and ceil(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

}  // namespace

bool NodataMask::any_in_row(std::int64_t j, std::int64_t x0, std::int64_t x1) const {
  if (samples == 0 || x1 < x0) return false;
  const std::int64_t last_x = width - 1;
  j = std::min<std::int64_t>(std::max<std::int64_t>(j, 0), height - 1);
  x0 = std::min(std::max<std::int64_t>(x0, 0), last_x);
  x1 = std::min(std::max<std::int64_t>(x1, 0), last_x);
  const auto first = runs.begin() + row_begin[static_cast<std::size_t>(j)];
  const auto last = runs.begin() + row_begin[static_cast<std::size_t>(j) + 1];
  // The first run ending after x0 (runs are sorted and disjoint) is the only candidate.
  const auto r = std::upper_bound(first, last, x0, [](std::int64_t x, const std::array<int, 2>& run) { return x < run[1]; });
  return r != last && (*r)[0] <= x1;
}

bool valid_bounds(const NodataMask& m, std::array<int, 4>& box) {
  bool any = false;
  for (int j = 0; j < m.height; ++j) {
    const std::uint32_t a = m.row_begin[static_cast<std::size_t>(j)], b = m.row_begin[static_cast<std::size_t>(j) + 1];
    // The row's first and last valid columns: around its first and last runs.
    int lo = 0, hi = m.width - 1;
    if (a < b && m.runs[a][0] == 0) lo = m.runs[a][1];
    if (a < b && m.runs[b - 1][1] == m.width) hi = m.runs[b - 1][0] - 1;
    if (lo > hi) continue;  // the whole row is nodata
    box = any ? std::array<int, 4>{std::min(box[0], lo), box[1], std::max(box[2], hi), j} : std::array<int, 4>{lo, j, hi, j};
    any = true;
  }
  return any;
}

NodataMask nodata_mask(const HeightGrid& grid) {
  NodataMask m;
  m.width = grid.width;
  m.height = grid.height;
  m.row_begin.assign(1, 0);
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width;) {
      const std::size_t k = static_cast<std::size_t>(j) * grid.width + i;
      if (grid.valid.empty() || grid.valid[k]) {
        ++i;
        continue;
      }
      int end = i;
      while (end < grid.width && !grid.valid[static_cast<std::size_t>(j) * grid.width + end]) ++end;
      m.runs.push_back({i, end});
      m.samples += static_cast<std::size_t>(end - i);
      i = end;
    }
    m.row_begin.push_back(static_cast<std::uint32_t>(m.runs.size()));
  }
  return m;
}

std::string encode_nodata_mask(const NodataMask& m) {
  std::string out(kMagic, 4);
  put_le<std::uint8_t>(out, kVersion);
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(m.width));
  put_le<std::uint32_t>(out, static_cast<std::uint32_t>(m.height));
  put_le<std::uint64_t>(out, m.samples);
  for (int j = 0; j < m.height; ++j) {
    const std::uint32_t a = m.row_begin[static_cast<std::size_t>(j)], b = m.row_begin[static_cast<std::size_t>(j) + 1];
    put_varint(out, b - a);
    int end = 0;
    for (std::uint32_t r = a; r < b; ++r) {
      put_varint(out, static_cast<std::uint32_t>(m.runs[r][0] - end));
      put_varint(out, static_cast<std::uint32_t>(m.runs[r][1] - m.runs[r][0]));
      end = m.runs[r][1];
    }
  }
  return out;
}

NodataMask decode_nodata_mask(std::string_view s) {
  if (s.size() < 4 || s.substr(0, 4) != std::string_view(kMagic, 4)) throw bad_input("nodata mask has a bad magic");
  if (s.size() < kHeadBytes) throw bad_input("nodata mask is truncated: {} bytes", s.size());
  if (get_le<std::uint8_t>(s, 4) != kVersion)
    throw bad_input("nodata mask version {} is not supported (this is version {})", get_le<std::uint8_t>(s, 4), kVersion);
  const std::uint32_t w = get_le<std::uint32_t>(s, 5), h = get_le<std::uint32_t>(s, 9);
  const std::uint64_t count = get_le<std::uint64_t>(s, 13);
  if (w < 2 || h < 2 || w > static_cast<std::uint32_t>(kMaxSide) || h > static_cast<std::uint32_t>(kMaxSide))
    throw bad_input("nodata mask is {} x {} samples", w, h);
  // Every row takes at least one byte: a short section cannot claim many rows.
  if (s.size() - kHeadBytes < h) throw bad_input("nodata mask is truncated: {} rows in {} bytes", h, s.size() - kHeadBytes);
  NodataMask m;
  m.width = static_cast<int>(w);
  m.height = static_cast<int>(h);
  m.row_begin.reserve(static_cast<std::size_t>(h) + 1);
  m.row_begin.push_back(0);
  std::size_t at = kHeadBytes;
  for (std::uint32_t j = 0; j < h; ++j) {
    const std::uint32_t n = get_varint(s, at);
    // Each run takes at least two bytes, and a row holds at most (w + 1) / 2 runs.
    if (n > (w + 1) / 2 || n > (s.size() - at) / 2) throw bad_input("nodata mask row {} claims {} runs", j, n);
    std::uint64_t end = 0;
    for (std::uint32_t r = 0; r < n; ++r) {
      const std::uint64_t gap = get_varint(s, at), len = get_varint(s, at);
      if ((r > 0 && gap == 0) || len == 0 || end + gap + len > w)
        throw bad_input("nodata mask row {} has a run outside the row or not separated from the previous one", j);
      m.runs.push_back({static_cast<int>(end + gap), static_cast<int>(end + gap + len)});
      end += gap + len;
      m.samples += static_cast<std::size_t>(len);
    }
    m.row_begin.push_back(static_cast<std::uint32_t>(m.runs.size()));
  }
  if (at != s.size()) throw bad_input("nodata mask has {} bytes after its last row", s.size() - at);
  if (m.samples != count) throw bad_input("nodata mask counts {} nodata samples but its runs hold {}", count, m.samples);
  return m;
}

bool covers_nodata(const NodataMask& mask, const std::array<std::array<std::int64_t, 2>, 3>& v) {
  if (mask.samples == 0) return false;
  const std::int64_t y_lo = std::min({v[0][1], v[1][1], v[2][1]}), y_hi = std::max({v[0][1], v[1][1], v[2][1]});
  for (std::int64_t y = y_lo; y <= y_hi; ++y) {
    // The closed triangle's span on row y: between the crossings of its edges with the
    // row, x = xa + (y - ya)(xb - xa) / (yb - ya); ceil(min) = min(ceil), floor(max) = max(floor).
    std::int64_t lo = 0, hi = -1;
    bool any = false;
    for (int e = 0; e < 3; ++e) {
      const auto& a = v[static_cast<std::size_t>(e)];
      const auto& b = v[static_cast<std::size_t>((e + 1) % 3)];
      std::int64_t c, f;
      if (a[1] == b[1]) {
        if (a[1] != y) continue;
        c = std::min(a[0], b[0]), f = std::max(a[0], b[0]);
      } else {
        if (y < std::min(a[1], b[1]) || y > std::max(a[1], b[1])) continue;
        std::int64_t num = (y - a[1]) * (b[0] - a[0]), den = b[1] - a[1];
        if (den < 0) num = -num, den = -den;
        c = a[0] + ceil_div(num, den);
        f = a[0] + floor_div(num, den);
      }
      lo = any ? std::min(lo, c) : c;
      hi = any ? std::max(hi, f) : f;
      any = true;
    }
    if (any && mask.any_in_row(y, lo, hi)) return true;
  }
  return false;
}

std::size_t cut_holes(const NodataMask& mask, TileTriangulation& tri) {
  if (mask.samples == 0) return 0;
  std::vector<std::array<int, 3>> kept;
  kept.reserve(tri.triangles.size());
  std::vector<int> renumber(tri.vertices.size(), -1);
  for (const auto& t : tri.triangles) {
    std::array<std::array<std::int64_t, 2>, 3> p;
    for (int c = 0; c < 3; ++c) {
      const auto& q = tri.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(c)])];
      p[static_cast<std::size_t>(c)] = {q.gx, q.gy};
    }
    if (covers_nodata(mask, p)) continue;
    kept.push_back(t);
    for (int k : t) renumber[static_cast<std::size_t>(k)] = 0;
  }
  const std::size_t dropped = tri.triangles.size() - kept.size();
  if (dropped == 0) return 0;
  std::vector<TileTriangulation::Vertex> vertices;
  for (std::size_t k = 0; k < tri.vertices.size(); ++k)
    if (renumber[k] == 0) {
      renumber[k] = static_cast<int>(vertices.size());
      vertices.push_back(tri.vertices[k]);
    }
  for (auto& t : kept)
    for (int& k : t) k = renumber[static_cast<std::size_t>(k)];
  tri.vertices = std::move(vertices);
  tri.triangles = std::move(kept);
  return dropped;
}

}  // namespace fest::terrainlod
