#pragma once
// The values of a PLY body, one at a time, as both PLY readers walk it: the mesh reader
// (ply_reader.cpp) and the attributed reader (attributed_ply.cpp). A source per encoding,
// chosen once by with_ply_source() so that the element loops are compiled for each
// (a branch on the encoding per value costs more than the value).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <utility>

#include "formats/mesh/ply_header.hpp"
#include "formats/mesh/text_cursor.hpp"

namespace fest::formats::mesh_detail {

class PlyBinarySource {
 public:
  PlyBinarySource(std::string_view bytes, std::size_t start, bool big_endian)
      : bytes_(bytes), pos_(start), big_endian_(big_endian) {}

  // The next value as a double; false when the bytes end first.
  bool read(PlyType type, double& out) {
    const std::size_t size = ply_type_size(type);
    if (bytes_.size() - pos_ < size) return false;
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, size);
    pos_ += size;
    if (big_endian_ != host_is_big_endian()) {
      for (std::size_t i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    }
    switch (type) {
      case PlyType::int8: { std::int8_t v; std::memcpy(&v, raw, 1); out = v; break; }
      case PlyType::uint8: out = raw[0]; break;
      case PlyType::int16: { std::int16_t v; std::memcpy(&v, raw, 2); out = v; break; }
      case PlyType::uint16: { std::uint16_t v; std::memcpy(&v, raw, 2); out = v; break; }
      case PlyType::int32: { std::int32_t v; std::memcpy(&v, raw, 4); out = v; break; }
      case PlyType::uint32: { std::uint32_t v; std::memcpy(&v, raw, 4); out = v; break; }
      case PlyType::float32: { float v; std::memcpy(&v, raw, 4); out = static_cast<double>(v); break; }
      case PlyType::float64: std::memcpy(&out, raw, 8); break;
    }
    return true;
  }
  // Whether `count` items of `type` can still be there (checked before a list loop).
  bool can_hold(std::uint64_t count, PlyType type) const {
    return count <= (bytes_.size() - pos_) / ply_type_size(type);
  }
  // Binary files must end exactly after the last element.
  std::size_t trailing() const { return bytes_.size() - pos_; }

 private:
  static bool host_is_big_endian() {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }
  std::string_view bytes_;
  std::size_t pos_;
  bool big_endian_;
};

class PlyAsciiSource {
 public:
  PlyAsciiSource(std::string_view bytes, std::size_t start) : cursor_(bytes, start) {}

  // The next token as a double; false when it is missing, not a number, or not an
  // integer where the property's type is one.
  bool read(PlyType type, double& out) {
    std::string_view token = cursor_.next_token();
    if (!parse_double(token, out)) return false;
    return !ply_type_is_integer(type) || std::floor(out) == out;
  }
  // Every token needs a character and a separator.
  bool can_hold(std::uint64_t count, PlyType) const { return count <= cursor_.remaining() / 2 + 1; }
  // Trailing whitespace is fine in a text file; anything else is not.
  std::size_t trailing() {
    cursor_.skip_whitespace();
    return cursor_.remaining();
  }

 private:
  TextCursor cursor_;
};

// Calls read_body(source) with the source for the header's encoding, positioned at the
// first byte of the body, and returns what it returns.
template <class ReadBody>
decltype(auto) with_ply_source(std::string_view bytes, const PlyHeader& header, ReadBody&& read_body) {
  if (header.encoding == PlyEncoding::ascii) {
    PlyAsciiSource source(bytes, header.body_offset);
    return read_body(source);
  }
  PlyBinarySource source(bytes, header.body_offset, header.encoding == PlyEncoding::binary_big_endian);
  return read_body(source);
}

}  // namespace fest::formats::mesh_detail
