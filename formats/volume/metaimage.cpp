#include "formats/volume/metaimage.hpp"
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

struct ElementType {
  const char* name;
  ScalarType type;
};
// MET_LONG/MET_ULONG are 32-bit in MetaIO regardless of the platform's long.
constexpr ElementType kElementTypes[] = {
    {"MET_UCHAR", ScalarType::u8},      {"MET_CHAR", ScalarType::i8},          {"MET_SHORT", ScalarType::i16},
    {"MET_USHORT", ScalarType::u16},    {"MET_INT", ScalarType::i32},          {"MET_UINT", ScalarType::u32},
    {"MET_LONG", ScalarType::i32},      {"MET_ULONG", ScalarType::u32},        {"MET_LONG_LONG", ScalarType::i64},
    {"MET_ULONG_LONG", ScalarType::u64}, {"MET_FLOAT", ScalarType::f32},       {"MET_DOUBLE", ScalarType::f64},
};

const char* element_type_name(ScalarType t) noexcept {
  switch (t) {
    case ScalarType::u8: return "MET_UCHAR";
    case ScalarType::i8: return "MET_CHAR";
    case ScalarType::i16: return "MET_SHORT";
    case ScalarType::u16: return "MET_USHORT";
    case ScalarType::i32: return "MET_INT";
    case ScalarType::u32: return "MET_UINT";
    case ScalarType::i64: return "MET_LONG_LONG";
    case ScalarType::u64: return "MET_ULONG_LONG";
    case ScalarType::f32: return "MET_FLOAT";
    case ScalarType::f64: return "MET_DOUBLE";
  }
  return "MET_NONE";
}

struct MetaHeader {
  std::optional<std::string> object_type, ndims, dim_size, element_type, spacing, element_size, offset, matrix;
  std::optional<std::string> orientation, msb, compressed, compressed_size, binary, channels;
  std::optional<std::string> data_file;
};

bool parse_bool(const std::string& value, const char* field) {
  const std::string v = to_lower(value);
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  throw bad_input("MetaImage {}: '{}' is neither True nor False", field, fest::quoted_bytes(value, 20));
}

// Every key MetaIO writes that fest reads (lower case), and the member keeping it.
constexpr HeaderField<MetaHeader> kMetaFields[] = {
    {"objecttype", &MetaHeader::object_type},
    {"ndims", &MetaHeader::ndims},
    {"dimsize", &MetaHeader::dim_size},
    {"elementtype", &MetaHeader::element_type},
    {"elementspacing", &MetaHeader::spacing},
    {"elementsize", &MetaHeader::element_size},
    {"offset", &MetaHeader::offset},
    {"position", &MetaHeader::offset},
    {"origin", &MetaHeader::offset},
    {"transformmatrix", &MetaHeader::matrix},
    {"rotation", &MetaHeader::matrix},
    {"orientation", &MetaHeader::matrix},
    {"anatomicalorientation", &MetaHeader::orientation},
    {"elementbyteordermsb", &MetaHeader::msb},
    {"binarydatabyteordermsb", &MetaHeader::msb},
    {"compresseddata", &MetaHeader::compressed},
    {"compresseddatasize", &MetaHeader::compressed_size},
    {"binarydata", &MetaHeader::binary},
    {"elementnumberofchannels", &MetaHeader::channels},
    {"elementdatafile", &MetaHeader::data_file},
};

// Header lines up to and including ElementDataFile, which MetaIO requires to be last;
// `data_start` is where the bytes after that line begin.
MetaHeader parse_header(std::string_view bytes, std::size_t& data_start) {
  MetaHeader h;
  HeaderLines lines(bytes, 0, 0, "MetaImage");
  std::string_view line;
  while (!h.data_file) {
    if (!lines.next(line)) throw bad_input("MetaImage header: no ElementDataFile line ends the header");
    if (trim(line).empty()) continue;
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos)
      throw bad_input("MetaImage header line {}: '{}' is not 'Key = Value'", lines.line_number(), fest::quoted_bytes(line, 40));
    store_field(h, kMetaFields, to_lower(trim(line.substr(0, eq))), std::string(trim(line.substr(eq + 1))));
  }
  data_start = lines.position();
  return h;
}

// Direction of each axis (LPS) from AnatomicalOrientation, as ITK writes it: each letter
// names the side an axis comes *from*, so "RAI" is the identity in LPS.
std::optional<std::array<Vec3, 3>> axes_from_orientation(const std::string& code, std::size_t n) {
  if (code.size() != n) return std::nullopt;
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  bool used[3] = {false, false, false};
  for (std::size_t c = 0; c < n; ++c) {
    int axis = -1;
    double sign = 1.0;
    switch (code[c]) {
      case 'R': case 'r': axis = 0; break;
      case 'L': case 'l': axis = 0, sign = -1; break;
      case 'A': case 'a': axis = 1; break;
      case 'P': case 'p': axis = 1, sign = -1; break;
      case 'I': case 'i': axis = 2; break;
      case 'S': case 's': axis = 2, sign = -1; break;
      default: return std::nullopt;  // "???" and the like: unknown, keep the identity
    }
    if (used[axis]) return std::nullopt;
    used[axis] = true;
    axes[c] = {0, 0, 0};
    axes[c][static_cast<std::size_t>(axis)] = sign;
  }
  return axes;
}

