#include "formats/volume/nrrd.hpp"
#include "core/quote.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/gzip.hpp"
#include "formats/volume/header_text.hpp"
#include "formats/volume/volume_geometry.hpp"
#include "formats/volume/voxel_codec.hpp"

namespace fest::formats::volume_detail {

namespace {

enum class Encoding { raw, gzip, ascii };

// The header fields fest uses, as text until all are known (their meaning depends on
// "dimension" and "space", which may come later in the header).
struct NrrdHeader {
  std::optional<std::string> type, dimension, sizes, encoding, endian, space, space_dimension;
  std::optional<std::string> space_directions, space_origin, spacings, kinds, byte_skip, line_skip;
};

std::optional<ScalarType> parse_type(const std::string& name) {
  struct Alias {
    const char* name;
    ScalarType type;
  };
  // Every spelling the NRRD specification allows for the scalar types.
  static const Alias aliases[] = {
      {"signed char", ScalarType::i8}, {"int8", ScalarType::i8}, {"int8_t", ScalarType::i8},
      {"uchar", ScalarType::u8}, {"unsigned char", ScalarType::u8}, {"uint8", ScalarType::u8}, {"uint8_t", ScalarType::u8},
      {"short", ScalarType::i16}, {"short int", ScalarType::i16}, {"signed short", ScalarType::i16},
      {"signed short int", ScalarType::i16}, {"int16", ScalarType::i16}, {"int16_t", ScalarType::i16},
      {"ushort", ScalarType::u16}, {"unsigned short", ScalarType::u16}, {"unsigned short int", ScalarType::u16},
      {"uint16", ScalarType::u16}, {"uint16_t", ScalarType::u16},
      {"int", ScalarType::i32}, {"signed int", ScalarType::i32}, {"int32", ScalarType::i32}, {"int32_t", ScalarType::i32},
      {"uint", ScalarType::u32}, {"unsigned int", ScalarType::u32}, {"uint32", ScalarType::u32}, {"uint32_t", ScalarType::u32},
      {"longlong", ScalarType::i64}, {"long long", ScalarType::i64}, {"long long int", ScalarType::i64},
      {"signed long long", ScalarType::i64}, {"signed long long int", ScalarType::i64}, {"int64", ScalarType::i64},
      {"int64_t", ScalarType::i64}, {"ulonglong", ScalarType::u64}, {"unsigned long long", ScalarType::u64},
      {"unsigned long long int", ScalarType::u64}, {"uint64", ScalarType::u64}, {"uint64_t", ScalarType::u64},
      {"float", ScalarType::f32}, {"double", ScalarType::f64},
  };
  const std::string lower = to_lower(name);
  for (const Alias& a : aliases)
    if (lower == a.name) return a.type;
  return std::nullopt;
}

const char* type_name(ScalarType t) noexcept {
  switch (t) {
    case ScalarType::f32: return "float";
    case ScalarType::f64: return "double";
    default: return scalar_type_name(t);  // int8 ... uint64 are NRRD names too
  }
}

// Signs that take the NRRD space to RAS, per axis of the world frame.
Vec3 space_to_ras(const std::string& space) {
  const std::string s = to_lower(space);
  if (s == "ras" || s == "right-anterior-superior" || s == "3d-right-handed") return {1, 1, 1};
  if (s == "lps" || s == "left-posterior-superior") return {-1, -1, 1};
  if (s == "las" || s == "left-anterior-superior") return {-1, 1, 1};
  throw bad_input("NRRD header: space '{}' is not supported (RAS, LPS, LAS or 3D-right-handed)", fest::quoted_bytes(space, 40));
}

// "(x,y,z)" -> three numbers.
Vec3 parse_vector(std::string_view text, const std::string& field) {
  text = trim(text);
  if (text.size() < 2 || text.front() != '(' || text.back() != ')')
    throw bad_input("{}: '{}' is not a vector like (1,0,0)", field, fest::quoted_bytes(text, 40));
  text = text.substr(1, text.size() - 2);
  Vec3 v{};
  std::size_t i = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t comma = text.find(',', i);
    const bool last = k == 2;
    if (last != (comma == std::string_view::npos)) throw bad_input("{}: a 3-D vector needs three numbers", field);
    v[k] = parse_number(text.substr(i, last ? std::string_view::npos : comma - i), field);
    i = comma + 1;
  }
  return v;
}

// "(a,b,c) none (d,e,f)": one entry per axis, nullopt for "none".
std::vector<std::optional<Vec3>> parse_directions(std::string_view text, std::size_t n) {
  std::vector<std::optional<Vec3>> out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == '\t') {
      ++i;
    } else if (text[i] == '(') {
      const std::size_t close = text.find(')', i);
      if (close == std::string_view::npos) throw bad_input("NRRD space directions: unclosed '('");
      out.push_back(parse_vector(text.substr(i, close + 1 - i), "NRRD space directions"));
      i = close + 1;
    } else if (text.substr(i, 4) == "none") {
      out.emplace_back();
      i += 4;
    } else {
      throw bad_input("NRRD space directions: unexpected '{}'", text.substr(i, 20));
    }
    if (out.size() > n) break;
  }
  if (out.size() != n) throw bad_input("NRRD space directions: {} entries expected, one per axis", n);
  return out;
}

