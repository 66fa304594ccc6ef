// PNG written here, through zlib, rather than by OpenCV's encoder, in two cases:
// - two channels (grey + alpha), which OpenCV's encoder refuses (expanding to RGBA would
//   not read back as 2 channels);
// - noisy raw data (capture's shots) with Huffman coding only: rows are stored with filter
//   0 (none), which on such data compresses better than libpng's adaptive filter choice
//   (the high bytes of 16-bit samples vary slowly, the low bytes are noise that no filter
//   predicts) and skips trying five filters per row: on the simulated station's shots
//   about 30 % less CPU than OpenCV at level 1 + Huffman-only, and 3 % smaller.
// A PNG is a signature and chunks (PNG spec: IHDR, IDAT, IEND), each with a CRC-32.
#include <algorithm>
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

// PNG colour types by channel count: grey, grey + alpha, RGB, RGBA.
constexpr char kColourType[5] = {0, 0, 4, 2, 6};

// Deflates the filtered rows in bands of a few rows, so that the raw bytes stay in cache.
class RowDeflater {
 public:
  RowDeflater(int level, int strategy) {
    if (deflateInit2(&z_, level, Z_DEFLATED, 15, 8, strategy) != Z_OK)
      throw runtime_failure("PNG writer: zlib initialisation failed");
  }
  ~RowDeflater() { deflateEnd(&z_); }
  RowDeflater(const RowDeflater&) = delete;
  RowDeflater& operator=(const RowDeflater&) = delete;

  void feed(const std::string& raw, bool last) {
    z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
    z_.avail_in = uInt(raw.size());
    const int flush = last ? Z_FINISH : Z_NO_FLUSH;
    for (;;) {
      if (packed_.size() - z_.total_out < 65536) packed_.resize(packed_.size() + std::max<std::size_t>(65536, raw.size()));
      z_.next_out = reinterpret_cast<Bytef*>(packed_.data() + z_.total_out);
      z_.avail_out = uInt(packed_.size() - z_.total_out);
      const int rc = deflate(&z_, flush);
      if (rc == Z_STREAM_END) break;
      if (rc != Z_OK && rc != Z_BUF_ERROR) throw runtime_failure("PNG writer: zlib compression failed");
      if (!last && z_.avail_in == 0) break;
    }
  }
  std::string take() {
    packed_.resize(z_.total_out);
    return std::move(packed_);
  }

 private:
  z_stream z_{};
  std::string packed_;
};

}  // namespace

std::string encode_png_unfiltered(const cv::Mat& pixels, int level, int strategy) {
  const bool sixteen = pixels.depth() == CV_16U;
  const int channels = pixels.channels();
  if (channels < 1 || channels > 4 || (!sixteen && pixels.depth() != CV_8U))
    throw runtime_failure("PNG writer: 1 to 4 channels of 8 or 16 bits expected");
  const std::size_t samples = std::size_t(pixels.cols) * std::size_t(channels);
  const std::size_t row_bytes = samples * (sixteen ? 2 : 1);

  RowDeflater deflater(level, strategy);
  constexpr int kBandRows = 16;
  std::string raw;
  for (int y0 = 0; y0 < pixels.rows; y0 += kBandRows) {
    const int y1 = std::min(pixels.rows, y0 + kBandRows);
    raw.resize((row_bytes + 1) * std::size_t(y1 - y0));
    char* out = raw.data();
    for (int y = y0; y < y1; ++y) {
      *out++ = '\0';  // filter type 0: none
      if (sixteen) {  // samples big-endian
        const std::uint16_t* row = pixels.ptr<std::uint16_t>(y);
        for (std::size_t i = 0; i < samples; ++i) {
          out[2 * i] = static_cast<char>(row[i] >> 8);
          out[2 * i + 1] = static_cast<char>(row[i] & 0xff);
        }
      } else {
        std::copy_n(pixels.ptr<char>(y), row_bytes, out);
      }
      out += row_bytes;
    }
    deflater.feed(raw, y1 == pixels.rows);
  }
  const std::string packed = deflater.take();

  std::string out("\x89PNG\r\n\x1a\n", 8);
  out.reserve(packed.size() + 1024);
  std::string ihdr;
  put_u32(ihdr, static_cast<std::uint32_t>(pixels.cols));
  put_u32(ihdr, static_cast<std::uint32_t>(pixels.rows));
  ihdr += static_cast<char>(sixteen ? 16 : 8);
  ihdr += kColourType[channels];
  ihdr += std::string(3, '\0');  // deflate, adaptive filtering (method 0), no interlace
  put_chunk(out, "IHDR", ihdr);
  // IDAT chunks of at most 1 MiB: readers handle any split, and chunk lengths stay small.
  constexpr std::size_t idat_max = std::size_t(1) << 20;
  for (std::size_t at = 0; at < packed.size(); at += idat_max)
    put_chunk(out, "IDAT", std::string_view(packed).substr(at, idat_max));
  put_chunk(out, "IEND", {});
  return out;
}

std::string encode_png_grey_alpha(const cv::Mat& pixels) { return encode_png_unfiltered(pixels, 6, Z_DEFAULT_STRATEGY); }

}  // namespace fest::formats::image_detail