// ITK's AnatomicalOrientation for an LPS direction, or "???" when an axis is oblique.
std::string orientation_code(const Volume& lps) {
  static const char from_positive[] = {'R', 'A', 'I'};  // +x (LPS) runs from Right to Left, ...
  static const char from_negative[] = {'L', 'P', 'S'};
  std::string code;
  for (int c = 0; c < 3; ++c) {
    char letter = '?';
    for (int r = 0; r < 3; ++r) {
      const double d = lps.direction[3 * r + c];
      if (d == 1.0) letter = from_positive[r];
      if (d == -1.0) letter = from_negative[r];
    }
    if (letter == '?') return "???";
    code += letter;
  }
  return code;
}

void set_geometry(Volume& v, const MetaHeader& h, std::size_t n) {
  // n is the number of axes in the file: 2, 3, or 4 (a series whose fourth axis is
  // frames, not space). Only the spatial axes (at most 3) place voxels in the world.
  const std::size_t ns = std::min<std::size_t>(n, 3);
  Vec3 flip{1, 1, 1};  // a negative spacing runs its axis backwards
  if (h.spacing || h.element_size) {
    const std::vector<double> s = parse_numbers(h.spacing ? *h.spacing : *h.element_size, n, "MetaImage ElementSpacing");
    for (std::size_t c = 0; c < n; ++c) {
      if (!std::isfinite(s[c]) || s[c] == 0) throw bad_input("MetaImage ElementSpacing: {} is not a usable spacing", s[c]);
      if (c == 3) {
        v.frame_spacing = std::fabs(s[c]);
        continue;
      }
      v.spacing[c] = std::fabs(s[c]);
      if (s[c] < 0) flip[c] = -1;
    }
  }
  if (h.offset) {
    const std::vector<double> o = parse_numbers(*h.offset, n, "MetaImage Offset");
    for (std::size_t c = 0; c < ns; ++c) {
      if (!std::isfinite(o[c])) throw bad_input("MetaImage Offset is not finite");
      v.origin[c] = o[c];
    }
  }
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  if (h.matrix) {
    // MetaIO stores the direction of axis i as numbers i*n .. i*n+n-1.
    const std::vector<double> m = parse_numbers(*h.matrix, n * n, "MetaImage TransformMatrix");
    for (std::size_t c = 0; c < ns; ++c) {
      axes[c] = {0, 0, 0};
      for (std::size_t r = 0; r < ns; ++r) axes[c][r] = m[c * n + r];
    }
    if (n == 2) axes[2] = unit_normal(axes[0], axes[1]);
  } else if (h.orientation) {
    if (auto from_code = axes_from_orientation(h.orientation->substr(0, ns), ns)) axes = *from_code;
  }
  for (int c = 0; c < 3; ++c)
    for (double& x : axes[c]) x *= flip[c];
  const Vec3 spacing{v.spacing[0], v.spacing[1], v.spacing[2]};
  set_axes(v, axes, "MetaImage TransformMatrix");  // normalises; the spacing is separate
  v.spacing = spacing;
  flip_xy(v);
}

// The header of a 4-D series, as ITK writes one: four axes, the fourth (frames) with
// the frame step as its spacing, no offset and an identity direction row/column.
std::string write_series_header(const Volume& volume, const Volume& lps, ScalarType type, bool compress,
                                std::size_t payload_size) {
  std::string out = "ObjectType = Image\nNDims = 4\nBinaryData = True\nBinaryDataByteOrderMSB = False\n";
  out += fmt::format("CompressedData = {}\n", compress ? "True" : "False");
  if (compress) out += fmt::format("CompressedDataSize = {}\n", payload_size);
  out += "TransformMatrix =";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      out += fmt::format(" {}", c < 3 && r < 3 ? lps.direction[static_cast<std::size_t>(3 * r + c)] : (r == c ? 1.0 : 0.0));
  out += fmt::format("\nOffset = {} {} {} 0\n", lps.origin[0], lps.origin[1], lps.origin[2]);
  out += "CenterOfRotation = 0 0 0 0\n";
  out += fmt::format("ElementSpacing = {} {} {} {}\n", volume.spacing[0], volume.spacing[1], volume.spacing[2],
                     volume.frame_spacing);
  out += fmt::format("DimSize = {} {} {} {}\n", volume.dims[0], volume.dims[1], volume.dims[2], volume.frames);
  out += fmt::format("ElementType = {}\nElementDataFile = LOCAL\n", element_type_name(type));
  return out;
}

}  // namespace