// Every field fest reads (lower case), and the member keeping it. Other fields (content,
// min, max, units, centerings, labels, ...) do not affect voxels.
constexpr HeaderField<NrrdHeader> kNrrdFields[] = {
    {"type", &NrrdHeader::type},
    {"dimension", &NrrdHeader::dimension},
    {"sizes", &NrrdHeader::sizes},
    {"encoding", &NrrdHeader::encoding},
    {"endian", &NrrdHeader::endian},
    {"space", &NrrdHeader::space},
    {"space dimension", &NrrdHeader::space_dimension},
    {"space directions", &NrrdHeader::space_directions},
    {"space origin", &NrrdHeader::space_origin},
    {"spacings", &NrrdHeader::spacings},
    {"kinds", &NrrdHeader::kinds},
    {"byte skip", &NrrdHeader::byte_skip},
    {"byteskip", &NrrdHeader::byte_skip},
    {"line skip", &NrrdHeader::line_skip},
    {"lineskip", &NrrdHeader::line_skip},
};

NrrdHeader parse_header(std::string_view bytes, std::size_t& data_start) {
  std::size_t pos = 0;
  std::string_view line;
  next_line(bytes, pos, line);
  if (line.size() != 8 || line.substr(0, 7) != "NRRD000" || line[7] < '1' || line[7] > '9')
    throw bad_input("NRRD: the first line is not a NRRD magic like \"NRRD0004\"");
  NrrdHeader h;
  HeaderLines lines(bytes, pos, 1, "NRRD");
  data_start = bytes.size();
  while (lines.next(line)) {
    if (line.empty()) {  // the blank line that separates header and attached data
      data_start = lines.position();
      break;
    }
    if (line.front() == '#') continue;
    const std::size_t field_end = line.find(": ");
    const std::size_t kv = line.find(":=");
    if (kv != std::string_view::npos && (field_end == std::string_view::npos || kv < field_end)) continue;  // key/value
    if (field_end == std::string_view::npos)
      throw bad_input("NRRD header line {}: '{}' is not 'field: value'", lines.line_number(), fest::quoted_bytes(line, 40));
    const std::string field = to_lower(trim(line.substr(0, field_end)));
    std::string value(trim(line.substr(field_end + 2)));
    if (field == "data file" || field == "datafile")
      throw bad_input("NRRD: detached data (data file: {}) is not supported; save with the data attached (.nrrd)",
                      value.substr(0, 60));
    store_field(h, kNrrdFields, field, std::move(value));
  }
  return h;
}

Encoding parse_encoding(const std::string& text) {
  const std::string e = to_lower(text);
  if (e == "raw") return Encoding::raw;
  if (e == "gzip" || e == "gz") return Encoding::gzip;
  if (e == "ascii" || e == "text" || e == "txt") return Encoding::ascii;
  throw bad_input("NRRD: encoding '{}' is not supported (raw, gzip or ascii)", fest::quoted_bytes(text, 40));
}

void check_kinds(const std::string& kinds, std::size_t n) {
  const std::vector<std::string_view> words = split_words(kinds);
  if (words.size() != n) throw bad_input("NRRD kinds: {} entries expected, one per axis", n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string k = to_lower(words[i]);
    if (k == "domain" || k == "space" || k == "???" || k == "none") continue;
    // The fourth axis of a series counts frames: time points or a list (gradients, echoes).
    if (i == 3 && (k == "time" || k == "list")) continue;
    throw bad_input("NRRD axis {} has kind '{}': only scalar volumes and series of them (a fourth axis of kind "
                    "time or list) are supported, not multi-component data",
                    i, words[i].substr(0, 40));
  }
}

