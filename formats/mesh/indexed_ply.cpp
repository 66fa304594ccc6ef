#include "formats/mesh/indexed_ply.hpp"

#include <cstring>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::formats {

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
  char* p = buffer_.data() + header_ + vertices * 12;
  for (const auto& t : triangles) {
    *p++ = 3;
    for (std::uint32_t v : t) {
      if (v >= vertices) throw bad_input("triangle vertex {} out of range ({} vertices)", v, vertices);
      const auto i = static_cast<std::int32_t>(v);
      std::memcpy(p, &i, 4);
      p += 4;
    }
  }
}

std::string_view IndexedPlyEncoder::encode(const float* xyz) {
  std::memcpy(buffer_.data() + header_, xyz, vertices_ * 12);
  return buffer_;
}

std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  IndexedPlyEncoder encoder(xyz.size() / 3, triangles);
  return std::string(encoder.encode(xyz.data()));
}

}  // namespace fest::formats
