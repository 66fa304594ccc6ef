#include "formats/mesh/ply_header.hpp"
#include "core/quote.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/mesh/text_cursor.hpp"

namespace fest::formats::mesh_detail {

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::int8: case PlyType::uint8: return 1;
    case PlyType::int16: case PlyType::uint16: return 2;
    case PlyType::int32: case PlyType::uint32: case PlyType::float32: return 4;
    case PlyType::float64: return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) { return type != PlyType::float32 && type != PlyType::float64; }

const char* ply_type_name(PlyType type) {
  switch (type) {
    case PlyType::int8: return "char";
    case PlyType::uint8: return "uchar";
    case PlyType::int16: return "short";
    case PlyType::uint16: return "ushort";
    case PlyType::int32: return "int";
    case PlyType::uint32: return "uint";
    case PlyType::float32: return "float";
    case PlyType::float64: return "double";
  }
  return "?";
}

std::size_t PlyElement::min_binary_size() const {
  std::size_t size = 0;
  for (const PlyProperty& p : properties) size += p.is_list ? ply_type_size(p.count_type) : ply_type_size(p.type);
  return size;
}

bool PlyElement::fixed_size() const {
  for (const PlyProperty& p : properties)
    if (p.is_list) return false;
  return true;
}

namespace {

bool type_from_name(std::string_view name, PlyType& type) {
  struct Entry { const char* name; PlyType type; };
  static const Entry entries[] = {
      {"char", PlyType::int8},     {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
      {"uint8", PlyType::uint8},   {"short", PlyType::int16},     {"int16", PlyType::int16},
      {"ushort", PlyType::uint16}, {"uint16", PlyType::uint16},   {"int", PlyType::int32},
      {"int32", PlyType::int32},   {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
      {"float", PlyType::float32}, {"float32", PlyType::float32}, {"double", PlyType::float64},
      {"float64", PlyType::float64},
  };
  const Entry* e = find_named(entries, name);
  if (e) type = e->type;
  return e != nullptr;
}

// a * b, or false on overflow.
bool checked_mul(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
  if (a != 0 && b > UINT64_MAX / a) return false;
  out = a * b;
  return true;
}

void check_sizes(const PlyHeader& header, std::size_t body_size) {
  // Binary: every instance needs min_binary_size() bytes; when no element has a list
  // the sum must match the body exactly. Ascii: every property needs a token of at
  // least one character plus a separator, so n tokens need 2n - 1 bytes.
  const bool binary = header.encoding != PlyEncoding::ascii;
  std::uint64_t needed = 0;
  bool all_fixed = true;
  for (const PlyElement& e : header.elements) {
    // An element without properties takes no bytes, so the body cannot bound its count,
    // and a reader would loop over instances that hold nothing (fuzz_radiosity_scene: a
    // propertyless vertex element of 6.7e12 instances, 38 s per input before the fix).
    if (e.properties.empty() && e.count > 0)
      throw bad_input("PLY header: element {} declares {} instances but no properties", fest::quoted_bytes(e.name), e.count);
    std::uint64_t per_instance = binary ? e.min_binary_size() : 2 * e.properties.size();
    std::uint64_t total = 0;
    if (!checked_mul(e.count, per_instance, total) || total > body_size + 1 || needed + total > body_size + 1) {
      throw bad_input("PLY header: element {} count {} exceeds what the {} bytes after the header can hold", fest::quoted_bytes(e.name),
                      e.count, body_size);
    }
    needed += total;
    all_fixed = all_fixed && e.fixed_size();
  }
  if (binary) {
    if (needed > body_size)
      throw bad_input("PLY: binary body needs at least {} bytes, the file has {} after the header", needed, body_size);
    if (all_fixed && needed != body_size)
      throw bad_input("PLY: binary body should be exactly {} bytes, the file has {} after the header", needed,
                      body_size);
  }
}

}  // namespace

PlyHeader parse_ply_header(std::string_view bytes) {
  PlyHeader header;
  TextCursor cursor(bytes);
  std::string_view line;
  if (!cursor.next_line(line) || line != "ply") throw bad_input("PLY header: first line is not \"ply\"");
  bool have_format = false;
  bool ended = false;
  std::size_t line_no = 1;
  while (!ended && cursor.next_line(line)) {
    ++line_no;
    LineTokens tokens(line);
    std::string_view keyword = tokens.next();
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      ended = true;
    } else if (keyword == "format") {
      std::string_view encoding = tokens.next();
      if (encoding == "ascii") header.encoding = PlyEncoding::ascii;
      else if (encoding == "binary_little_endian") header.encoding = PlyEncoding::binary_little_endian;
      else if (encoding == "binary_big_endian") header.encoding = PlyEncoding::binary_big_endian;
      else throw bad_input("PLY header line {}: unknown format \"{}\"", line_no, fest::quoted_bytes(encoding));
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(tokens.next());
      std::string_view count = tokens.next();
      if (element.name.empty() || !parse_uint64(count, element.count))
        throw bad_input("PLY header line {}: element count \"{}\" is not a non-negative integer", line_no, fest::quoted_bytes(count));
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) throw bad_input("PLY header line {}: property before any element", line_no);
      PlyProperty property;
      std::string_view type = tokens.next();
      if (type == "list") {
        property.is_list = true;
        std::string_view count_type = tokens.next();
        if (!type_from_name(count_type, property.count_type) || !ply_type_is_integer(property.count_type))
          throw bad_input("PLY header line {}: list length type \"{}\" is not an integer type", line_no, fest::quoted_bytes(count_type));
        type = tokens.next();
      }
      if (!type_from_name(type, property.type))
        throw bad_input("PLY header line {}: unknown property type \"{}\"", line_no, fest::quoted_bytes(type));
      property.name = std::string(tokens.next());
      if (property.name.empty()) throw bad_input("PLY header line {}: property without a name", line_no);
      header.elements.back().properties.push_back(std::move(property));
    } else {
      // Not a PLY keyword: some writers put free text in the header without `comment`.
      // Read it as a comment and say so, rather than refuse a file other readers open.
      std::string text(line.substr(0, 60));
      if (line.size() > 60) text += "...";
      header.warnings.push_back(
          fmt::format("PLY header line {}: \"{}\" has no PLY keyword; read as a comment", line_no, fest::quoted_bytes(text)));
    }
  }
  if (!ended) throw bad_input("PLY header: no end_header line (truncated header?)");
  if (!have_format) throw bad_input("PLY header: no format line");
  header.body_offset = cursor.position();
  check_sizes(header, bytes.size() - header.body_offset);
  return header;
}

}  // namespace fest::formats::mesh_detail