void set_geometry(Volume& v, const NrrdHeader& h, std::size_t n) {
  // n is the number of axes: 2, 3, or 4 (the fourth counts frames and has no direction).
  const std::size_t ns = std::min<std::size_t>(n, 3);
  if (h.space_dimension && !h.space) {
    if (parse_count(*h.space_dimension, "NRRD space dimension") != 3)
      throw bad_input("NRRD: space dimension {} is not supported, only 3", h.space_dimension->substr(0, 20));
  }
  const Vec3 sign = h.space ? space_to_ras(*h.space) : Vec3{1, 1, 1};
  if (h.space_directions) {
    const auto dirs = parse_directions(*h.space_directions, n);
    std::array<Vec3, 3> axes{};
    for (std::size_t c = 0; c < ns; ++c) {
      if (!dirs[c]) throw bad_input("NRRD space directions: axis {} of a scalar volume cannot be 'none'", c);
      axes[c] = *dirs[c];
    }
    if (n == 4 && dirs[3]) throw bad_input("NRRD space directions: the fourth axis (frames) must be 'none'");
    if (n == 2) {  // a single slice: its normal, one unit thick
      axes[2] = unit_normal(axes[0], axes[1]);
    }
    set_axes(v, axes, "NRRD space directions");
  }
  if (h.spacings) {
    const std::vector<std::string_view> words = split_words(*h.spacings);
    if (words.size() != n) throw bad_input("NRRD spacings: {} numbers expected, found {}", n, words.size());
    for (std::size_t c = 0; c < n; ++c) {
      const double s = parse_number(words[c], "NRRD spacings");
      // NaN means "no spacing" in NRRD (required for axes with a space direction);
      // negative spacing flips the axis.
      if (std::isnan(s) || s == 0.0) continue;
      if (!std::isfinite(s)) throw bad_input("NRRD spacings: axis {} spacing is not finite", c);
      if (c == 3) {
        v.frame_spacing = std::fabs(s);
        continue;
      }
      if (h.space_directions) continue;  // the directions already state this axis
      v.spacing[c] = std::fabs(s);
      if (s < 0) v.direction[4 * c] = -1.0;
    }
  }
  if (h.space_origin) {
    v.origin = parse_vector(*h.space_origin, "NRRD space origin");
    for (double o : v.origin)
      if (!std::isfinite(o)) throw bad_input("NRRD space origin is not finite");
  }
  // To RAS: each world component r scales by sign[r] (origin and every axis direction).
  for (int r = 0; r < 3; ++r) {
    v.origin[r] = 0.0 + sign[r] * v.origin[r];
    for (int c = 0; c < 3; ++c) v.direction[3 * r + c] = 0.0 + sign[r] * v.direction[3 * r + c];
  }
}

}  // namespace