Volume read_metaimage(std::string_view bytes) {
  std::size_t data_start = 0;
  const MetaHeader h = parse_header(bytes, data_start);
  if (h.object_type && to_lower(*h.object_type) != "image")
    throw bad_input("MetaImage: ObjectType '{}' is not Image", fest::quoted_bytes(*h.object_type, 40));
  if (to_lower(*h.data_file) != "local")
    throw bad_input("MetaImage: data in a separate file (ElementDataFile = {}) is not supported; use a .mha with "
                    "ElementDataFile = LOCAL",
                    h.data_file->substr(0, 60));
  if (!h.ndims) throw bad_input("MetaImage header: no NDims");
  if (!h.dim_size) throw bad_input("MetaImage header: no DimSize");
  if (!h.element_type) throw bad_input("MetaImage header: no ElementType");
  const std::uint64_t n = parse_count(*h.ndims, "MetaImage NDims");
  if (n < 2 || n > 4) throw bad_input("MetaImage: NDims = {} is not supported, only 2, 3 or 4 (a series of 3-D frames)", n);
  if (h.channels && parse_count(*h.channels, "MetaImage ElementNumberOfChannels") != 1)
    throw bad_input("MetaImage: ElementNumberOfChannels = {}; only scalar volumes are supported", h.channels->substr(0, 20));
  std::optional<ScalarType> type;
  for (const ElementType& e : kElementTypes)
    if (*h.element_type == e.name) type = e.type;
  if (!type) throw bad_input("MetaImage: ElementType '{}' is not supported", fest::quoted_bytes(*h.element_type, 40));

  const std::vector<std::string_view> words = split_words(*h.dim_size);
  if (words.size() != n) throw bad_input("MetaImage DimSize: {} sizes expected for NDims = {}, found {}", n, n, words.size());
  const auto [dims, count] = parse_axis_sizes(words, *h.dim_size, kMaxVoxels, "MetaImage DimSize", "exceeds");
  const bool big = h.msb && parse_bool(*h.msb, "ElementByteOrderMSB");
  const bool compressed = h.compressed && parse_bool(*h.compressed, "CompressedData");
  const bool binary = !h.binary || parse_bool(*h.binary, "BinaryData");

  std::string_view data = bytes.substr(data_start);
  const std::uint64_t needed = count * scalar_type_size(*type);
  std::string inflated;
  if (compressed) {
    if (h.compressed_size) {
      const std::uint64_t size = parse_count(*h.compressed_size, "MetaImage CompressedDataSize");
      if (size > data.size())
        throw bad_input("MetaImage: CompressedDataSize {} exceeds the {} bytes after the header", size, data.size());
      data = data.substr(0, static_cast<std::size_t>(size));
    }
    inflated = inflate_voxel_bytes(data, needed, "MetaImage compressed data");
    data = inflated;
  } else if (binary && needed > data.size()) {
    throw bad_input("MetaImage data truncated: {} voxels of {} need {} bytes, {} present", count, *h.element_type,
                    needed, data.size());
  } else if (!binary && count > data.size() / 2 + 1) {
    throw bad_input("MetaImage text data truncated: {} values cannot fit in {} bytes", count, data.size());
  }
  Volume v;
  v.type = *type;
  v.resize(static_cast<std::size_t>(dims[0]), static_cast<std::size_t>(dims[1]), static_cast<std::size_t>(dims[2]),
           static_cast<std::size_t>(dims[3]));
  if (binary || compressed)
    decode_voxels(data, *type, big, v.voxels);
  else
    parse_text_voxels(data, v.voxels, "MetaImage text data");
  set_geometry(v, h, static_cast<std::size_t>(n));
  return v;
}

std::string write_metaimage(const Volume& volume, ScalarType type, bool compress) {
  check_writable(volume, "MetaImage writer");
  Volume lps;  // geometry only: the voxels are encoded from `volume`
  lps.spacing = volume.spacing;
  lps.origin = volume.origin;
  lps.direction = volume.direction;
  flip_xy(lps);
  const std::string data = encode_voxels(volume.voxels, type, false);
  const std::string payload = compress ? gzip(data, 6, true) : data;

  if (volume.frames > 1) return write_series_header(volume, lps, type, compress, payload.size()) + payload;
  std::string out = "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n";
  out += fmt::format("CompressedData = {}\n", compress ? "True" : "False");
  if (compress) out += fmt::format("CompressedDataSize = {}\n", payload.size());
  out += "TransformMatrix =";
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out += fmt::format(" {}", lps.direction[3 * r + c]);
  out += fmt::format("\nOffset = {} {} {}\n", lps.origin[0], lps.origin[1], lps.origin[2]);
  out += "CenterOfRotation = 0 0 0\n";
  out += fmt::format("AnatomicalOrientation = {}\n", orientation_code(lps));
  out += fmt::format("ElementSpacing = {} {} {}\n", volume.spacing[0], volume.spacing[1], volume.spacing[2]);
  out += fmt::format("DimSize = {} {} {}\n", volume.dims[0], volume.dims[1], volume.dims[2]);
  out += fmt::format("ElementType = {}\nElementDataFile = LOCAL\n", element_type_name(type));
  out += payload;
  return out;
}

}  // namespace fest::formats::volume_detail
