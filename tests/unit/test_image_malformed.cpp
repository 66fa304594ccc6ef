// Malformed input: every case must give fest::Error with Status::bad_input from both
// read_image_header and read_image -- never a crash, a hang or a huge allocation.
// Inputs are built here from valid files written by fest and then damaged.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/image/image_io.hpp"
#include "testdata.hpp"
#include "test_image_helpers.hpp"

namespace fest::formats {
namespace {

using fest::test::random_image;

const std::vector<Format> image_formats = {Format::png, Format::pgm, Format::ppm, Format::pam,
                                           Format::pfm, Format::exr, Format::tiff};

#define expect_rejected(bytes, format)                 \
  do {                                                 \
    SCOPED_TRACE(::testing::Message() << "line " << __LINE__); \
    expect_rejected_impl(bytes, format);               \
  } while (0)

void expect_rejected_impl(const std::string& bytes, Format format) {
  EXPECT_BAD_INPUT(read_image_header(bytes, format));
  EXPECT_BAD_INPUT(read_image(bytes, format));
}

std::string valid(Format f, int depth = CV_8U, int channels = 3) {
  if (f == Format::pgm) channels = 1;
  if (f == Format::pfm || f == Format::exr) depth = CV_32F;
  Image image;
  image.pixels = random_image(6, 5, depth, channels);
  return write_image(image, f);
}

void put_u32_be(std::string& s, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s[at + std::size_t(i)] = static_cast<char>(v >> (24 - 8 * i));
}
void put_u32_le(std::string& s, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s[at + std::size_t(i)] = static_cast<char>(v >> (8 * i));
}
std::uint32_t get_u32_le(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | std::uint8_t(s[at + std::size_t(i)]);
  return v;
}
std::uint16_t get_u16_le(const std::string& s, std::size_t at) {
  return std::uint16_t(std::uint8_t(s[at]) | (std::uint8_t(s[at + 1]) << 8));
}

// Where the value field of a TIFF tag lies (OpenCV writes little-endian "II").
std::size_t tiff_value_at(const std::string& tiff, std::uint16_t tag) {
  const std::size_t ifd = get_u32_le(tiff, 4);
  const std::size_t count = get_u16_le(tiff, ifd);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t entry = ifd + 2 + 12 * i;
    if (get_u16_le(tiff, entry) == tag) return entry + 8;
  }
  ADD_FAILURE() << "tag " << tag << " not in the TIFF fest wrote";
  return 0;
}

// Where the 16-byte value of the EXR dataWindow attribute lies.
std::size_t exr_data_window_at(const std::string& exr) {
  const std::string key("dataWindow\0box2i\0", 17);
  const std::size_t at = exr.find(key);
  EXPECT_NE(at, std::string::npos);
  return at + key.size() + 4;
}

TEST(ImageMalformed, EmptyInputEveryFormat) {
  for (Format f : image_formats) expect_rejected("", f);
}

TEST(ImageMalformed, NotAnImageFormat) {
  EXPECT_BAD_INPUT(read_image_header(valid(Format::png), Format::ply));
  EXPECT_BAD_INPUT(read_image(valid(Format::png), Format::csv));
}

// Each valid file handed to every other format's reader is refused by its magic.
TEST(ImageMalformed, WrongMagicEveryPair) {
  const std::vector<Format> distinct = {Format::png, Format::pam, Format::pfm, Format::exr, Format::tiff};
  for (Format written : distinct)
    for (Format read : distinct)
      if (written != read) expect_rejected(valid(written), read);
  expect_rejected(std::string("\x89PNX\r\n\x1a\n", 8) + valid(Format::png).substr(8), Format::png);
  expect_rejected("P9\n2 2\n255\n0123", Format::pgm);
  expect_rejected("P1\n2 2\n0 1 1 0\n", Format::pgm);  // PBM bitmaps are not handled
  expect_rejected("P4\n8 1\n\xff", Format::pgm);
  expect_rejected("PX\n2 2\n-1\n", Format::pfm);
  expect_rejected("P6\n1 1\n255\nabc", Format::pfm);
  std::string tiff = valid(Format::tiff);
  expect_rejected("XX" + tiff.substr(2), Format::tiff);
  std::string big_tiff = tiff;
  big_tiff[2] = 43;  // BigTIFF
  expect_rejected(big_tiff, Format::tiff);
  std::string exr = valid(Format::exr);
  exr[0] = 0x77;
  expect_rejected(exr, Format::exr);
}

TEST(ImageMalformed, TruncatedHeaders) {
  const std::string png = valid(Format::png);
  for (std::size_t n : {1, 7, 8, 12, 20, 32}) expect_rejected(png.substr(0, n), Format::png);
  for (const char* s : {"P", "P5", "P5\n3", "P5\n3 2\n", "P5\n3 2\n255", "P2\n3 2 # c", "P6 3 2"})
    expect_rejected(s, Format::pgm);
  expect_rejected("P7\nWIDTH 2\nHEIGHT 2\n", Format::pam);
  expect_rejected("P7\nWIDTH 2\nHEIGHT 2\nDEPTH 1\nMAXVAL 255\n", Format::pam);      // no ENDHDR
  expect_rejected("P7\nWIDTH 2\nHEIGHT 2\nMAXVAL 255\nENDHDR\n1234", Format::pam);  // no DEPTH
  for (const char* s : {"PF", "PF\n3", "Pf\n2 2\n", "Pf\n2 2\n-1.0"}) expect_rejected(s, Format::pfm);
  const std::string tiff = valid(Format::tiff);
  for (std::size_t n : {2, 4, 7, 8}) expect_rejected(tiff.substr(0, n), Format::tiff);
  const std::string exr = valid(Format::exr);
  for (std::size_t n : {3, 6, 8, 20, 100, 200}) expect_rejected(exr.substr(0, n), Format::exr);
}

TEST(ImageMalformed, TruncatedPixelData) {
  for (Format f : {Format::pgm, Format::ppm, Format::pam})
    for (int depth : {CV_8U, CV_16U}) {
      const std::string bytes = valid(f, depth, f == Format::pam ? 4 : 3);
      expect_rejected(bytes.substr(0, bytes.size() - 1), f);
    }
  expect_rejected("P2\n2 2\n255\n1 2 3", Format::pgm);  // a sample missing
  EXPECT_BAD_INPUT(read_image("P3\n2 1\n255\n1 2 3 4 5 x\n", Format::ppm));  // header is fine
  const std::string pfm = valid(Format::pfm);
  expect_rejected(pfm.substr(0, pfm.size() - 1), Format::pfm);
  const std::string png = valid(Format::png);
  expect_rejected(png.substr(0, png.size() * 3 / 4), Format::png);
  const std::string tiff = valid(Format::tiff);
  expect_rejected(tiff.substr(0, tiff.size() / 2), Format::tiff);
  // EXR: the chunk offset table is intact but the pixel chunks are gone.
  const std::string exr = valid(Format::exr);
  EXPECT_BAD_INPUT(read_image(exr.substr(0, exr.size() - 40), Format::exr));
}

// Damage inside the compressed data is found by the decoder and still reported as bad
// input (libpng checks CRCs; zlib the stream).
TEST(ImageMalformed, CorruptCompressedData) {
  Image image;
  image.pixels = random_image(64, 64, CV_8U, 3);
  std::string png = write_image(image, Format::png);
  const std::size_t idat = png.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  for (std::size_t i = idat + 20; i < idat + 60; ++i) png[i] = static_cast<char>(~png[i]);
  EXPECT_BAD_INPUT(read_image(png, Format::png));
  // A smooth image, so ZIP compresses it (OpenEXR stores incompressible chunks raw,
  // where damage is undetectable by design).
  Image smooth;
  smooth.pixels = cv::Mat(64, 64, CV_32FC3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) smooth.pixels.at<cv::Vec3f>(y, x) = cv::Vec3f(float(x), float(y), 1.0f);
  std::string exr = write_image(smooth, Format::exr);
  ASSERT_LT(exr.size(), smooth.pixels.total() * 12 / 2);
  for (std::size_t i = exr.size() - 120; i < exr.size() - 20; ++i) exr[i] = static_cast<char>(i * 7);
  EXPECT_BAD_INPUT(read_image(exr, Format::exr));
}

TEST(ImageMalformed, AbsurdDimensions) {
  for (const char* s : {"P5\n100000 100000\n255\n", "P2\n100000 100000\n255\n1", "P6\n0 5\n255\n",
                        "P5\n5 0\n255\n", "P5\n4294967297 1\n255\n", "P5\n-3 2\n255\n"})
    expect_rejected(s, Format::pgm);
  expect_rejected("P7\nWIDTH 100000\nHEIGHT 100000\nDEPTH 1\nMAXVAL 255\nENDHDR\n", Format::pam);
  expect_rejected("PF\n100000 100000\n-1\n", Format::pfm);
  // Exactly 2^30 values passes the size limit, then fails on the data it lacks --
  // before anything is allocated.
  expect_rejected("P5\n32768 32768\n255\n0123", Format::pgm);

  std::string png = valid(Format::png);
  put_u32_be(png, 16, 100000);
  put_u32_be(png, 20, 100000);
  expect_rejected(png, Format::png);
  put_u32_be(png, 16, 0);
  expect_rejected(png, Format::png);
  // Plausible size, but far more pixels than the compressed data could ever hold.
  png = valid(Format::png);
  put_u32_be(png, 16, 30000);
  put_u32_be(png, 20, 30000);
  expect_rejected(png, Format::png);

  for (std::uint32_t w : {100000u, 0u, 0x80000000u}) {
    std::string tiff = valid(Format::tiff);
    put_u32_le(tiff, tiff_value_at(tiff, 256), w);
    put_u32_le(tiff, tiff_value_at(tiff, 257), 100000);
    expect_rejected(tiff, Format::tiff);
  }

  std::string exr = valid(Format::exr);
  const std::size_t box = exr_data_window_at(exr);
  put_u32_le(exr, box + 8, 99999);
  put_u32_le(exr, box + 12, 99999);
  expect_rejected(exr, Format::exr);
  put_u32_le(exr, box, 0x80000000u);  // xMin = INT_MIN: width would overflow an int
  put_u32_le(exr, box + 8, 0x7fffffffu);
  expect_rejected(exr, Format::exr);
  put_u32_le(exr, box, 10);  // xMax < xMin
  put_u32_le(exr, box + 8, 5);
  expect_rejected(exr, Format::exr);
}

TEST(ImageMalformed, MaxvalOutOfRange) {
  // std::string literals keep the embedded NUL pixel bytes (a const char* would stop at them).
  using namespace std::string_literals;
  for (const std::string& s : {"P5\n2 1\n0\n\0\0"s, "P5\n2 1\n70000\n\0\0\0\0"s, "P2\n2 1\n0\n0 0\n"s, "P2\n2 1\n-1\n0 0\n"s})
    expect_rejected(s, Format::pgm);
  expect_rejected("P7\nWIDTH 1\nHEIGHT 1\nDEPTH 1\nMAXVAL 70000\nENDHDR\n\0\0", Format::pam);
  expect_rejected("P7\nWIDTH 1\nHEIGHT 1\nDEPTH 1\nMAXVAL 0\nENDHDR\n\0", Format::pam);
}

TEST(ImageMalformed, SampleAboveMaxval) {
  EXPECT_BAD_INPUT(read_image("P2\n2 1\n100\n50 200\n", Format::pgm));
  EXPECT_BAD_INPUT(read_image(std::string("P5\n2 1\n100\n") + char(50) + char(200), Format::pgm));
  EXPECT_BAD_INPUT(read_image(std::string("P5\n1 1\n1000\n") + char(0x03) + char(0xe9), Format::pgm));
}

TEST(ImageMalformed, PamHeaderFields) {
  const std::string pixels(16, '\0');
  for (const char* header : {
           "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 1\nMAXVAL 255\nTUPLTYPE CMYK\nENDHDR\n",
           "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 1\nMAXVAL 255\nTUPLTYPE RGB\nENDHDR\n",
           "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 5\nMAXVAL 255\nENDHDR\n",
           "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 0\nMAXVAL 255\nENDHDR\n",
           "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 1\nMAXVAL 255\nCOLOUR blue\nENDHDR\n",
           "P7\nWIDTH two\nHEIGHT 2\nDEPTH 1\nMAXVAL 255\nENDHDR\n",
       })
    expect_rejected(header + pixels, Format::pam);
}

TEST(ImageMalformed, PfmHeaderFields) {
  const std::string pixels(64, '\0');
  for (const char* header : {"PF\n-2 2\n-1\n", "Pf\n2 -2\n-1\n", "Pf\n-2 -2\n1\n", "Pf\n2 2\n0\n",
                             "Pf\n2 2\nnan\n", "Pf\n2 2\ninf\n", "Pf\n2 2\nabc\n", "Pf\n2.5 2\n-1\n"})
    expect_rejected(header + pixels, Format::pfm);
}

TEST(ImageMalformed, ExrGarbageAndUnsupportedLayouts) {
  const std::string magic("\x76\x2f\x31\x01", 4);
  expect_rejected(magic + std::string("\x02\0\0\0", 4) + std::string(64, '\x5a'), Format::exr);
  expect_rejected(magic + std::string(200, '\xff'), Format::exr);
  expect_rejected(magic + std::string("\x02\0\0\0", 4) + std::string(64, '\0'), Format::exr);
  std::string exr = valid(Format::exr);
  std::string multipart = exr;
  multipart[5] = 0x10;  // version flag 0x1000: multi-part
  expect_rejected(multipart, Format::exr);
  std::string deep = exr;
  deep[5] = 0x08;  // 0x800: deep data
  expect_rejected(deep, Format::exr);
  std::string version = exr;
  version[4] = 3;
  expect_rejected(version, Format::exr);

  // A channel named other than R,G,B,A,Y.
  Image grey;
  grey.pixels = random_image(4, 4, CV_32F, 1);
  std::string y_only = write_image(grey, Format::exr);
  const std::size_t chlist = y_only.find(std::string("chlist\0", 7));
  ASSERT_NE(chlist, std::string::npos);
  y_only[chlist + 7 + 4] = 'Z';
  expect_rejected(y_only, Format::exr);
  // An attribute whose size runs past the end of the file.
  std::string huge_attribute = exr;
  put_u32_le(huge_attribute, exr.find(std::string("chlist\0", 7)) + 7, 0x7ffffff0u);
  expect_rejected(huge_attribute, Format::exr);
  // The chunk offset table (one chunk here: its 8-byte entry holds its own end)
  // points far outside the file.
  std::string offsets = exr;
  std::size_t table = 0;
  for (std::size_t p = 8; p + 8 <= offsets.size() && table == 0; ++p)
    if (get_u32_le(offsets, p) == p + 8 && get_u32_le(offsets, p + 4) == 0) table = p;
  ASSERT_NE(table, 0u);
  put_u32_le(offsets, table, 0x7ffffff0u);
  EXPECT_BAD_INPUT(read_image(offsets, Format::exr));
}

TEST(ImageMalformed, TiffBrokenIfd) {
  const std::string tiff = valid(Format::tiff);
  std::string past_end = tiff;
  put_u32_le(past_end, 4, 0xffffff00u);
  expect_rejected(past_end, Format::tiff);
  std::string inside_header = tiff;
  put_u32_le(inside_header, 4, 2);
  expect_rejected(inside_header, Format::tiff);
  std::string too_many_entries = tiff;
  const std::size_t ifd = get_u32_le(tiff, 4);
  too_many_entries[ifd] = '\xff';
  too_many_entries[ifd + 1] = '\xff';
  expect_rejected(too_many_entries, Format::tiff);
  std::string strip_outside = tiff;
  put_u32_le(strip_outside, tiff_value_at(tiff, 273), 0x7fff0000u);
  expect_rejected(strip_outside, Format::tiff);
  std::string twelve_bit = tiff;
  // BitsPerSample of a 3-channel file is an offset to 3 SHORTs; rewrite the first.
  const std::size_t bits_at = get_u32_le(tiff, tiff_value_at(tiff, 258));
  twelve_bit[bits_at] = 12;
  twelve_bit[bits_at + 2] = 12;
  twelve_bit[bits_at + 4] = 12;
  expect_rejected(twelve_bit, Format::tiff);
  std::string no_width = tiff;
  const std::size_t width_entry = tiff_value_at(tiff, 256) - 8;
  no_width[width_entry] = '\x01';  // tag 256 becomes 257+...: ImageWidth is gone
  no_width[width_entry + 1] = '\x7f';
  expect_rejected(no_width, Format::tiff);
}

TEST(ImageMalformed, PngChunkStructure) {
  const std::string png = valid(Format::png);
  std::string bad_depth = png;
  bad_depth[24] = 3;
  expect_rejected(bad_depth, Format::png);
  std::string bad_type = png;
  bad_type[25] = 5;
  expect_rejected(bad_type, Format::png);
  std::string interlace = png;
  interlace[28] = 2;
  expect_rejected(interlace, Format::png);
  // IEND right after IHDR: no image data at all.
  const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  expect_rejected(png.substr(0, 33) + iend, Format::png);
  // A chunk claiming 2 GiB.
  std::string huge_chunk = png;
  put_u32_be(huge_chunk, 33, 0x7ffffff0u);
  expect_rejected(huge_chunk, Format::png);
}

// Inputs that once broke a reader (fuzzing), kept in tests/data/regress/image/ and named
// <anything>.<format extension>: each must read or give bad_input.
TEST(ImageRegressions, EveryStoredInputIsHandled) {
  namespace fs = std::filesystem;
  const fs::path dir = fest::test::fixture("regress/image");
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no regression inputs";
  int replayed = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    Format f;
    if (ext == ".png") f = Format::png;
    else if (ext == ".pgm") f = Format::pgm;
    else if (ext == ".ppm") f = Format::ppm;
    else if (ext == ".pam") f = Format::pam;
    else if (ext == ".pfm") f = Format::pfm;
    else if (ext == ".exr") f = Format::exr;
    else if (ext == ".tif" || ext == ".tiff") f = Format::tiff;
    else continue;
    const std::string bytes = fest::test::slurp(entry.path().string());
    try {
      (void)read_image(bytes, f);
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), Status::bad_input) << entry.path() << ": " << e.what();
    }
    ++replayed;
  }
  if (replayed == 0) GTEST_SKIP() << "no regression inputs";
}

}  // namespace
}  // namespace fest::formats
