// TIFF header: byte order, the first IFD, and the tags that say the image's size and
// where its strips or tiles are; every offset is checked against the file.
#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "formats/image/byte_reader.hpp"
#include "formats/image/image_headers.hpp"
#include "formats/image/image_limits.hpp"

namespace fest::formats::image_detail {
namespace {

enum Tag : std::uint16_t {
  image_width = 256, image_length = 257, bits_per_sample = 258, compression = 259,
  photometric = 262, strip_offsets = 273, samples_per_pixel = 277, strip_byte_counts = 279,
  planar_configuration = 284, tile_offsets = 324, tile_byte_counts = 325, sample_format = 339,
};

enum FieldType : std::uint16_t { type_short = 3, type_long = 4 };

struct Entry {
  std::uint16_t tag = 0;
  std::uint16_t type = 0;
  std::uint32_t count = 0;
  std::uint64_t value_at = 0;  // where the value (or the array) lies in the file
};

class TiffReader {
 public:
  explicit TiffReader(std::string_view bytes) : bytes_(bytes) {}

  ImageHeader parse() {
    if (bytes_.size() < 8) throw bad_input("TIFF header: truncated (less than 8 bytes)");
    if (bytes_.substr(0, 2) == "II") little_ = true;
    else if (bytes_.substr(0, 2) == "MM") little_ = false;
    else throw bad_input("TIFF header: byte order mark is neither II nor MM");
    const std::uint16_t magic = u16(2);
    if (magic == 43) throw bad_input("TIFF header: BigTIFF is not supported");
    if (magic != 42) throw bad_input("TIFF header: magic number {} is not 42", magic);
    const std::uint32_t ifd = u32(4);
    if (ifd < 8 || !fits(bytes_, ifd, 2))
      throw bad_input("TIFF header: first IFD offset {} lies outside the {}-byte file", ifd, bytes_.size());
    const std::uint16_t count = u16(ifd);
    if (count == 0 || !fits(bytes_, std::uint64_t(ifd) + 2, std::uint64_t(count) * 12))
      throw bad_input("TIFF header: IFD at byte {} with {} entries runs past the end of the file", ifd, count);
    for (std::uint16_t i = 0; i < count; ++i) entries_.push_back(entry(std::uint64_t(ifd) + 2 + 12u * i));
    return describe();
  }

 private:
  std::uint16_t u16(std::uint64_t at) const {
    return little_ ? load_u16_le(bytes_, at) : load_u16_be(bytes_, at);
  }
  std::uint32_t u32(std::uint64_t at) const {
    return little_ ? load_u32_le(bytes_, at) : load_u32_be(bytes_, at);
  }

  static std::uint64_t type_size(std::uint16_t type) {
    switch (type) {
      case 1: case 2: case 6: case 7: return 1;   // BYTE, ASCII, SBYTE, UNDEFINED
      case 3: case 8: return 2;                   // SHORT, SSHORT
      case 4: case 9: case 11: case 13: return 4; // LONG, SLONG, FLOAT, IFD
      case 5: case 10: case 12: return 8;         // RATIONAL, SRATIONAL, DOUBLE
      default: return 0;                          // unknown types are skipped by readers
    }
  }

  Entry entry(std::uint64_t at) const {
    Entry e;
    e.tag = u16(at);
    e.type = u16(at + 2);
    e.count = u32(at + 4);
    const std::uint64_t size = type_size(e.type) * e.count;
    e.value_at = size <= 4 ? at + 8 : u32(at + 8);
    if (size > 4 && !fits(bytes_, e.value_at, size))
      throw bad_input("TIFF IFD: tag {} points to {} bytes at offset {}, outside the {}-byte file", e.tag,
                      size, e.value_at, bytes_.size());
    return e;
  }

  const Entry* find(std::uint16_t tag) const {
    for (const Entry& e : entries_)
      if (e.tag == tag) return &e;
    return nullptr;
  }

  // The i-th value of an integer tag (SHORT or LONG).
  std::uint32_t value(const Entry& e, std::uint32_t i) const {
    if (i >= e.count) throw bad_input("TIFF IFD: tag {} has {} values, {} needed", e.tag, e.count, i + 1);
    if (e.type == type_short) return u16(e.value_at + 2u * i);
    if (e.type == type_long) return u32(e.value_at + 4u * i);
    throw bad_input("TIFF IFD: tag {} has type {}, not SHORT or LONG", e.tag, e.type);
  }

