// PNG header: the signature, IHDR, and a walk over the chunks up to the first IDAT.
#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "formats/image/byte_reader.hpp"
#include "formats/image/image_headers.hpp"
#include "formats/image/image_limits.hpp"

namespace fest::formats::image_detail {
namespace {

constexpr char png_signature[] = "\x89PNG\r\n\x1a\n";

bool depth_allowed(int color_type, int depth) {
  switch (color_type) {
    case 0: return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
    case 3: return depth == 1 || depth == 2 || depth == 4 || depth == 8;
    case 2: case 4: case 6: return depth == 8 || depth == 16;
    default: return false;
  }
}

// Chunk types are four ASCII letters; anything else is shown as '?' in messages.
std::string_view printable_type(std::string_view type) {
  for (char c : type)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))) return "?";
  return type;
}

}  // namespace

ImageHeader read_png_header(std::string_view bytes) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), png_signature, 8) != 0)
    throw bad_input("PNG header: missing PNG signature at byte 0");
  // The first chunk must be IHDR with 13 bytes of data.
  if (!fits(bytes, 8, 8 + 13 + 4)) throw bad_input("PNG header: truncated IHDR chunk");
  if (load_u32_be(bytes, 8) != 13 || bytes.substr(12, 4) != "IHDR")
    throw bad_input("PNG header: first chunk is not a 13-byte IHDR");
  const std::uint32_t width = load_u32_be(bytes, 16);
  const std::uint32_t height = load_u32_be(bytes, 20);
  const int depth = std::uint8_t(bytes[24]);
  const int color_type = std::uint8_t(bytes[25]);
  if (width == 0 || height == 0 || width > 0x7fffffffu || height > 0x7fffffffu)
    throw bad_input("PNG header: image size {} x {} is invalid", width, height);
  if (!depth_allowed(color_type, depth))
    throw bad_input("PNG header: bit depth {} with colour type {} is invalid", depth, color_type);
  if (bytes[26] != 0 || bytes[27] != 0 || std::uint8_t(bytes[28]) > 1)
    throw bad_input("PNG header: unknown compression, filter or interlace method");

  ImageHeader h;
  h.width = static_cast<int>(width);
  h.height = static_cast<int>(height);
  h.bits = depth == 16 ? 16 : 8;  // 1, 2, 4-bit samples are expanded to 8 bits
  h.is_float = false;
  static constexpr int channels_of_type[] = {1, 0, 3, 3, 2, 0, 4};
  h.channels = channels_of_type[color_type];

  // Walk the chunks: each must lie inside the file, and the image data must begin.
  // A palette with a tRNS chunk decodes to RGBA.
  std::uint64_t at = 8;
  for (;;) {
    if (!fits(bytes, at, 12)) throw bad_input("PNG data: truncated chunk at byte {} before any IDAT", at);
    const std::uint32_t length = load_u32_be(bytes, at);
    const std::string_view type = bytes.substr(at + 4, 4);
    if (length > 0x7fffffffu || !fits(bytes, at + 8, std::uint64_t(length) + 4))
      throw bad_input("PNG data: chunk '{}' at byte {} runs past the end of the file",
                      printable_type(type), at);
    if (type == "IDAT") break;
    if (type == "IEND") throw bad_input("PNG data: IEND before any IDAT chunk");
    if (type == "tRNS" && color_type == 3) h.channels = 4;
    at += std::uint64_t(length) + 12;
  }
  check_dimensions(h, "PNG");
  check_expansion(h, bytes.size(), "PNG");
  return h;
}

}  // namespace fest::formats::image_detail
