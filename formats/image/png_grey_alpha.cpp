// Two-channel (grey + alpha) PNG writer. OpenCV's PNG encoder accepts only 1, 3 or 4
// channels, and expanding to RGBA would not read back as 2 channels, so the few
// chunks of such a file are written here (PNG spec: IHDR, IDAT, IEND; filter 0).
#include <cstdint>
#include <string>

#include <zlib.h>

#include "core/error.hpp"
#include "formats/image/image_codecs.hpp"

namespace fest::formats::image_detail {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v >> 24);
  out += static_cast<char>((v >> 16) & 0xff);
  out += static_cast<char>((v >> 8) & 0xff);
  out += static_cast<char>(v & 0xff);
}

void put_chunk(std::string& out, const char* type, std::string_view data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t type_at = out.size();
  out.append(type, 4);
  out.append(data);
  // The CRC covers the type and the data.
  const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(out.data() + type_at), uInt(4 + data.size()));
  put_u32(out, static_cast<std::uint32_t>(crc));
}

}  // namespace

std::string encode_png_grey_alpha(const cv::Mat& pixels) {
  const bool sixteen = pixels.depth() == CV_16U;
  const std::size_t row_bytes = std::size_t(pixels.cols) * 2 * (sixteen ? 2 : 1);

  // Each row: filter type 0 (none), then the samples, 16-bit ones big-endian.
  std::string raw;
  raw.reserve((row_bytes + 1) * std::size_t(pixels.rows));
  for (int y = 0; y < pixels.rows; ++y) {
    raw += '\0';
    if (sixteen) {
      const std::uint16_t* row = pixels.ptr<std::uint16_t>(y);
      for (int i = 0; i < pixels.cols * 2; ++i) {
        raw += static_cast<char>(row[i] >> 8);
        raw += static_cast<char>(row[i] & 0xff);
      }
    } else {
      raw.append(reinterpret_cast<const char*>(pixels.ptr<std::uint8_t>(y)), row_bytes);
    }
  }
  uLongf packed_size = compressBound(uLong(raw.size()));
  std::string packed(packed_size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(raw.data()),
                uLong(raw.size()), 6) != Z_OK)
    throw runtime_failure("PNG writer: zlib compression failed");
  packed.resize(packed_size);

  std::string out("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  put_u32(ihdr, static_cast<std::uint32_t>(pixels.cols));
  put_u32(ihdr, static_cast<std::uint32_t>(pixels.rows));
  ihdr += static_cast<char>(sixteen ? 16 : 8);
  ihdr += static_cast<char>(4);  // colour type 4: grey + alpha
  ihdr += std::string(3, '\0');  // deflate, adaptive filtering, no interlace
  put_chunk(out, "IHDR", ihdr);
  // IDAT chunks of at most 1 MiB: readers handle any split, and chunk lengths stay small.
  constexpr std::size_t idat_max = std::size_t(1) << 20;
  for (std::size_t at = 0; at < packed.size(); at += idat_max)
    put_chunk(out, "IDAT", std::string_view(packed).substr(at, idat_max));
  put_chunk(out, "IEND", {});
  return out;
}

}  // namespace fest::formats::image_detail
