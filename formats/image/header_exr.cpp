// EXR header, parsed by hand (magic, version flags, attributes) so OpenEXR only ever
// sees a single-part flat image with channels we can place and a data window we can
// afford. See the OpenEXR file layout document ("Header Attributes").
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <utility>
#include <string>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "formats/image/byte_reader.hpp"
#include "formats/image/exr_channels.hpp"
#include "formats/image/image_headers.hpp"
#include "formats/image/image_limits.hpp"

namespace fest::formats::image_detail {
namespace {

constexpr std::uint32_t exr_magic = 20000630;
constexpr std::uint32_t flag_tiled = 0x200, flag_long_names = 0x400, flag_deep = 0x800,
                        flag_multipart = 0x1000;

class ExrHeaderReader {
 public:
  explicit ExrHeaderReader(std::string_view bytes) : bytes_(bytes) {}

  ExrLayout parse() {
    if (bytes_.size() < 8 || load_u32_le(bytes_, 0) != exr_magic)
      throw bad_input("EXR header: missing magic number at byte 0");
    const std::uint32_t version = load_u32_le(bytes_, 4);
    if ((version & 0xff) != 2) throw bad_input("EXR header: file version {} is not 2", version & 0xff);
    if (version & (flag_deep | flag_multipart))
      throw bad_input("EXR header: deep or multi-part files are not supported");
    if (version & ~std::uint32_t(0xff | flag_tiled | flag_long_names))
      throw bad_input("EXR header: unknown version flags 0x{:x}", version);
    max_name_ = (version & flag_long_names) ? 255 : 31;

    ExrLayout layout;
    bool have_channels = false, have_window = false, have_compression = false;
    std::array<std::uint32_t, 2> tile_size{0, 0};
    pos_ = 8;
    for (;;) {
      const std::string name = text("attribute name");
      if (name.empty()) break;
      const std::string type = text("attribute type");
      if (!fits(bytes_, pos_, 4)) throw bad_input("EXR header: truncated attribute '{}'", fest::quoted_bytes(name));
      const std::int32_t size = static_cast<std::int32_t>(load_u32_le(bytes_, pos_));
      pos_ += 4;
      if (size < 0 || !fits(bytes_, pos_, std::uint64_t(size)))
        throw bad_input("EXR header: attribute '{}' of {} bytes runs past the end of the file", fest::quoted_bytes(name), size);
      const std::string_view value = bytes_.substr(pos_, std::size_t(size));
      check_attribute_size(name, type, value);
      if (type == "chlist") {
        // OpenEXR reads a channel list by its content, up to its empty name, whatever the
        // size field says, so every chlist must end exactly where its size does (one that
        // did not let OpenEXR drift into the next attribute and allocate 1.75 GB for it:
        // fuzz_image_header, regress/image/).
        if (name == "channels") {
          layout.channels = parse_channels(value);
          have_channels = true;
        } else {
          read_channel_list(value);
        }
      } else if (name == "dataWindow" && type == "box2i" && size == 16) {
        layout.data_window = parse_box(value);
        have_window = true;
      } else if (name == "tiles" && type == "tiledesc") {
        tile_size = {load_u32_le(value, 0), load_u32_le(value, 4)};
      } else if (name == "compression" && type == "compression" && size == 1) {
        layout.compression = std::uint8_t(value[0]);
        have_compression = true;
      }
      pos_ += std::size_t(size);
    }
    if (!have_channels || !have_window || !have_compression)
      throw bad_input("EXR header: channels, dataWindow or compression attribute missing");
    if (layout.compression > 9) throw bad_input("EXR header: unknown compression {}", layout.compression);
    layout.tiled = (version & flag_tiled) != 0;
    if (layout.tiled && tile_size[0] == 0) throw bad_input("EXR header: tiled file without a tiles attribute");
    layout.header_end = pos_;

    const auto& w = layout.data_window;
    const std::int64_t width = std::int64_t(w[2]) - w[0] + 1, height = std::int64_t(w[3]) - w[1] + 1;
    if (width <= 0 || height <= 0 || width > 0x7fffffff || height > 0x7fffffff)
      throw bad_input("EXR header: data window ({},{})-({},{}) is empty or too large", w[0], w[1], w[2], w[3]);
    layout.header.width = static_cast<int>(width);
    layout.header.height = static_cast<int>(height);
    layout.header.channels = static_cast<int>(layout.channels.size());
    layout.tile_width = tile_size[0];
    layout.tile_height = tile_size[1];
    layout.header.bits = 32;  // half and float are both read as float
    layout.header.is_float = true;
    check_dimensions(layout.header, "EXR");
    check_chunk_table(layout);
    ImageHeader stored = layout.header;
    check_expansion(stored, bytes_.size(), "EXR");
    return layout;
  }

