#include "formats/mesh/indexed_ply.hpp"

#include <cstring>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::formats {
namespace {

// The face element: a count byte 3 and three little-endian int32 indices per triangle,
// written from `p` on; returns the end.
char* put_triangles(char* p, const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices) {
  for (const auto& t : triangles) {
    *p++ = 3;
    for (std::uint32_t v : t) {
      if (v >= vertices) throw bad_input("triangle vertex {} out of range ({} vertices)", v, vertices);
      const auto i = static_cast<std::int32_t>(v);
      std::memcpy(p, &i, 4);
      p += 4;
    }
  }
  return p;
}

}  // namespace

IndexedPlyEncoder::IndexedPlyEncoder(std::size_t vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles)
    : vertices_(vertices) {
  const std::uint16_t probe = 1;
  unsigned char low;
  std::memcpy(&low, &probe, 1);
  if (low != 1) throw io_error("write_indexed_ply: this writer needs a little-endian machine");
  buffer_ = fmt::format(
      "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      vertices, triangles.size());
  header_ = buffer_.size();
  buffer_.resize(header_ + vertices * 12 + triangles.size() * 13);
  put_triangles(buffer_.data() + header_ + vertices * 12, triangles, vertices);
}

std::string_view IndexedPlyEncoder::encode(const float* xyz) {
  if (vertices_ > 0) std::memcpy(buffer_.data() + header_, xyz, vertices_ * 12);  // an empty mesh may pass nullptr
  return buffer_;
}

std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  IndexedPlyEncoder encoder(xyz.size() / 3, triangles);
  return std::string(encoder.encode(xyz.data()));
}

std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                              const std::vector<std::string>& scalar_names, const std::vector<std::vector<float>>& scalars) {
  const std::size_t n = xyz.size() / 3;
  if (scalar_names.size() != scalars.size()) throw bad_input("{} scalar names for {} arrays", scalar_names.size(), scalars.size());
  for (std::size_t k = 0; k < scalars.size(); ++k) {
    if (scalars[k].size() != n) throw bad_input("scalar {} has {} values for {} vertices", scalar_names[k], scalars[k].size(), n);
    const std::string& name = scalar_names[k];
    if (name.empty() || name.find_first_of(" \t\n\r") != std::string::npos)
      throw bad_input("scalar name '{}' cannot be a PLY property name", name);
  }
  std::string out = fmt::format("ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n", n);
  for (const auto& name : scalar_names) out += fmt::format("property float {}\n", name);
  out += fmt::format("element face {}\nproperty list uchar int vertex_indices\nend_header\n", triangles.size());
  const std::size_t stride = 4 * (3 + scalars.size());
  const std::size_t header = out.size();
  out.resize(header + n * stride + triangles.size() * 13);
  char* p = out.data() + header;
  for (std::size_t v = 0; v < n; ++v) {
    std::memcpy(p, &xyz[3 * v], 12);
    p += 12;
    for (const auto& s : scalars) {
      std::memcpy(p, &s[v], 4);
      p += 4;
    }
  }
  put_triangles(p, triangles, n);
  return out;
}

}  // namespace fest::formats
