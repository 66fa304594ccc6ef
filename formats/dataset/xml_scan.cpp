#include "formats/dataset/xml_scan.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "formats/dataset/xml_blocks.hpp"
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
  size_t begin = 0, end = 0;  // where its '<' is, and just past its '>'
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
    size_t appended_begin = std::string_view::npos, appended_end = s_.size();
    bool base64_appended = false;
    while (next_tag(tag)) {
      if (tag.closing) {
        if (!open_.empty()) {
          if (open_array_.back() >= 0) arrays_[static_cast<size_t>(open_array_.back())].text_end = tag.begin;
          open_.pop_back();
          open_array_.pop_back();
        }
        continue;
      }
      // Raw appended data follows; the markup that matters is all before it.
      if (tag.name == "AppendedData") {
        std::string_view encoding = tag.get("encoding");
        if (encoding != "raw" && encoding != "base64")
          throw bad_input("{}: <AppendedData encoding={}> at byte {} is neither raw nor base64", format_,
                          quoted_bytes(encoding), tag.begin);
        base64_appended = encoding == "base64";
        size_t underscore = s_.find('_', tag.end);
        if (underscore == std::string_view::npos)
          throw bad_input("{}: <AppendedData> at byte {} has no '_' before its data", format_, tag.begin);
        // Only white space may stand between the tag and the '_': VTK takes the data to
        // start there, and anything else put its block offsets astray (a SIGSEGV in VTK).
        const size_t stray = s_.substr(tag.end, underscore - tag.end).find_first_not_of(" \t\r\n");
        if (stray != std::string_view::npos)
          throw bad_input("{}: <AppendedData> at byte {}: {} at byte {} before the '_' that starts its data", format_,
                          tag.begin, quoted_bytes(s_.substr(tag.end + stray, 1)), tag.end + stray);
        appended_begin = underscore + 1;
        size_t close = s_.rfind("</AppendedData>");
        if (close != std::string_view::npos && close >= appended_begin) appended_end = close;
        break;
      }
      int array = element(tag);
      if (!tag.self_closing) {
        open_.push_back(tag.name);
        open_array_.push_back(array);
      }
    }
    if (!seen_root_) throw bad_input("{}: not a VTK XML file (no <VTKFile> element)", format_);
    for (XmlArray& a : arrays_)
      if (a.text_end < a.text_begin) a.text_end = a.text_begin;  // never closed: no inline text
    link_connectivity();
    uint64_t budget = saturating_add(
        saturating_mul(s_.size(), compressed_ ? kCompressedExpansion : kPlainExpansion), kSlack);
    if (declared_bytes_ > budget)
      throw bad_input("{}: the arrays declared need {} bytes, more than a {}-byte file can hold", format_,
                      declared_bytes_, s_.size());
    check_xml_blocks(s_, encoding_, arrays_, appended_begin, appended_end, base64_appended, format_);
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
    tag.begin = pos_;
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
        tag.end = ++pos_;
        return true;
      }
      if (s_[pos_] == '/') {
        if (pos_ + 1 >= s_.size() || s_[pos_ + 1] != '>') return false;
        tag.self_closing = true;
        pos_ += 2;
        tag.end = pos_;
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
    throw bad_input("{}: <{} {}={}> is not a count", format_, quoted_bytes(tag.name), key, quoted_bytes(tag.get(key)));
  }

  // The six whole numbers of an "x0 x1 y0 y1 z0 z1" extent; false (the rest 0) at the
  // first one that does not parse.
  static bool parse_extent(const std::string& text, long long (&e)[6]) {
    for (long long& v : e) v = 0;
    const char* p = text.c_str();
    for (long long& v : e) {
      char* end = nullptr;
      v = std::strtoll(p, &end, 10);
      if (end == p) return false;
      p = end;
    }
    return true;
  }

  // Points of an "x0 x1 y0 y1 z0 z1" extent.
  uint64_t extent_points(const Tag& tag, std::string_view key) const {
    const std::string text(tag.get(key));
    long long e[6];
    if (!parse_extent(text, e))
      throw bad_input("{}: <{} {}={}> is not an extent", format_, tag.name, key, quoted_bytes(text, 40));
    uint64_t points = 1;
    for (int axis = 0; axis < 3; ++axis) {
      long long lo = e[2 * axis], hi = e[2 * axis + 1];
      if (lo < -(1LL << 31) || hi > (1LL << 31))
        throw bad_input("{}: {} {} is out of range", format_, key, quoted_bytes(text, 40));
      if (hi < lo) return 0;
      points = saturating_mul(points, static_cast<uint64_t>(hi - lo + 1));
    }
    if (points > kMaxCount)
      throw bad_input("{}: {} {} describes more than 2^40 points", format_, key, quoted_bytes(text, 40));
    return points;
  }

  // Cells of a grid of `points` points over an extent: vtkImageData counts one cell
  // per interval along each axis that has more than one point.
  uint64_t extent_cells(const Tag& tag, std::string_view key) const {
    long long e[6];
    parse_extent(std::string(tag.get(key)), e);  // extent_points has refused what does not parse
    uint64_t cells = 1;
    for (int axis = 0; axis < 3; ++axis) {
      long long lo = e[2 * axis], hi = e[2 * axis + 1];
      if (hi < lo) return 0;
      if (hi > lo) cells = saturating_mul(cells, static_cast<uint64_t>(hi - lo));
    }
    return cells;
  }

  static uint64_t type_size(std::string_view type) {
    if (type == "Int8" || type == "UInt8" || type == "Bit" || type == "Char") return 1;
    if (type == "Int16" || type == "UInt16") return 2;
    if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
    if (type == "String") return 32;  // a std::string each
    return 8;
  }

  // The array index of a DataArray tag, -1 for other tags.
  int element(const Tag& tag) {
    const std::string_view parent = open_.empty() ? std::string_view() : open_.back();
    if (tag.name == "VTKFile") {
      seen_root_ = true;
      std::string_view type = tag.get("type");
      if (type != expected_)
        throw bad_input("{}: this is a VTK XML {} file, not {}", format_,
                        type.empty() ? std::string("untyped") : quoted_bytes(type, 24), expected_);
      vtk_file(tag);
    } else if ((tag.name == "ImageData" || tag.name == "StructuredGrid") && tag.has("WholeExtent")) {
      extent_points(tag, "WholeExtent");
    } else if (tag.name == "Piece") {
      piece(tag);
    } else if (tag.name == "DataArray" || tag.name == "Array") {
      return data_array(tag, parent);
    } else if (tag.name == "Cells" || tag.name == "Verts" || tag.name == "Lines" || tag.name == "Strips" ||
               tag.name == "Polys") {
      ++cell_group_;
    }
    return -1;
  }

  // How the blocks are encoded: VTK's defaults are UInt32 headers, no compression.
  void vtk_file(const Tag& tag) {
    std::string_view header = tag.has("header_type") ? tag.get("header_type") : "UInt32";
    if (header != "UInt32" && header != "UInt64")
      throw bad_input("{}: <VTKFile header_type={}> at byte {} is neither UInt32 nor UInt64", format_,
                      quoted_bytes(header), tag.begin);
    encoding_.header_bytes = header == "UInt32" ? 4 : 8;
    // Without byte_order VTK reads the machine's order: little endian where fest runs.
    std::string_view order = tag.has("byte_order") ? tag.get("byte_order") : "LittleEndian";
    if (order != "LittleEndian" && order != "BigEndian")
      throw bad_input("{}: <VTKFile byte_order={}> at byte {} is neither LittleEndian nor BigEndian", format_,
                      quoted_bytes(order), tag.begin);
    encoding_.big_endian = order == "BigEndian";
    std::string_view compressor = tag.get("compressor");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor" && compressor != "vtkLZ4DataCompressor" &&
        compressor != "vtkLZMADataCompressor")
      throw bad_input("{}: <VTKFile compressor={}> at byte {} is not one VTK has (vtkZLibDataCompressor, "
                      "vtkLZ4DataCompressor, vtkLZMADataCompressor)",
                      format_, quoted_bytes(compressor, 24), tag.begin);
    compressed_ = !compressor.empty();
    encoding_.compressed = compressed_;
    encoding_.zlib = compressor == "vtkZLibDataCompressor";
  }

  void piece(const Tag& tag) {
    if (expected_ == "ImageData" || expected_ == "StructuredGrid") {
      points_ = extent_points(tag, "Extent");
      cells_ = extent_cells(tag, "Extent");
      return;
    }
    points_ = number(tag, "NumberOfPoints", 0, kMaxCount);
    verts_ = number(tag, "NumberOfVerts", 0, kMaxCount);
    lines_ = number(tag, "NumberOfLines", 0, kMaxCount);
    strips_ = number(tag, "NumberOfStrips", 0, kMaxCount);
    polys_ = number(tag, "NumberOfPolys", 0, kMaxCount);
    cells_ = number(tag, "NumberOfCells", 0, kMaxCount) + verts_ + lines_ + strips_ + polys_;
  }

  int data_array(const Tag& tag, std::string_view parent) {
    uint64_t comps = number(tag, "NumberOfComponents", 1, kMaxComponents);
    std::string_view name = tag.get("Name");
    XmlArray array;
    array.name = name;
    array.type = tag.get("type");
    array.format = tag.get("format");
    array.offset = tag.get("offset");
    array.tag_offset = tag.begin;
    array.text_begin = array.text_end = tag.end;
    uint64_t tuples = 0;
    bool known = true;
    if (parent == "PointData" || parent == "Points" || parent == "Coordinates") {
      tuples = points_;
    } else if (parent == "CellData") {
      tuples = cells_;
    } else if (parent == "Cells") {
      if (name == "faces" || name == "faceoffsets")
        throw bad_input("{}: polyhedron cells (faces arrays) are not supported", format_);
      if (name == "offsets" || name == "types") tuples = cells_;
      array.is_offsets = name == "offsets";
      known = name == "offsets" || name == "types";
    } else if (parent == "Verts" || parent == "Lines" || parent == "Strips" || parent == "Polys") {
      if (name == "offsets")
        tuples = parent == "Verts" ? verts_ : parent == "Lines" ? lines_ : parent == "Strips" ? strips_ : polys_;
      array.is_offsets = name == "offsets";
      known = array.is_offsets;
    } else if (parent == "FieldData") {
      tuples = number(tag, "NumberOfTuples", 0, kMaxCount);
    } else {
      known = false;  // an array VTK does not read by its place: sized by its data only
    }
    array.values = saturating_mul(tuples, comps);
    array.values_from_offsets = !known;
    uint64_t bytes = saturating_mul(array.values, type_size(array.type));
    declared_bytes_ = saturating_add(declared_bytes_, bytes);
    arrays_.push_back(array);
    const bool connectivity = (parent == "Cells" || parent == "Verts" || parent == "Lines" || parent == "Strips" ||
                               parent == "Polys") && name == "connectivity";
    groups_.push_back(connectivity || array.is_offsets ? cell_group_ : -1);
    return static_cast<int>(arrays_.size() - 1);
  }

  // Each connectivity array is as long as the last value of the offsets array beside it.
  void link_connectivity() {
    for (size_t i = 0; i < arrays_.size(); ++i) {
      if (groups_[i] < 0 || arrays_[i].is_offsets) continue;
      for (size_t j = 0; j < arrays_.size(); ++j)
        if (groups_[j] == groups_[i] && arrays_[j].is_offsets) arrays_[i].offsets_of = static_cast<int>(j);
    }
  }

  std::string_view s_;
  std::string_view expected_;
  const char* format_;
  size_t pos_ = 0;
  std::vector<std::string_view> open_;
  std::vector<int> open_array_;  // for each open element, its index in arrays_ or -1
  std::vector<XmlArray> arrays_;
  std::vector<int> groups_;      // cell group (Cells, Polys, ...) of each array, or -1
  int cell_group_ = 0;
  XmlEncoding encoding_;
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