 private:
  // OpenEXR reads a known attribute type by its own idea of the value's size, not by
  // the size field, and does not check the two agree: were they to differ, its reading
  // would drift from ours into bytes we never checked (a fuzzer found it allocating
  // 1.8 GB for an "opaque" attribute that way). So every known type must have exactly
  // the size OpenEXR will read, and the variable ones must be well formed within it.
  static void check_attribute_size(const std::string& name, const std::string& type, std::string_view value) {
    static const std::pair<const char*, std::size_t> fixed[] = {
        {"box2i", 16}, {"box2f", 16}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12},
        {"v3d", 24}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"int", 4}, {"float", 4},
        {"double", 8}, {"compression", 1}, {"lineOrder", 1}, {"envmap", 1}, {"deepImageState", 1},
        {"chromaticities", 32}, {"keycode", 28}, {"timecode", 8}, {"rational", 8}, {"tiledesc", 9}};
    for (const auto& [known, size] : fixed)
      if (type == known) {
        if (value.size() != size)
          throw bad_input("EXR header: attribute '{}' of type {} has {} bytes, not {}", fest::quoted_bytes(name), fest::quoted_bytes(type), value.size(), size);
        return;
      }
    if (type == "floatvector" && value.size() % 4 != 0)
      throw bad_input("EXR header: attribute '{}' ({} bytes) is not a whole number of floats", fest::quoted_bytes(name), value.size());
    if (type == "stringvector") {
      // { int32 length, characters } repeated, filling the value exactly.
      std::size_t at = 0;
      while (at < value.size()) {
        if (!fits(value, at, 4)) throw bad_input("EXR header: attribute '{}' is a malformed string vector", fest::quoted_bytes(name));
        const std::uint32_t length = load_u32_le(value, at);
        if (!fits(value, at + 4, length)) throw bad_input("EXR header: attribute '{}' is a malformed string vector", fest::quoted_bytes(name));
        at += 4 + std::size_t(length);
      }
    }
    if (type == "preview") {
      // uint32 width, uint32 height, then width * height RGBA bytes.
      if (value.size() < 8 || std::uint64_t(load_u32_le(value, 0)) * load_u32_le(value, 4) * 4 != value.size() - 8)
        throw bad_input("EXR header: preview image size does not match its {} bytes", value.size());
    }
    if (type == "chlist" && (value.empty() || value.back() != '\0'))
      throw bad_input("EXR header: channel list '{}' is not terminated", fest::quoted_bytes(name));
  }

