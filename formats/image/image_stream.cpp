#include "formats/image/image_stream.hpp"

#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "formats/concatenated.hpp"
#include "formats/image/image_headers.hpp"

namespace fest::formats {

namespace {

constexpr char k_png_signature[] = "\x89PNG\r\n\x1a\n";

// Length of the PNG file at the start of `b`: the signature, then chunks
// (4-byte big-endian length, type, data, CRC) up to and including IEND.
std::size_t png_length(std::string_view b, std::size_t frame) {
  std::size_t pos = 8;
  while (true) {
    if (b.size() - pos < 12) throw bad_input("image stream: frame {} (PNG) is truncated", frame);
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + pos);
    const std::uint64_t len = (std::uint64_t(p[0]) << 24) | (std::uint64_t(p[1]) << 16) | (std::uint64_t(p[2]) << 8) | p[3];
    if (len > 0x7fffffffu || len + 12 > b.size() - pos) throw bad_input("image stream: frame {} (PNG) is truncated", frame);
    const bool end = std::memcmp(p + 4, "IEND", 4) == 0;
    pos += static_cast<std::size_t>(len) + 12;
    if (end) return pos;
  }
}

std::size_t netpbm_length(std::string_view b, std::size_t frame) {
  image_detail::NetpbmLayout l;
  try {
    l = image_detail::read_netpbm_layout(b, false);
  } catch (const Error& e) {
    throw bad_input("image stream: frame {}: {}", frame, e.what());
  }
  if (l.ascii) throw bad_input("image stream: frame {} is ASCII Netpbm (P2/P3), which cannot be delimited; use P5/P6", frame);
  const std::uint64_t bytes_per = l.maxval > 255 ? 2 : 1;
  return l.data_offset + static_cast<std::size_t>(std::uint64_t(l.header.width) * l.header.height * l.header.channels * bytes_per);
}

}  // namespace

std::vector<std::string_view> split_image_stream(std::string_view bytes) {
  if (bytes.empty()) throw bad_input("image stream: empty input");
  const bool png = bytes.size() >= 8 && std::memcmp(bytes.data(), k_png_signature, 8) == 0;
  const bool pnm = bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '5' || bytes[1] == '6' || bytes[1] == '7' ||
                                                            bytes[1] == '2' || bytes[1] == '3');
  if (!png && !pnm) return {bytes};
  return split_concatenated<std::string_view>(bytes, [&](std::string_view rest, std::size_t frame, std::size_t& len)
                                                  -> std::optional<std::string_view> {
    if (png && rest.size() >= 8 && std::memcmp(rest.data(), k_png_signature, 8) == 0) len = png_length(rest, frame);
    else if (pnm && rest.size() >= 2 && rest[0] == 'P') len = netpbm_length(rest, frame);
    else if (rest.find_first_not_of(" \t\r\n") == std::string_view::npos) return std::nullopt;  // trailing whitespace
    else throw bad_input("image stream: {} bytes after frame {} are not an image of the stream's format", rest.size(), frame);
    return rest.substr(0, len);
  });
}

}  // namespace fest::formats
