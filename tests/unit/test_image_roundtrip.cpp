// Round trips: write -> read gives identical pixels for every format and every depth
// and channel count the format holds; the header agrees; the orientation pattern
// (red at x=1,y=0, blue at x=0,y=1) survives, RGB order and PFM's bottom-up rows
// included.
#include <cmath>
#include <string>
#include <vector>

#include "formats/image/image_io.hpp"
#include "testdata.hpp"
#include "test_image_helpers.hpp"

namespace fest::formats {
namespace {

using fest::test::identical;
using fest::test::orientation_image;
using fest::test::random_image;

struct Case {
  Format format;
  int depth;
  int channels;
  bool ascii = false;
};

const char* short_name(Format f) {
  switch (f) {
    case Format::png: return "png";
    case Format::pgm: return "pgm";
    case Format::ppm: return "ppm";
    case Format::pam: return "pam";
    case Format::pfm: return "pfm";
    case Format::exr: return "exr";
    case Format::tiff: return "tiff";
    default: return "other";
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  return std::string(short_name(c.format)) + "_" +
         (c.depth == CV_8U ? "u8" : c.depth == CV_16U ? "u16" : "f32") + "_c" + std::to_string(c.channels) +
         (c.ascii ? "_ascii" : "");
}

// Every combination each format can hold exactly.
std::vector<Case> exact_cases() {
  std::vector<Case> cases;
  for (int depth : {CV_8U, CV_16U}) {
    for (int c = 1; c <= 4; ++c) cases.push_back({Format::png, depth, c});
    for (int c = 1; c <= 4; ++c) cases.push_back({Format::pam, depth, c});
    for (bool ascii : {false, true}) {
      cases.push_back({Format::pgm, depth, 1, ascii});
      cases.push_back({Format::ppm, depth, 3, ascii});
    }
  }
  for (int c : {1, 3}) cases.push_back({Format::pfm, CV_32F, c});
  for (int c = 1; c <= 4; ++c) cases.push_back({Format::exr, CV_32F, c});
  for (int depth : {CV_8U, CV_16U, CV_32F})
    for (int c : {1, 3, 4}) cases.push_back({Format::tiff, depth, c});
  return cases;
}

class ExactRoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(ExactRoundTrip, RandomPixelsSurviveUnchanged) {
  const Case c = GetParam();
  Image in;
  in.pixels = random_image(37, 23, c.depth, c.channels);  // odd sizes catch stride slips
  in.color_space = c.depth == CV_32F ? ColorSpace::linear : ColorSpace::srgb;
  ImageWriteOptions options;
  options.ascii = c.ascii;
  const std::string bytes = write_image(in, c.format, options);

  const ImageHeader h = read_image_header(bytes, c.format);
  EXPECT_EQ(h.width, 37);
  EXPECT_EQ(h.height, 23);
  EXPECT_EQ(h.channels, c.channels);
  EXPECT_EQ(h.bits, c.depth == CV_8U ? 8 : c.depth == CV_16U ? 16 : 32);
  EXPECT_EQ(h.is_float, c.depth == CV_32F);

  const Image out = read_image(bytes, c.format);
  EXPECT_TRUE(identical(in.pixels, out.pixels));
  EXPECT_EQ(out.color_space, in.color_space);
}

TEST_P(ExactRoundTrip, OrientationAndChannelOrderSurvive) {
  const Case c = GetParam();
  Image in;
  in.pixels = orientation_image(c.depth, c.channels);
  ImageWriteOptions options;
  options.ascii = c.ascii;
  const Image out = read_image(write_image(in, c.format, options), c.format);
  ASSERT_EQ(out.pixels.type(), in.pixels.type());
  ASSERT_EQ(out.pixels.size(), in.pixels.size());
  EXPECT_TRUE(identical(in.pixels, out.pixels));
  // The pattern itself, independently of the comparison above.
  cv::Mat as_double;
  out.pixels.convertTo(as_double, CV_64F);
  const double full = c.depth == CV_8U ? 255 : c.depth == CV_16U ? 65535 : 1.0;
  const double* row0 = as_double.ptr<double>(0);
  EXPECT_EQ(row0[1 * c.channels + 0], full);  // (x=1,y=0) first channel (red)
  EXPECT_EQ(row0[0], 0.0);
  if (c.channels >= 3) {
    EXPECT_EQ(row0[1 * c.channels + 2], 0.0);                   // no blue at the red pixel
    EXPECT_EQ(as_double.ptr<double>(1)[2], full);              // (x=0,y=1) blue
    EXPECT_EQ(as_double.ptr<double>(1)[0], 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, ExactRoundTrip, ::testing::ValuesIn(exact_cases()), case_name);

// Half precision: 11 significant bits, so each value comes back within a relative
// 2^-11 of what was written (round to nearest), and values already representable
// in half come back exactly.
TEST(ImageRoundTrip, ExrHalfWithinHalfPrecision) {
  for (int channels = 1; channels <= 4; ++channels) {
    Image in;
    in.pixels = random_image(19, 11, CV_32F, channels, 11);
    ImageWriteOptions options;
    options.exr_half = true;
    const std::string bytes = write_image(in, Format::exr, options);
    const Image out = read_image(bytes, Format::exr);
    ASSERT_EQ(out.pixels.type(), in.pixels.type());
    const float* a = in.pixels.ptr<float>();
    const float* b = out.pixels.ptr<float>();
    for (std::size_t i = 0; i < in.pixels.total() * std::size_t(channels); ++i)
      ASSERT_LE(std::fabs(a[i] - b[i]), std::ldexp(std::fabs(a[i]), -11)) << "sample " << i;
    // Half is smaller than float on disk for the same pixels.
    EXPECT_LT(bytes.size(), write_image(in, Format::exr).size());

    Image representable;
    out.pixels.copyTo(representable.pixels);
    EXPECT_TRUE(identical(read_image(write_image(representable, Format::exr, options), Format::exr).pixels,
                          representable.pixels));
  }
}

TEST(ImageRoundTrip, ColourSpaceFollowsTheFormat) {
  Image grey;
  grey.pixels = random_image(5, 4, CV_8U, 1);
  EXPECT_EQ(read_image(write_image(grey, Format::png), Format::png).color_space, ColorSpace::srgb);
  EXPECT_EQ(read_image(write_image(grey, Format::tiff), Format::tiff).color_space, ColorSpace::srgb);
  Image hdr;
  hdr.pixels = random_image(5, 4, CV_32F, 1);
  hdr.color_space = ColorSpace::srgb;  // the file formats say linear, whatever was in memory
  EXPECT_EQ(read_image(write_image(hdr, Format::pfm), Format::pfm).color_space, ColorSpace::linear);
  EXPECT_EQ(read_image(write_image(hdr, Format::exr), Format::exr).color_space, ColorSpace::linear);
  EXPECT_EQ(read_image(write_image(hdr, Format::tiff), Format::tiff).color_space, ColorSpace::linear);
}

TEST(ImageRoundTrip, AsciiPnmIsPlainText) {
  Image in;
  in.pixels = random_image(40, 3, CV_16U, 3);
  ImageWriteOptions options;
  options.ascii = true;
  const std::string bytes = write_image(in, Format::ppm, options);
  EXPECT_EQ(bytes.substr(0, 2), "P3");
  for (char ch : bytes) EXPECT_TRUE(ch == '\n' || (ch >= ' ' && ch <= '~'));
  // Netpbm asks for plain-format lines of at most 70 characters.
  std::size_t line = 0;
  for (char ch : bytes) {
    line = ch == '\n' ? 0 : line + 1;
    EXPECT_LE(line, 70u);
  }
  options.ascii = false;
  EXPECT_EQ(write_image(in, Format::ppm, options).substr(0, 2), "P6");
}

TEST(ImageRoundTrip, WritingIsDeterministic) {
  Image in;
  in.pixels = random_image(16, 9, CV_32F, 3);
  for (Format f : {Format::exr, Format::pfm, Format::tiff})
    EXPECT_EQ(write_image(in, f), write_image(in, f)) << short_name(f);
}

// Formats that cannot hold an image refuse it instead of losing data.
TEST(ImageWrite, RefusesWhatTheFormatCannotHold) {
  Image f1, f3, f2, u8_2, u8_4, u16_3, u8_1, d1;
  f1.pixels = random_image(4, 4, CV_32F, 1);
  f2.pixels = random_image(4, 4, CV_32F, 2);
  f3.pixels = random_image(4, 4, CV_32F, 3);
  u8_1.pixels = random_image(4, 4, CV_8U, 1);
  u8_2.pixels = random_image(4, 4, CV_8U, 2);
  u8_4.pixels = random_image(4, 4, CV_8U, 4);
  u16_3.pixels = random_image(4, 4, CV_16U, 3);
  d1.pixels = cv::Mat(4, 4, CV_64F, cv::Scalar(1.0));
  for (Format f : {Format::png, Format::pgm, Format::ppm, Format::pam}) {
    EXPECT_BAD_INPUT(write_image(f1, f));
    EXPECT_BAD_INPUT(write_image(f3, f));
  }
  EXPECT_BAD_INPUT(write_image(u8_4, Format::pgm));
  EXPECT_BAD_INPUT(write_image(u16_3, Format::pgm));
  EXPECT_BAD_INPUT(write_image(u8_1, Format::ppm));
  EXPECT_BAD_INPUT(write_image(u8_1, Format::pfm));
  EXPECT_BAD_INPUT(write_image(u16_3, Format::pfm));
  EXPECT_BAD_INPUT(write_image(f2, Format::pfm));
  EXPECT_BAD_INPUT(write_image(u8_1, Format::exr));
  EXPECT_BAD_INPUT(write_image(u8_2, Format::tiff));
  EXPECT_BAD_INPUT(write_image(Image{}, Format::png));
  for (Format f : {Format::png, Format::pam, Format::pfm, Format::exr, Format::tiff})
    EXPECT_BAD_INPUT(write_image(d1, f));
  EXPECT_BAD_INPUT(write_image(u8_1, Format::ply));
}

TEST(ImageWrite, NonContiguousRoiIsWrittenAsItsPixels) {
  const cv::Mat big = random_image(20, 20, CV_16U, 3);
  Image roi;
  roi.pixels = big(cv::Rect(3, 4, 7, 5));
  for (Format f : {Format::png, Format::ppm, Format::pam, Format::tiff})
    EXPECT_TRUE(identical(read_image(write_image(roi, f), f).pixels, roi.pixels)) << short_name(f);
  Image froi;
  const cv::Mat fbig = random_image(20, 20, CV_32F, 3);
  froi.pixels = fbig(cv::Rect(1, 2, 9, 6));
  for (Format f : {Format::pfm, Format::exr, Format::tiff})
    EXPECT_TRUE(identical(read_image(write_image(froi, f), f).pixels, froi.pixels)) << short_name(f);
}

}  // namespace
}  // namespace fest::formats
