#pragma once
// The PLY header, parsed by fest itself so that element counts can be checked against
// the bytes that follow before anything is allocated (see ply_header.cpp).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fest::formats::mesh_detail {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

std::size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);
const char* ply_type_name(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::float32;  // the item type for a list
  bool is_list = false;
  PlyType count_type = PlyType::uint8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  // Bytes one instance needs at least (binary), or tokens it needs at least (ascii):
  // a list counts only its length field / one token.
  std::size_t min_binary_size() const;
  bool fixed_size() const;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  // first byte after "end_header\n"
  // Lines read leniently: a line that starts with no PLY keyword is read as a comment
  // (Blender 2.47 writes "Created by Blender3D ..." without `comment`).
  std::vector<std::string> warnings;
};

// Parses and validates the header: magic, format line, element and property lines,
// and that the element counts can fit in the bytes after the header (exactly, for
// binary files whose elements have no lists). Throws bad_input naming the line.
PlyHeader parse_ply_header(std::string_view bytes);

}  // namespace fest::formats::mesh_detail