  // A NUL-terminated name of at most max_name_ characters.
  std::string text(const char* what) {
    const std::size_t end = bytes_.find('\0', pos_);
    if (end == std::string_view::npos) throw bad_input("EXR header: truncated {} at byte {}", what, pos_);
    if (end - pos_ > max_name_) throw bad_input("EXR header: {} at byte {} is too long", what, pos_);
    std::string s(bytes_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return s;
  }

  static std::array<std::int32_t, 4> parse_box(std::string_view v) {
    std::array<std::int32_t, 4> box{};
    for (int i = 0; i < 4; ++i) box[i] = static_cast<std::int32_t>(load_u32_le(v, 4 * i));
    return box;
  }

  // chlist: repeated { name\0, int32 type, uint8 pLinear, 3 reserved, int32 xs, int32 ys }, then \0.
  std::vector<ExrChannel> parse_channels(std::string_view v) const { return order_channels(read_channel_list(v)); }

  // A chlist value's channels as stored, checked to end exactly at the value's end.
  std::vector<ExrChannel> read_channel_list(std::string_view v) const {
    std::vector<ExrChannel> found;
    std::size_t at = 0;
    for (;;) {
      const std::size_t end = v.find('\0', at);
      if (end == std::string_view::npos) throw bad_input("EXR header: channel list is not terminated");
      if (end == at) {
        // OpenEXR stops reading at this terminator: it must be the value's last byte.
        if (end + 1 != v.size()) throw bad_input("EXR header: bytes after the end of the channel list");
        break;
      }
      if (end - at > max_name_ || !fits(v, end + 1, 16)) throw bad_input("EXR header: channel list is truncated");
      ExrChannel c;
      c.name = std::string(v.substr(at, end - at));
      c.pixel_type = static_cast<int>(load_u32_le(v, end + 1));
      const std::int32_t xs = static_cast<std::int32_t>(load_u32_le(v, end + 9));
      const std::int32_t ys = static_cast<std::int32_t>(load_u32_le(v, end + 13));
      if (c.pixel_type < 0 || c.pixel_type > 2)
        throw bad_input("EXR header: channel '{}' has unknown pixel type {}", fest::quoted_bytes(c.name), c.pixel_type);
      if (xs != 1 || ys != 1) throw bad_input("EXR header: subsampled channel '{}' is not supported", fest::quoted_bytes(c.name));
      found.push_back(c);
      if (found.size() > 64) throw bad_input("EXR header: more than 64 channels");
      at = end + 17;
    }
    return found;
  }

  // A scanline file has one 8-byte offset per chunk of lines right after the header;
  // a tiled one at least one per tile of the top level. OpenEXR allocates a buffer per
  // tile, so tiles may not be (much) larger than the image either.
  void check_chunk_table(const ExrLayout& layout) const {
    std::uint64_t chunks = 1;
    const std::uint64_t width = std::uint64_t(layout.header.width), height = std::uint64_t(layout.header.height);
    if (layout.tiled) {
      if (layout.tile_width == 0 || layout.tile_height == 0 || layout.tile_width > std::max<std::uint64_t>(width, 64) ||
          layout.tile_height > std::max<std::uint64_t>(height, 64))
        throw bad_input("EXR header: tile size {} x {} for a {} x {} image", layout.tile_width, layout.tile_height,
                        width, height);
      chunks = ((width + layout.tile_width - 1) / layout.tile_width) *
               ((height + layout.tile_height - 1) / layout.tile_height);
    } else {
      const std::uint64_t lines = exr_lines_per_chunk(layout.compression);
      chunks = (std::uint64_t(layout.header.height) + lines - 1) / lines;
    }
    if (!fits(bytes_, layout.header_end, chunks * 8))
      throw bad_input("EXR data: truncated, the table of {} chunk offsets runs past the end of the file", chunks);
  }

  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::size_t max_name_ = 31;
};

}  // namespace

ExrLayout read_exr_layout(std::string_view bytes) { return ExrHeaderReader(bytes).parse(); }

ImageHeader read_exr_header(std::string_view bytes) { return read_exr_layout(bytes).header; }

int exr_lines_per_chunk(int compression) {
  switch (compression) {
    case 0: case 1: case 2: return 1;   // none, RLE, ZIPS
    case 3: case 5: case 9: return 16;  // ZIP, PXR24, DWAA
    case 4: case 6: case 7: return 32;  // PIZ, B44, B44A
    case 8: return 256;                 // DWAB
    default: return 1;
  }
}

// Images have R,G,B(,A) or Y(,A), in that order in memory; a file lists channels
// alphabetically, so the order is rebuilt here.
std::vector<ExrChannel> order_channels(const std::vector<ExrChannel>& all) {
  // hdrmerge's per-pixel "valid" weight rides along with R,G,B; the image is the colour
  // (read_exr_channel reads "valid" itself).
  std::vector<ExrChannel> found;
  for (const ExrChannel& c : all)
    if (c.name != "valid" || all.size() == 1) found.push_back(c);
  auto has = [&](const char* n) {
    for (const ExrChannel& c : found)
      if (c.name == n) return true;
    return false;
  };
  std::vector<const char*> wanted;
  if (has("R") && has("G") && has("B")) wanted = {"R", "G", "B"};
  else if (has("Y")) wanted = {"Y"};
  if (!wanted.empty() && has("A")) wanted.push_back("A");
  if (wanted.empty() || wanted.size() != found.size()) {
    std::string names;
    for (const ExrChannel& c : found) names += (names.empty() ? "" : ",") + c.name;
    throw bad_input("EXR header: channels [{}] are not R,G,B(,A) or Y(,A)", names.substr(0, 200));
  }
  std::vector<ExrChannel> ordered;
  for (const char* n : wanted)
    for (const ExrChannel& c : found)
      if (c.name == n) ordered.push_back(c);
  return ordered;
}

}  // namespace fest::formats::image_detail