Volume read_nrrd(std::string_view bytes) {
  std::size_t data_start = 0;
  const NrrdHeader h = parse_header(bytes, data_start);
  if (!h.type) throw bad_input("NRRD header: no 'type' field");
  if (!h.dimension) throw bad_input("NRRD header: no 'dimension' field");
  if (!h.sizes) throw bad_input("NRRD header: no 'sizes' field");
  if (!h.encoding) throw bad_input("NRRD header: no 'encoding' field");
  const std::optional<ScalarType> type = parse_type(*h.type);
  if (!type) throw bad_input("NRRD: type '{}' is not supported (scalar integers, float or double)", fest::quoted_bytes(*h.type, 40));
  const std::uint64_t n = parse_count(*h.dimension, "NRRD dimension");
  if (n < 2 || n > 4)
    throw bad_input("NRRD: dimension {} is not supported, only 2-D and 3-D scalar data and 4-D series of them", n);
  const std::vector<std::string_view> size_words = split_words(*h.sizes);
  if (size_words.size() != n) throw bad_input("NRRD sizes: {} numbers expected for dimension {}, found {}", n, n, size_words.size());
  const auto [dims, count] = parse_axis_sizes(size_words, *h.sizes, kMaxVoxels, "NRRD sizes", "exceed");
  if (h.kinds) check_kinds(*h.kinds, n);
  const Encoding encoding = parse_encoding(*h.encoding);
  bool big = false;
  if (h.endian) {
    const std::string e = to_lower(*h.endian);
    if (e != "little" && e != "big") throw bad_input("NRRD: endian '{}' is neither little nor big", fest::quoted_bytes(*h.endian, 20));
    big = e == "big";
  }
  const std::int64_t byte_skip = h.byte_skip ? parse_integer(*h.byte_skip, "NRRD byte skip") : 0;
  if (byte_skip < -1) throw bad_input("NRRD: byte skip {} is invalid", byte_skip);
  if (byte_skip == -1 && encoding != Encoding::raw) throw bad_input("NRRD: byte skip -1 is only allowed with raw encoding");

  std::string_view data = bytes.substr(data_start);
  const std::uint64_t line_skip = h.line_skip ? parse_count(*h.line_skip, "NRRD line skip") : 0;
  for (std::uint64_t i = 0; i < line_skip; ++i) {
    const std::size_t nl = data.find('\n');
    if (nl == std::string_view::npos) throw bad_input("NRRD: line skip {} passes the end of the data", line_skip);
    data.remove_prefix(nl + 1);
  }

  const std::uint64_t needed = count * scalar_type_size(*type);
  Volume v;
  v.type = *type;
  std::string inflated;
  if (encoding == Encoding::raw) {
    if (byte_skip == -1) {
      if (needed > data.size()) throw bad_input("NRRD data truncated: {} bytes needed, {} present", needed, data.size());
      data = data.substr(data.size() - needed);
    } else {
      if (static_cast<std::uint64_t>(byte_skip) > data.size()) throw bad_input("NRRD: byte skip {} passes the end of the data", byte_skip);
      data.remove_prefix(static_cast<std::size_t>(byte_skip));
      if (needed > data.size())
        throw bad_input("NRRD data truncated: {} voxels of {} need {} bytes, {} present", count, scalar_type_name(*type),
                        needed, data.size());
    }
  } else if (encoding == Encoding::gzip) {
    const auto skip = static_cast<std::uint64_t>(byte_skip);
    inflated = inflate_voxel_bytes(data, needed + skip, "NRRD gzip data");
    data = std::string_view(inflated).substr(static_cast<std::size_t>(skip));
  } else {
    // Every text value takes at least one character and a separator.
    if (count > data.size() / 2 + 1)
      throw bad_input("NRRD ascii data truncated: {} values cannot fit in {} bytes", count, data.size());
  }
  v.resize(static_cast<std::size_t>(dims[0]), static_cast<std::size_t>(dims[1]), static_cast<std::size_t>(dims[2]),
           static_cast<std::size_t>(dims[3]));
  if (encoding == Encoding::ascii)
    parse_text_voxels(data, v.voxels, "NRRD ascii data");
  else
    decode_voxels(data, *type, big, v.voxels);
  set_geometry(v, h, static_cast<std::size_t>(n));
  return v;
}

std::string write_nrrd(const Volume& volume, ScalarType type, bool compress) {
  check_writable(volume, "NRRD writer");
  std::string out = "NRRD0004\n# Complete NRRD file format specification at:\n# http://teem.sourceforge.net/nrrd/format.html\n";
  const bool series = volume.frames > 1;
  out += fmt::format("type: {}\ndimension: {}\nspace: right-anterior-superior\n", type_name(type), series ? 4 : 3);
  out += fmt::format("sizes: {} {} {}", volume.dims[0], volume.dims[1], volume.dims[2]);
  out += series ? fmt::format(" {}\n", volume.frames) : "\n";
  out += "space directions:";
  for (int c = 0; c < 3; ++c) {
    const Vec3 a = axis_step(volume, c);
    out += fmt::format(" ({},{},{})", a[0], a[1], a[2]);
  }
  // A series: the fourth axis lists frames; its step is the one spacing NRRD allows
  // beside space directions (NaN for the spatial axes).
  out += series ? fmt::format(" none\nkinds: domain domain domain list\nspacings: nan nan nan {}\n", volume.frame_spacing)
                : "\nkinds: domain domain domain\n";
  if (scalar_type_size(type) > 1) out += "endian: little\n";
  out += fmt::format("encoding: {}\n", compress ? "gzip" : "raw");
  out += fmt::format("space origin: ({},{},{})\n\n", volume.origin[0], volume.origin[1], volume.origin[2]);
  const std::string data = encode_voxels(volume.voxels, type, false);
  out += compress ? gzip(data) : data;
  return out;
}

}  // namespace fest::formats::volume_detail
