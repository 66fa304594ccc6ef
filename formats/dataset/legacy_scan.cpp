#include "formats/dataset/legacy_scan.hpp"
#include "core/quote.hpp"

#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>

#include "lib/core/error.hpp"

namespace fest::formats::detail {
namespace {

constexpr size_t kMaxToken = 255;           // vtkDataReader::ReadString reads at most this
constexpr uint64_t kMaxComponents = 1u << 24;  // far beyond any real attribute
constexpr int kPolyhedron = 42;             // VTK_POLYHEDRON: needs face streams legacy lacks
constexpr int kNumberOfCellTypes = 256;     // cell types are stored as unsigned char

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

bool has_prefix(const std::string& s, std::string_view prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

bool is_hex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// How vtkDataReader::ReadArray stores a type name (it matches prefixes, in this order).
struct ValueType {
  enum Kind { unsupported, bit, fixed, string, variant } kind = unsupported;
  uint64_t size = 0;   // bytes per value in binary files, for `fixed`
  bool real = false;   // ASCII values are floating point, not integers
};

ValueType classify(const std::string& type) {
  if (has_prefix(type, "bit")) return {ValueType::bit, 0};
  if (type == "char" || type == "signed_char") return {ValueType::fixed, 1};
  if (has_prefix(type, "unsigned_char")) return {ValueType::fixed, 1};
  if (has_prefix(type, "short")) return {ValueType::fixed, 2};
  if (has_prefix(type, "unsigned_short")) return {ValueType::fixed, 2};
  if (has_prefix(type, "vtkidtype")) return {ValueType::fixed, 4};
  if (has_prefix(type, "int")) return {ValueType::fixed, 4};
  if (has_prefix(type, "unsigned_int")) return {ValueType::fixed, 4};
  if (has_prefix(type, "long")) return {ValueType::fixed, sizeof(long)};
  if (has_prefix(type, "unsigned_long")) return {ValueType::fixed, sizeof(unsigned long)};
  if (has_prefix(type, "vtktypeint64")) return {ValueType::fixed, 8};
  if (has_prefix(type, "vtktypeuint64")) return {ValueType::fixed, 8};
  if (has_prefix(type, "float")) return {ValueType::fixed, 4, true};
  if (has_prefix(type, "double")) return {ValueType::fixed, 8, true};
  if (has_prefix(type, "string") || has_prefix(type, "utf8_string")) return {ValueType::string, 0};
  if (has_prefix(type, "variant")) return {ValueType::variant, 0};
  return {};
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Whether `operator>>` reads all of `t` as an integer (or, if `real`, a floating
// point number). When it reads only part of a word, or fails, vtkDataReader carries
// on and takes the rest for the next keyword ("POINT_DATA" inside an array that is
// one value short), so the scan must stop exactly there too.
bool is_number(std::string_view t, bool real) {
  size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  size_t digits = 0;
  while (i < t.size() && is_digit(t[i])) ++i, ++digits;
  if (!real) return digits > 0 && digits <= 20 && i == t.size();
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && is_digit(t[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    size_t exponent = 0;
    while (i < t.size() && is_digit(t[i])) ++i, ++exponent;
    if (exponent == 0) return false;
  }
  return i == t.size();
}

class LegacyWalker {
 public:
  explicit LegacyWalker(std::string_view bytes) : s_(bytes) {}

  LegacyHeader run() {
    read_header();
    dataset_sections();
    return header_;
  }

 private:
  template <typename... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> f, Args&&... args) const {
    throw bad_input("legacy VTK: {} (byte {})", fmt::format(f, std::forward<Args>(args)...), pos_);
  }

  size_t remaining() const { return s_.size() - pos_; }

  std::string_view line() {
    size_t end = s_.find('\n', pos_);
    if (end == std::string_view::npos) end = s_.size();
    std::string_view text = s_.substr(pos_, end - pos_);
    pos_ = end < s_.size() ? end + 1 : end;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
  }

  std::string_view token() {
    while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
    size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    if (pos_ - start > kMaxToken) {
      pos_ = start;
      fail("a word of {} characters where VTK reads at most {}", pos_ - start, kMaxToken);
    }
    return s_.substr(start, pos_ - start);
  }

  std::string keyword(const char* what) {
    std::string_view t = token();
    if (t.empty()) fail("file ends where {} was expected", what);
    return lower(t);
  }

  std::optional<std::string> peek_keyword() {
    size_t saved = pos_;
    std::string_view t = token();
    pos_ = saved;
    if (t.empty()) return std::nullopt;
    return lower(t);
  }

  uint64_t count(const char* what) { return parse_count(token(), what); }

  uint64_t parse_count(std::string_view t, const char* what) {
    if (t.empty()) fail("file ends where the {} was expected", what);
    std::string_view digits = t;
    if (digits.front() == '+') digits.remove_prefix(1);
    if (digits.empty() || digits.size() > 18) fail("{} '{}' is not a count", what, fest::quoted_bytes(t));
    uint64_t value = 0;
    for (char c : digits) {
      if (c < '0' || c > '9') fail("{} '{}' is not a count", what, fest::quoted_bytes(t));
      value = value * 10 + static_cast<uint64_t>(c - '0');
    }
    return value;
  }

  int64_t integer(const char* what) {
    std::string_view t = token();
    if (t.empty()) fail("file ends inside the {}", what);
    bool negative = t.front() == '-';
    std::string_view digits = t;
    if (negative || t.front() == '+') digits.remove_prefix(1);
    if (digits.empty() || digits.size() > 10) fail("{} value '{}' is not an integer", what, fest::quoted_bytes(t));
    int64_t value = 0;
    for (char c : digits) {
      if (c < '0' || c > '9') fail("{} value '{}' is not an integer", what, fest::quoted_bytes(t));
      value = value * 10 + (c - '0');
    }
    return negative ? -value : value;
  }

  // Attribute names are %-encoded; vtkDataReader::DecodeString reads past the end of
  // a name whose '%' lacks its two hex digits.
  void name(const char* what) {
    std::string_view t = token();
    if (t.empty()) fail("file ends where the {} name was expected", what);
    for (size_t i = 0; i < t.size(); ++i)
      if (t[i] == '%' && (i + 2 >= t.size() || !is_hex(t[i + 1]) || !is_hex(t[i + 2])))
        fail("{} name '{}' has a '%' without two hex digits", what, fest::quoted_bytes(t));
  }

  uint64_t components(const char* what) { return parse_components(token(), what); }

  uint64_t parse_components(std::string_view t, const char* what) {
    uint64_t n = parse_count(t, what);
    if (n < 1 || n > kMaxComponents) fail("{} of {} is out of range", what, n);
    return n;
  }

  // Binary data starts on the line after its header; VTK skips the rest of that line
  // with getline(line, 256).
  void skip_to_next_line() {
    size_t end = s_.find('\n', pos_);
    if (end == std::string_view::npos) {
      pos_ = s_.size();
      return;
    }
    if (end - pos_ >= 256) fail("binary data must start on the line after its header");
    pos_ = end + 1;
  }

  void need_bytes(uint64_t n, const char* what) {
    if (n > remaining()) fail("{} needs {} bytes, only {} remain", what, n, remaining());
  }

  uint64_t big_endian(size_t bytes) {
    uint64_t v = 0;
    for (size_t i = 0; i < bytes; ++i) v = (v << 8) | static_cast<unsigned char>(s_[pos_ + i]);
    pos_ += bytes;
    return v;
  }

  // Guards every count before it is multiplied: an ASCII value takes at least two
  // bytes (one digit and a separator), a binary one at least one bit.
  uint64_t values(uint64_t tuples, uint64_t comps, const char* what) {
    return values(tuples, comps, what, header_.binary ? remaining() * 8 + 8 : remaining() / 2 + 1);
  }

  uint64_t values(uint64_t tuples, uint64_t comps, const char* what, uint64_t limit) {
    if (comps != 0 && tuples > limit / comps)
      fail("{} declares {} x {} values, more than the {} remaining bytes can hold", what, tuples, comps,
           remaining());
    return tuples * comps;
  }

  void skip_ascii_values(uint64_t n, const char* what, bool real) {
    for (uint64_t i = 0; i < n; ++i) {
      std::string_view t = token();
      if (t.empty()) fail("{} ends after {} of {} values", what, i, n);
      if (!is_number(t, real)) {
        pos_ -= t.size();
        fail("{} value {} of {} is '{}', not a number", what, i, n, fest::quoted_bytes(t, 40));
      }
    }
  }

  void skip_ascii_words(uint64_t n, const char* what) {
    for (uint64_t i = 0; i < n; ++i)
      if (token().empty()) fail("{} ends after {} of {} values", what, i, n);
  }

  void array(const std::string& type, uint64_t tuples, uint64_t comps, const char* what) {
    ValueType vt = classify(type);
    // An ASCII string takes a line of at least one byte, not two.
    uint64_t n = vt.kind == ValueType::string ? values(tuples, comps, what, remaining() + 1)
                                              : values(tuples, comps, what);
    switch (vt.kind) {
      case ValueType::unsupported:
        fail("{} has unsupported data type '{}'", what, fest::quoted_bytes(type));
      case ValueType::bit:
      case ValueType::fixed:
        if (header_.binary) {
          skip_to_next_line();
          uint64_t bytes = vt.kind == ValueType::bit ? (n + 7) / 8 : n * vt.size;
          need_bytes(bytes, what);
          pos_ += bytes;
        } else {
          skip_ascii_values(n, what, vt.real);
        }
        break;
      case ValueType::string:
        strings(n, what);
        break;
      case ValueType::variant:
        skip_ascii_words(values(n, 2, what), what);
        break;
    }
    metadata();
  }

  void strings(uint64_t n, const char* what) {
    skip_to_next_line();
    for (uint64_t i = 0; i < n; ++i) {
      if (pos_ >= s_.size()) fail("{} ends after {} of {} strings", what, i, n);
      if (!header_.binary) {
        line();
        continue;
      }
      // vtkDataReader's length prefix: the top two bits of the first byte say how wide.
      unsigned top = static_cast<unsigned char>(s_[pos_]) >> 6;
      size_t width = top == 3 ? 1 : top == 2 ? 2 : top == 1 ? 4 : 8;
      need_bytes(width, what);
      uint64_t length = big_endian(width);
      if (width < 8) length &= (uint64_t{1} << (8 * width - 2)) - 1;
      need_bytes(length, what);
      pos_ += length;
    }
  }

  // Optional "METADATA" block after an array, ended by a blank line.
  void metadata() {
    std::optional<std::string> next = peek_keyword();
    if (!next || !has_prefix(*next, "metadata")) return;
    token();
    line();
    while (pos_ < s_.size() && !line().empty()) {
    }
  }

  void read_header() {
    if (s_.empty()) fail("empty input");
    std::string_view first = line();
    constexpr std::string_view magic = "# vtk DataFile Version";
    if (first.substr(0, magic.size()) != magic) fail("first line is not '{} x.y'", magic);
    std::string version(first.substr(magic.size(), 32));
    if (std::sscanf(version.c_str(), "%d.%d", &header_.major_version, &header_.minor_version) != 2)
      fail("cannot read the file version in '{}'", fest::quoted_bytes(first, 64));
    if (pos_ >= s_.size()) fail("file ends before the title line");
    line();  // title
    std::string type = keyword("ASCII or BINARY");
    if (has_prefix(type, "ascii")) {
      header_.binary = false;
    } else if (has_prefix(type, "binary")) {
      header_.binary = true;
    } else {
      fail("third line says '{}', not ASCII or BINARY", fest::quoted_bytes(type));
    }
    std::string dataset = keyword("DATASET");
    if (!has_prefix(dataset, "dataset")) fail("expected DATASET, found '{}'", fest::quoted_bytes(dataset));
    header_.dataset_type = keyword("dataset type");
    for (const char* known : {"polydata", "structured_points", "structured_grid", "rectilinear_grid",
                              "unstructured_grid"})
      if (has_prefix(header_.dataset_type, known)) {
        header_.dataset_type = known;
        return;
      }
    fail("unknown dataset type '{}'", fest::quoted_bytes(header_.dataset_type));
  }

  // The grid readers first run a metadata pass that scans tokens for DIMENSIONS and
  // treats any word starting "field" on the way as field data, dereferencing a null
  // pointer when that fails (VTK 9.1). So grids must state DIMENSIONS before
  // anything but field data and geometry numbers.
  bool allowed_before_dimensions(const std::string& k) const {
    return has_prefix(k, "field") || has_prefix(k, "dimensions") || has_prefix(k, "spacing") ||
           has_prefix(k, "aspect_ratio") || has_prefix(k, "origin");
  }

  void dataset_sections() {
    const bool grid = header_.dataset_type != "polydata" && header_.dataset_type != "unstructured_grid";
    bool seen_dimensions = false;
    for (;;) {
      std::optional<std::string> next = peek_keyword();
      if (!next) {
        if (grid && !seen_dimensions) fail("{} without DIMENSIONS", header_.dataset_type);
        return;
      }
      const std::string& k = *next;
      if (grid && !seen_dimensions && !allowed_before_dimensions(k))
        fail("{}: DIMENSIONS must come before '{}'", fest::quoted_bytes(header_.dataset_type), fest::quoted_bytes(k));
      if (has_prefix(k, "dimensions")) seen_dimensions = true;
      token();
      if (has_prefix(k, "field")) {
        field_data();
      } else if (has_prefix(k, "points")) {
        uint64_t n = count("point count");
        array(keyword("point type"), n, 3, "POINTS");
      } else if (has_prefix(k, "cells") || has_prefix(k, "vertices") || has_prefix(k, "lines") ||
                 has_prefix(k, "polygons") || has_prefix(k, "triangle_strips")) {
        cells(k.c_str());
      } else if (has_prefix(k, "cell_types")) {
        cell_types();
      } else if (has_prefix(k, "dimensions")) {
        uint64_t product = 1;
        for (int axis = 0; axis < 3; ++axis) {
          uint64_t d = count("dimension");
          if (d > static_cast<uint64_t>(std::numeric_limits<int>::max())) fail("dimension {} is out of range", d);
          header_.dimensions[axis] = static_cast<int>(d);
          product *= d;
          if (product > (uint64_t{1} << 40)) fail("DIMENSIONS describe more than 2^40 points");
        }
      } else if (has_prefix(k, "spacing") || has_prefix(k, "aspect_ratio") || has_prefix(k, "origin")) {
        skip_ascii_values(3, "SPACING or ORIGIN", true);
      } else if (has_prefix(k, "x_coordinates") || has_prefix(k, "y_coordinates") ||
                 has_prefix(k, "z_coordinates")) {
        uint64_t n = count("coordinate count");
        array(keyword("coordinate type"), n, 1, "coordinates");
      } else if (has_prefix(k, "point_data") || has_prefix(k, "cell_data")) {
        attributes(count("attribute count"));
        return;
      } else {
        return;  // not ours to judge: VTK reports the unknown keyword
      }
    }
  }

  void cells(const char* what) {
    if (header_.major_version >= 5) {
      uint64_t offsets = count("offsets count");
      uint64_t connectivity = count("connectivity count");
      if (offsets < 1) {
        declare_cells(0);
        return;
      }
      if (keyword("OFFSETS") != "offsets") fail("{} must be followed by OFFSETS", what);
      array(keyword("offsets type"), offsets, 1, "OFFSETS");
      if (keyword("CONNECTIVITY") != "connectivity") fail("{} must be followed by CONNECTIVITY", what);
      array(keyword("connectivity type"), connectivity, 1, "CONNECTIVITY");
      declare_cells(offsets - 1);
      return;
    }
    // Up to version 4: "n size" then, per cell, its point count and its point ids.
    uint64_t n = count("cell count");
    uint64_t size = count("cell list size");
    values(size, 1, what);
    if (n > size) fail("{} declares {} cells in a list of {} values", what, n, size);
    if (header_.binary) {
      skip_to_next_line();
      need_bytes(size * 4, what);
    }
    uint64_t used = 0;
    for (uint64_t cell = 0; cell < n; ++cell) {
      int64_t points = header_.binary ? static_cast<int32_t>(big_endian(4)) : integer("cell list");
      if (points < 0 || static_cast<uint64_t>(points) + 1 > size - used)
        fail("{}: cell {} with {} points overruns the list of {} values", what, cell, points, size);
      used += 1 + static_cast<uint64_t>(points);
      if (header_.binary) {
        pos_ += 4 * static_cast<size_t>(points);
      } else {
        for (int64_t i = 0; i < points; ++i) integer("cell list");
      }
    }
    if (used != size) fail("{}: {} cells use {} values of the {} declared", what, n, used, size);
    declare_cells(n);
  }

  void declare_cells(uint64_t n) {
    cells_ = n;
    if (cell_types_ && *cell_types_ != n) fail("CELL_TYPES lists {} types for {} cells", *cell_types_, n);
  }

  void cell_types() {
    uint64_t n = count("cell type count");
    values(n, 1, "CELL_TYPES");
    if (header_.binary) {
      skip_to_next_line();
      need_bytes(n * 4, "CELL_TYPES");
    }
    for (uint64_t i = 0; i < n; ++i) {
      int64_t type = header_.binary ? static_cast<int32_t>(big_endian(4)) : integer("CELL_TYPES");
      if (type < 0 || type >= kNumberOfCellTypes) fail("cell {} has type {}, not a VTK cell type", i, type);
      if (type == kPolyhedron) fail("cell {} is a polyhedron, which legacy files cannot describe", i);
    }
    cell_types_ = n;
    if (cells_ && *cells_ != n) fail("CELL_TYPES lists {} types for {} cells", n, *cells_);
  }

  void field_data() {
    name("field");
    uint64_t arrays = count("field array count");
    values(arrays, 4, "FIELD");  // each array header takes at least "a 1 0 int"
    for (uint64_t i = 0; i < arrays; ++i) {
      std::optional<std::string> next = peek_keyword();
      if (next && *next == "null_array") {
        token();
        continue;
      }
      name("field array");
      uint64_t comps = components("field array component count");
      uint64_t tuples = count("field array tuple count");
      array(keyword("field array type"), tuples, comps, "FIELD array");
    }
  }

  void attributes(uint64_t n) {
    for (;;) {
      std::optional<std::string> next = peek_keyword();
      if (!next) return;
      const std::string k = *next;
      token();
      if (has_prefix(k, "scalars")) {
        name("SCALARS");
        std::string type = keyword("SCALARS type");
        std::string_view raw = token();
        std::string key = lower(raw);
        uint64_t comps = 1;
        if (key != "lookup_table") {
          comps = parse_components(raw, "SCALARS component count");
          key = keyword("LOOKUP_TABLE");
        }
        if (key != "lookup_table") fail("SCALARS must name a LOOKUP_TABLE, found '{}'", fest::quoted_bytes(key));
        name("lookup table");
        array(type, n, comps, "SCALARS");
      } else if (has_prefix(k, "vectors") || has_prefix(k, "normals")) {
        name("VECTORS");
        array(keyword("VECTORS type"), n, 3, "VECTORS");
      } else if (has_prefix(k, "tensors6")) {
        name("TENSORS6");
        array(keyword("TENSORS6 type"), n, 6, "TENSORS6");
      } else if (has_prefix(k, "tensors")) {
        name("TENSORS");
        array(keyword("TENSORS type"), n, 9, "TENSORS");
      } else if (has_prefix(k, "texture_coordinates")) {
        name("TEXTURE_COORDINATES");
        uint64_t dim = count("texture dimension");
        if (dim < 1 || dim > 3) fail("texture coordinates of dimension {}", dim);
        array(keyword("TEXTURE_COORDINATES type"), n, dim, "TEXTURE_COORDINATES");
      } else if (has_prefix(k, "global_ids") || has_prefix(k, "pedigree_ids") || has_prefix(k, "edge_flags")) {
        name("id");
        array(keyword("id type"), n, 1, "ids");
      } else if (has_prefix(k, "color_scalars")) {
        name("COLOR_SCALARS");
        uint64_t comps = components("COLOR_SCALARS component count");
        array(header_.binary ? "unsigned_char" : "float", n, comps, "COLOR_SCALARS");
      } else if (has_prefix(k, "lookup_table")) {
        name("LOOKUP_TABLE");
        uint64_t entries = count("lookup table size");
        if (header_.binary) {
          values(entries, 4, "LOOKUP_TABLE");
          skip_to_next_line();
          need_bytes(entries * 4, "LOOKUP_TABLE");
          pos_ += entries * 4;
        } else {
          skip_ascii_values(values(entries, 4, "LOOKUP_TABLE"), "LOOKUP_TABLE", true);
        }
      } else if (has_prefix(k, "field")) {
        field_data();
      } else if (has_prefix(k, "point_data") || has_prefix(k, "cell_data")) {
        n = count("attribute count");
      } else {
        return;  // VTK reports the unknown keyword
      }
    }
  }

  std::string_view s_;
  size_t pos_ = 0;
  LegacyHeader header_;
  std::optional<uint64_t> cells_;
  std::optional<uint64_t> cell_types_;
};

}  // namespace

LegacyHeader scan_legacy_vtk(std::string_view bytes) { return LegacyWalker(bytes).run(); }

}  // namespace fest::formats::detail
