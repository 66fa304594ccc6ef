#include "formats/dataset/xml_scan.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "lib/core/error.hpp"

namespace fest::formats::detail {
namespace {

constexpr uint64_t kMaxCount = uint64_t{1} << 40;       // points, cells or tuples in one piece
constexpr uint64_t kMaxComponents = uint64_t{1} << 24;
// zlib inflates at most ~1032:1; LZ4 and LZMA stay below this for real data too.
constexpr uint64_t kCompressedExpansion = 1100;
// Uncompressed: ASCII "0 " (2 bytes) becomes an 8-byte double; raw binary is 1:1.
constexpr uint64_t kPlainExpansion = 16;
constexpr uint64_t kSlack = uint64_t{1} << 20;

struct Attribute {
  std::string_view name;
  std::string_view value;
};

struct Tag {
  std::string_view name;
  std::vector<Attribute> attributes;
  bool closing = false;
  bool self_closing = false;

  std::string_view get(std::string_view key) const {
    for (const Attribute& a : attributes)
      if (a.name == key) return a.value;
    return {};
  }
  bool has(std::string_view key) const {
    for (const Attribute& a : attributes)
      if (a.name == key) return true;
    return false;
  }
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

uint64_t saturating_mul(uint64_t a, uint64_t b) {
  if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
  return a * b;
}

uint64_t saturating_add(uint64_t a, uint64_t b) { return b > UINT64_MAX - a ? UINT64_MAX : a + b; }

class XmlScanner {
 public:
  XmlScanner(std::string_view bytes, std::string_view expected, const char* format)
      : s_(bytes), expected_(expected), format_(format) {}

  XmlLimits run() {
    if (s_.empty()) throw bad_input("{}: empty input", format_);
    Tag tag;
    while (next_tag(tag)) {
      if (tag.closing) {
        if (!open_.empty()) open_.pop_back();
        continue;
      }
      // Raw appended data follows; the markup that matters is all before it.
      if (tag.name == "AppendedData") break;
      element(tag);
      if (!tag.self_closing) open_.push_back(tag.name);
    }
    if (!seen_root_) throw bad_input("{}: not a VTK XML file (no <VTKFile> element)", format_);
    uint64_t budget = saturating_add(
        saturating_mul(s_.size(), compressed_ ? kCompressedExpansion : kPlainExpansion), kSlack);
    if (declared_bytes_ > budget)
      throw bad_input("{}: the arrays declared need {} bytes, more than a {}-byte file can hold", format_,
                      declared_bytes_, s_.size());
    // A stored value takes at least one byte unless compressed.
    XmlLimits limits;
    limits.max_data_driven_values =
        std::min(saturating_add(saturating_mul(s_.size(), compressed_ ? kCompressedExpansion : 1), kSlack),
                 kMaxCount);
    return limits;
  }

 private:
  // Reads the next tag into `tag`; false at the end of input or on markup too broken
  // to follow (expat then reports it precisely).
  bool next_tag(Tag& tag) {
    for (;;) {
      size_t lt = s_.find('<', pos_);
      if (lt == std::string_view::npos) return false;
      pos_ = lt;
      if (skip_special("<!--", "-->") || skip_special("<?", "?>") || skip_special("<![CDATA[", "]]>") ||
          skip_special("<!", ">"))
        continue;
      return parse_tag(tag);
    }
  }

  bool skip_special(std::string_view open, std::string_view close) {
    if (s_.compare(pos_, open.size(), open) != 0) return false;
    size_t end = s_.find(close, pos_ + open.size());
    pos_ = end == std::string_view::npos ? s_.size() : end + close.size();
    return true;
  }

  bool parse_tag(Tag& tag) {
    tag = Tag{};
    ++pos_;  // '<'
    if (pos_ < s_.size() && s_[pos_] == '/') {
      tag.closing = true;
      ++pos_;
    }
    size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_]) && s_[pos_] != '>' && s_[pos_] != '/') ++pos_;
    tag.name = s_.substr(start, pos_ - start);
    if (tag.name.empty()) return false;
    for (;;) {
      while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
      if (pos_ >= s_.size()) return false;
      if (s_[pos_] == '>') {
        ++pos_;
        return true;
      }
      if (s_[pos_] == '/') {
        if (pos_ + 1 >= s_.size() || s_[pos_ + 1] != '>') return false;
        tag.self_closing = true;
        pos_ += 2;
        return true;
      }
      size_t name_start = pos_;
      while (pos_ < s_.size() && !is_space(s_[pos_]) && s_[pos_] != '=' && s_[pos_] != '>') ++pos_;
      std::string_view name = s_.substr(name_start, pos_ - name_start);
      while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
      if (pos_ >= s_.size() || s_[pos_] != '=') return false;
      ++pos_;
      while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
      if (pos_ >= s_.size() || (s_[pos_] != '"' && s_[pos_] != '\'')) return false;
      char quote = s_[pos_++];
      size_t end = s_.find(quote, pos_);
      if (end == std::string_view::npos) return false;
      tag.attributes.push_back({name, s_.substr(pos_, end - pos_)});
      pos_ = end + 1;
    }
  }

