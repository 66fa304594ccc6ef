#include "terrainlod/quantized_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fest::terrainlod {
namespace {

template <typename T>
void put(std::string& s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));  // little-endian hosts (as everywhere fest runs)
  s.append(b, sizeof(T));
}

// Zig-zag: 0, -1, 1, -2, ... -> 0, 1, 2, 3, ...; the shift is done unsigned (shifting a
// negative int left is undefined before C++20).
std::uint16_t zz16(int v) {
  return static_cast<std::uint16_t>((static_cast<std::uint32_t>(v) << 1) ^ static_cast<std::uint32_t>(v >> 31));
}

}  // namespace

std::string encode_quantized_mesh(const TileTriangulation& input, const QmFrame& f) {
  // High-water-mark coding needs vertices numbered in order of first use.
  TileTriangulation tri;
  std::vector<int> renum(input.vertices.size(), -1);
  for (const auto& t : input.triangles) {
    std::array<int, 3> r{};
    for (int k = 0; k < 3; ++k) {
      int& id = renum[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      if (id < 0) {
        id = static_cast<int>(tri.vertices.size());
        tri.vertices.push_back(input.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])]);
      }
      r[static_cast<std::size_t>(k)] = id;
    }
    tri.triangles.push_back(r);
  }
  const std::size_t n = tri.vertices.size();
  double zlo = 0, zhi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    zlo = i ? std::min(zlo, tri.vertices[i].z) : tri.vertices[i].z;
    zhi = i ? std::max(zhi, tri.vertices[i].z) : tri.vertices[i].z;
  }
  std::vector<int> u(n), v(n), h(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = tri.vertices[i];
    u[i] = static_cast<int>(std::llround(static_cast<double>(p.gx - f.gx0) * 32767.0 / static_cast<double>(f.cells)));
    v[i] = static_cast<int>(std::llround(static_cast<double>(p.gy - f.gy0) * 32767.0 / static_cast<double>(f.cells)));
    h[i] = zhi > zlo ? static_cast<int>(std::llround((p.z - zlo) / (zhi - zlo) * 32767.0)) : 0;
  }
  const double wx0 = f.origin_x + static_cast<double>(f.gx0) * f.dx, wy0 = f.origin_y + static_cast<double>(f.gy0) * f.dy;
  const double wx1 = wx0 + static_cast<double>(f.cells) * f.dx, wy1 = wy0 + static_cast<double>(f.cells) * f.dy;
  const double cx = (wx0 + wx1) / 2, cy = (wy0 + wy1) / 2, cz = (zlo + zhi) / 2;
  std::string out;
  put(out, cx), put(out, cy), put(out, cz);
  put(out, static_cast<float>(zlo)), put(out, static_cast<float>(zhi));
  put(out, cx), put(out, cy), put(out, cz);
  put(out, 0.5 * std::sqrt((wx1 - wx0) * (wx1 - wx0) + (wy1 - wy0) * (wy1 - wy0) + (zhi - zlo) * (zhi - zlo)));
  put(out, cx), put(out, cy), put(out, zhi);  // horizon occlusion point: not meaningful off the globe
  put(out, static_cast<std::uint32_t>(n));
  for (const auto* a : {&u, &v, &h}) {
    int prev = 0;
    for (int x : *a) {
      put(out, zz16(x - prev));
      prev = x;
    }
  }
  const bool wide = n > 65536;
  if (wide)
    while (out.size() % 4) out.push_back('\0');
  put(out, static_cast<std::uint32_t>(tri.triangles.size()));
  std::uint32_t highest = 0;
  for (const auto& t : tri.triangles)
    for (int idx : t) {
      const std::uint32_t code = highest - static_cast<std::uint32_t>(idx);
      if (wide) put(out, code);
      else put(out, static_cast<std::uint16_t>(code));
      if (code == 0) ++highest;
    }
  // Edge lists: vertices on the west (u = 0), south (v = 0), east, north borders.
  for (int side = 0; side < 4; ++side) {
    std::vector<std::uint32_t> list;
    for (std::size_t i = 0; i < n; ++i)
      if ((side == 0 && u[i] == 0) || (side == 1 && v[i] == 0) || (side == 2 && u[i] == 32767) || (side == 3 && v[i] == 32767))
        list.push_back(static_cast<std::uint32_t>(i));
    put(out, static_cast<std::uint32_t>(list.size()));
    for (auto i : list) {
      if (wide) put(out, i);
      else put(out, static_cast<std::uint16_t>(i));
    }
  }
  return out;
}

}  // namespace fest::terrainlod
