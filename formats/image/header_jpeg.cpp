// JPEG (JFIF/Exif) header: a walk over the marker segments up to the frame header
// (SOFn), which gives the size and the number of components. The EXIF orientation tag is
// not applied (pixels come back in stored order, as djpeg writes them).
#include <cstdint>

#include "core/error.hpp"
#include "formats/image/byte_reader.hpp"
#include "formats/image/image_headers.hpp"
#include "formats/image/image_limits.hpp"

namespace fest::formats::image_detail {

ImageHeader read_jpeg_header(std::string_view bytes) {
  if (bytes.size() < 4 || std::uint8_t(bytes[0]) != 0xFF || std::uint8_t(bytes[1]) != 0xD8)
    throw bad_input("JPEG header: missing start-of-image marker at byte 0");
  std::size_t at = 2;
  while (true) {
    // Markers may be preceded by fill bytes 0xFF.
    if (!fits(bytes, at, 2)) throw bad_input("JPEG header: truncated before the frame header (byte {})", at);
    if (std::uint8_t(bytes[at]) != 0xFF) throw bad_input("JPEG header: no marker at byte {}", at);
    std::uint8_t marker = std::uint8_t(bytes[at + 1]);
    while (marker == 0xFF) {
      ++at;
      if (!fits(bytes, at, 2)) throw bad_input("JPEG header: truncated before the frame header (byte {})", at);
      marker = std::uint8_t(bytes[at + 1]);
    }
    at += 2;
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;  // no length
    if (marker == 0xD9 || marker == 0xDA)
      throw bad_input("JPEG header: {} before any frame header", marker == 0xD9 ? "end of image" : "scan data");
    if (!fits(bytes, at, 2)) throw bad_input("JPEG header: truncated segment length at byte {}", at);
    const std::uint16_t length = load_u16_be(bytes, at);
    if (length < 2 || !fits(bytes, at, length))
      throw bad_input("JPEG header: segment of {} bytes at byte {} runs past the end", length, at);
    // SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC).
    const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (!frame) {
      at += length;
      continue;
    }
    if (length < 8) throw bad_input("JPEG header: frame header of {} bytes", length);
    const int precision = std::uint8_t(bytes[at + 2]);
    ImageHeader h;
    h.height = load_u16_be(bytes, at + 3);
    h.width = load_u16_be(bytes, at + 5);
    h.channels = std::uint8_t(bytes[at + 7]);
    h.bits = 8;
    if (precision != 8)
      throw bad_input("JPEG header: {}-bit samples (only 8-bit JPEG is supported)", precision);
    if (marker == 0xC3 || marker == 0xC7 || marker == 0xCB || marker == 0xCF)
      throw bad_input("JPEG header: lossless JPEG is not supported");
    if (h.channels == 4)
      throw bad_input("JPEG header: 4 components (CMYK or YCCK, which fest does not read; convert to RGB first)");
    if (h.channels != 1 && h.channels != 3)
      throw bad_input("JPEG header: {} components (grey or YCbCr colour supported)", h.channels);
    if (length < 8 + 3 * h.channels) throw bad_input("JPEG header: frame header too short for {} components", h.channels);
    check_dimensions(h, "JPEG");
    check_expansion(h, bytes.size(), "JPEG");
    return h;
  }
}

}  // namespace fest::formats::image_detail
