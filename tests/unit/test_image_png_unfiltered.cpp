// The PNG writer behind ImageWriteOptions::png_huffman_only (capture's raw shots):
// whatever it writes, libpng (through OpenCV, an independent decoder) reads back
// identically, for every depth and channel count PNG holds; the rows carry filter 0 and
// the IDAT stream is split into chunks of at most 1 MiB as the PNG spec allows.
#include <cstdint>
#include <string>
#include <vector>

#include <zlib.h>

#include "formats/image/image_io.hpp"
#include "test_image_helpers.hpp"

namespace fest::formats {
namespace {

using fest::test::identical;
using fest::test::orientation_image;
using fest::test::random_image;

std::uint32_t be32(const std::string& s, std::size_t at) {
  return std::uint32_t(std::uint8_t(s[at])) << 24 | std::uint32_t(std::uint8_t(s[at + 1])) << 16 |
         std::uint32_t(std::uint8_t(s[at + 2])) << 8 | std::uint32_t(std::uint8_t(s[at + 3]));
}

struct Chunks {
  std::vector<std::string> types;
  std::vector<std::size_t> lengths;
  std::string idat;
};

// Walks the chunks after the signature, checking each CRC.
Chunks chunks_of(const std::string& png) {
  Chunks c;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t n = be32(png, at);
    c.types.push_back(png.substr(at + 4, 4));
    c.lengths.push_back(n);
    const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), uInt(4 + n));
    EXPECT_EQ(crc, be32(png, at + 8 + n)) << "CRC of chunk " << c.types.back();
    if (c.types.back() == "IDAT") c.idat += png.substr(at + 8, n);
    at += 12 + n;
  }
  return c;
}

ImageWriteOptions raw_shot_options() {
  ImageWriteOptions o;
  o.png_compression = 1;
  o.png_huffman_only = true;
  return o;
}

TEST(PngUnfiltered, RoundTripsEveryDepthAndChannelCount) {
  for (int depth : {CV_8U, CV_16U})
    for (int channels = 1; channels <= 4; ++channels) {
      SCOPED_TRACE(testing::Message() << "depth " << depth << " channels " << channels);
      const cv::Mat random = random_image(37, 29, depth, channels);
      EXPECT_TRUE(identical(read_image(write_image(Image{random}, Format::png, raw_shot_options()), Format::png).pixels,
                            random));
      const cv::Mat pattern = orientation_image(depth, channels);
      EXPECT_TRUE(identical(read_image(write_image(Image{pattern}, Format::png, raw_shot_options()), Format::png).pixels,
                            pattern));
    }
}

TEST(PngUnfiltered, RowsUnfilteredAndIdatSplitAtOneMebibyte) {
  // 700 x 400 RGBA 16-bit uniform noise: 2.24 MB of bytes that Huffman coding cannot
  // shrink, so the stream needs a second (and third) IDAT chunk.
  const cv::Mat m = random_image(700, 400, CV_16U, 4, 11);
  const std::string png = write_image(Image{m}, Format::png, raw_shot_options());
  const Chunks c = chunks_of(png);
  ASSERT_GE(c.types.size(), 4u);
  EXPECT_EQ(c.types.front(), "IHDR");
  EXPECT_EQ(c.types.back(), "IEND");
  std::size_t idats = 0;
  for (std::size_t i = 0; i < c.types.size(); ++i)
    if (c.types[i] == "IDAT") {
      ++idats;
      EXPECT_LE(c.lengths[i], std::size_t(1) << 20);
    }
  EXPECT_GE(idats, 2u);
  // Inflate and look at the first byte of every row: filter type 0.
  const std::size_t row_bytes = 1 + 700 * 4 * 2;
  std::string raw(row_bytes * 400, '\0');
  uLongf raw_size = uLongf(raw.size());
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &raw_size, reinterpret_cast<const Bytef*>(c.idat.data()),
                       uLong(c.idat.size())),
            Z_OK);
  ASSERT_EQ(raw_size, raw.size());
  for (int y = 0; y < 400; ++y) EXPECT_EQ(raw[std::size_t(y) * row_bytes], '\0') << "row " << y;
  // Big-endian samples: the first sample's high byte follows the first filter byte.
  EXPECT_EQ(std::uint8_t(raw[1]), m.at<cv::Vec4w>(0, 0)[0] >> 8);
  EXPECT_TRUE(identical(read_image(png, Format::png).pixels, m));
}

TEST(PngUnfiltered, HuffmanCodingShrinksASlowRampWithNoise) {
  // Like a raw shot: a slowly varying level (the high bytes repeat) plus 6 bits of noise
  // (the low bytes are nearly uniform). Huffman coding of the unfiltered bytes needs
  // about 1-2 bits per high byte and 8 per low byte: well under 80 % of the raw rows.
  cv::Mat m(120, 160, CV_16UC3);
  cv::RNG rng(3);
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      for (int c = 0; c < 3; ++c) m.at<cv::Vec3w>(y, x)[c] = std::uint16_t(8000 + 10 * x + 5 * y + rng.uniform(0, 64));
  const std::size_t raw_rows = 120 * (1 + 160 * 3 * 2);
  const std::string png = write_image(Image{m}, Format::png, raw_shot_options());
  EXPECT_LT(png.size(), raw_rows * 8 / 10);
  EXPECT_TRUE(identical(read_image(png, Format::png).pixels, m));
}

}  // namespace
}  // namespace fest::formats