  std::uint32_t scalar(std::uint16_t tag, std::uint32_t fallback, bool required) const {
    const Entry* e = find(tag);
    if (!e) {
      if (required) throw bad_input("TIFF IFD: required tag {} is missing", tag);
      return fallback;
    }
    return value(*e, 0);
  }

  ImageHeader describe() const {
    const std::uint32_t width = scalar(image_width, 0, true);
    const std::uint32_t height = scalar(image_length, 0, true);
    const std::uint32_t samples = scalar(samples_per_pixel, 1, false);
    const std::uint32_t bits = scalar(bits_per_sample, 1, false);
    const std::uint32_t format = scalar(sample_format, 1, false);
    const std::uint32_t compress = scalar(compression, 1, false);
    const std::uint32_t photo = scalar(photometric, 1, false);
    const std::uint32_t planar = scalar(planar_configuration, 1, false);
    if (width == 0 || height == 0 || width > 0x7fffffffu || height > 0x7fffffffu)
      throw bad_input("TIFF IFD: image size {} x {} is invalid", width, height);
    if (samples < 1 || samples > 4) throw bad_input("TIFF IFD: {} samples per pixel (1 to 4 supported)", samples);
    if (const Entry* b = find(bits_per_sample))
      for (std::uint32_t i = 1; i < samples && i < b->count; ++i)
        if (value(*b, i) != bits) throw bad_input("TIFF IFD: samples of different bit depths are not supported");
    const bool is_float = format == 3;
    if (!((format == 1 && (bits == 8 || bits == 16)) || (is_float && bits == 32)))
      throw bad_input("TIFF IFD: {}-bit samples of sample format {} are not supported "
                      "(8/16-bit unsigned integer or 32-bit float)", bits, format);
    if (planar != 1 && planar != 2) throw bad_input("TIFF IFD: planar configuration {} is invalid", planar);

    ImageHeader h;
    h.width = static_cast<int>(width);
    h.height = static_cast<int>(height);
    h.bits = static_cast<int>(bits);
    h.is_float = is_float;
    // A palette image (photometric 3) decodes to RGB.
    h.channels = photo == 3 ? 3 : static_cast<int>(samples);
    ImageHeader stored = h;
    stored.channels = static_cast<int>(samples);
    check_dimensions(h, "TIFF");
    check_pixel_data(stored, compress);
    return h;
  }

  // Strips (or tiles) must all lie inside the file; uncompressed ones must add up to
  // the whole image, compressed ones to what a codec could expand.
  void check_pixel_data(const ImageHeader& stored, std::uint32_t compress) const {
    const Entry* offsets = find(strip_offsets);
    const Entry* counts = find(strip_byte_counts);
    if (!offsets) {
      offsets = find(tile_offsets);
      counts = find(tile_byte_counts);
    }
    if (!offsets || !counts) throw bad_input("TIFF IFD: no strip or tile offsets and byte counts");
    if (offsets->count != counts->count || offsets->count == 0)
      throw bad_input("TIFF IFD: {} strip offsets but {} byte counts", offsets->count, counts->count);
    std::uint64_t total = 0;
    for (std::uint32_t i = 0; i < offsets->count; ++i) {
      const std::uint32_t at = value(*offsets, i);
      const std::uint32_t size = value(*counts, i);
      if (!fits(bytes_, at, size))
        throw bad_input("TIFF data: strip {} ({} bytes at offset {}) lies outside the {}-byte file", i, size,
                        at, bytes_.size());
      total += size;
    }
    const std::uint64_t needed = std::uint64_t(stored.width) * std::uint64_t(stored.height) *
                                 std::uint64_t(stored.channels) * bytes_per_value(stored);
    if (compress == 1 && find(strip_offsets) && total < needed)
      throw bad_input("TIFF data: truncated, {} bytes of uncompressed pixels expected, strips hold {}", needed,
                      total);
    check_expansion(stored, static_cast<std::size_t>(total), "TIFF");
  }

  std::string_view bytes_;
  bool little_ = true;
  std::vector<Entry> entries_;
};

}  // namespace

ImageHeader read_tiff_header(std::string_view bytes) { return TiffReader(bytes).parse(); }

}  // namespace fest::formats::image_detail
