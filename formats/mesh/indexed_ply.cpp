#include "formats/mesh/indexed_ply.hpp"

#include <cstring>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::formats {

std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const std::size_t n = xyz.size() / 3;
  const std::uint16_t probe = 1;
  unsigned char low;
  std::memcpy(&low, &probe, 1);
  if (low != 1) throw io_error("write_indexed_ply: this writer needs a little-endian machine");
  std::string out = fmt::format(
      "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      n, triangles.size());
  const std::size_t header = out.size();
  out.resize(header + xyz.size() * 4 + triangles.size() * 13);
  char* p = out.data() + header;
  std::memcpy(p, xyz.data(), xyz.size() * 4);
  p += xyz.size() * 4;
  for (const auto& t : triangles) {
    *p++ = 3;
    for (std::uint32_t v : t) {
      if (v >= n) throw bad_input("triangle vertex {} out of range ({} vertices)", v, n);
      const auto i = static_cast<std::int32_t>(v);
      std::memcpy(p, &i, 4);
      p += 4;
    }
  }
  return out;
}

}  // namespace fest::formats