  uint64_t number(const Tag& tag, std::string_view key, uint64_t fallback, uint64_t max) const {
    if (!tag.has(key)) return fallback;
    std::string_view v = tag.get(key);
    while (!v.empty() && is_space(v.front())) v.remove_prefix(1);
    while (!v.empty() && is_space(v.back())) v.remove_suffix(1);
    if (v.empty() || v.size() > 18) bad_number(tag, key);
    uint64_t n = 0;
    for (char c : v) {
      if (c < '0' || c > '9') bad_number(tag, key);
      n = n * 10 + static_cast<uint64_t>(c - '0');
    }
    if (n > max) throw bad_input("{}: <{} {}=\"{}\"> is out of range", format_, tag.name, key, n);
    return n;
  }

  [[noreturn]] void bad_number(const Tag& tag, std::string_view key) const {
    throw bad_input("{}: <{} {}=\"{}\"> is not a count", format_, tag.name, key, tag.get(key).substr(0, 40));
  }

  // Points of an "x0 x1 y0 y1 z0 z1" extent.
  uint64_t extent_points(const Tag& tag, std::string_view key) const {
    std::string text(tag.get(key));
    long long e[6] = {0, 0, 0, 0, 0, 0};
    const char* p = text.c_str();
    for (long long& v : e) {
      char* end = nullptr;
      v = std::strtoll(p, &end, 10);
      if (end == p) throw bad_input("{}: <{} {}=\"{}\"> is not an extent", format_, tag.name, key, text.substr(0, 60));
      p = end;
    }
    uint64_t points = 1;
    for (int axis = 0; axis < 3; ++axis) {
      long long lo = e[2 * axis], hi = e[2 * axis + 1];
      if (lo < -(1LL << 31) || hi > (1LL << 31)) throw bad_input("{}: {} {} is out of range", format_, key, text);
      if (hi < lo) return 0;
      points = saturating_mul(points, static_cast<uint64_t>(hi - lo + 1));
    }
    if (points > kMaxCount) throw bad_input("{}: {} \"{}\" describes more than 2^40 points", format_, key, text);
    return points;
  }

  static uint64_t type_size(std::string_view type) {
    if (type == "Int8" || type == "UInt8" || type == "Bit" || type == "Char") return 1;
    if (type == "Int16" || type == "UInt16") return 2;
    if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
    if (type == "String") return 32;  // a std::string each
    return 8;
  }

  void element(const Tag& tag) {
    const std::string_view parent = open_.empty() ? std::string_view() : open_.back();
    if (tag.name == "VTKFile") {
      seen_root_ = true;
      std::string_view type = tag.get("type");
      if (type != expected_)
        throw bad_input("{}: this is a VTK XML {} file, not {}", format_, type.empty() ? "untyped" : type,
                        expected_);
      compressed_ = tag.has("compressor") && !tag.get("compressor").empty();
    } else if ((tag.name == "ImageData" || tag.name == "StructuredGrid") && tag.has("WholeExtent")) {
      extent_points(tag, "WholeExtent");
    } else if (tag.name == "Piece") {
      piece(tag);
    } else if (tag.name == "DataArray" || tag.name == "Array") {
      data_array(tag, parent);
    }
  }

  void piece(const Tag& tag) {
    if (expected_ == "ImageData" || expected_ == "StructuredGrid") {
      points_ = extent_points(tag, "Extent");
      cells_ = points_;  // never more cells than points in a grid
      return;
    }
    points_ = number(tag, "NumberOfPoints", 0, kMaxCount);
    verts_ = number(tag, "NumberOfVerts", 0, kMaxCount);
    lines_ = number(tag, "NumberOfLines", 0, kMaxCount);
    strips_ = number(tag, "NumberOfStrips", 0, kMaxCount);
    polys_ = number(tag, "NumberOfPolys", 0, kMaxCount);
    cells_ = number(tag, "NumberOfCells", 0, kMaxCount) + verts_ + lines_ + strips_ + polys_;
  }

  void data_array(const Tag& tag, std::string_view parent) {
    uint64_t comps = number(tag, "NumberOfComponents", 1, kMaxComponents);
    std::string_view name = tag.get("Name");
    uint64_t tuples = 0;
    if (parent == "PointData" || parent == "Points" || parent == "Coordinates") {
      tuples = points_;
    } else if (parent == "CellData") {
      tuples = cells_;
    } else if (parent == "Cells") {
      if (name == "faces" || name == "faceoffsets")
        throw bad_input("{}: polyhedron cells (faces arrays) are not supported", format_);
      if (name == "offsets" || name == "types") tuples = cells_;
    } else if (parent == "Verts" || parent == "Lines" || parent == "Strips" || parent == "Polys") {
      if (name == "offsets")
        tuples = parent == "Verts" ? verts_ : parent == "Lines" ? lines_ : parent == "Strips" ? strips_ : polys_;
    } else if (parent == "FieldData") {
      tuples = number(tag, "NumberOfTuples", 0, kMaxCount);
    }
    uint64_t bytes = saturating_mul(saturating_mul(tuples, comps), type_size(tag.get("type")));
    declared_bytes_ = saturating_add(declared_bytes_, bytes);
  }

  std::string_view s_;
  std::string_view expected_;
  const char* format_;
  size_t pos_ = 0;
  std::vector<std::string_view> open_;
  bool seen_root_ = false;
  bool compressed_ = false;
  uint64_t points_ = 0, cells_ = 0, verts_ = 0, lines_ = 0, strips_ = 0, polys_ = 0;
  uint64_t declared_bytes_ = 0;
};

}  // namespace

XmlLimits scan_vtk_xml(std::string_view bytes, std::string_view expected_type, const char* format) {
  return XmlScanner(bytes, expected_type, format).run();
}

}  // namespace fest::formats::detail
