// Real files from the test data, and the hand-made fixtures in tests/data/image
// (tests/data/image/make_fixtures.py states their content).
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "formats/image/image_io.hpp"
#include "testdata.hpp"
#include "test_image_helpers.hpp"

namespace fest::formats {
namespace {

using fest::test::fixture;
using fest::test::identical;
using fest::test::slurp;

// Re-encoding an integer image into every integer format it fits gives it back.
void expect_survives_integer_formats(const Image& image) {
  std::vector<Format> formats = {Format::png, Format::pam, Format::tiff};
  if (image.pixels.channels() == 1) formats.push_back(Format::pgm);
  if (image.pixels.channels() == 3) formats.push_back(Format::ppm);
  for (Format f : formats) EXPECT_TRUE(identical(read_image(write_image(image, f), f).pixels, image.pixels));
}

TEST(ImageRealFiles, CameraPngIsGrey8Bit512) {
  FEST_REQUIRE_TESTDATA(path, "images/camera.png");
  const std::string bytes = slurp(path);
  const ImageHeader h = read_image_header(bytes, Format::png);
  EXPECT_EQ(h.width, 512);
  EXPECT_EQ(h.height, 512);
  EXPECT_EQ(h.channels, 1);
  EXPECT_EQ(h.bits, 8);
  const Image image = read_image(bytes, Format::png);
  EXPECT_EQ(image.pixels.type(), CV_8UC1);
  EXPECT_EQ(image.pixels.size(), cv::Size(512, 512));
  EXPECT_EQ(image.color_space, ColorSpace::srgb);
  expect_survives_integer_formats(image);
}

TEST(ImageRealFiles, AstronautPngIsRgb8Bit512) {
  FEST_REQUIRE_TESTDATA(path, "faces/astronaut.png");
  const std::string bytes = slurp(path);
  const ImageHeader h = read_image_header(bytes, Format::png);
  EXPECT_EQ(h.width, 512);
  EXPECT_EQ(h.height, 512);
  EXPECT_EQ(h.channels, 3);
  const Image image = read_image(bytes, Format::png);
  EXPECT_EQ(image.pixels.type(), CV_8UC3);
  expect_survives_integer_formats(image);
  // The astronaut's suit is white and the background is dark: channels span most of
  // the 8-bit range.
  const nlohmann::json d = describe_image(image);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(d["min"][c].get<double>(), 30.0);
    EXPECT_GE(d["max"][c].get<double>(), 225.0);
  }
}

TEST(ImageRealFiles, CityExrIsFloatRgb1024x512) {
  FEST_REQUIRE_TESTDATA(path, "hdr/city.exr");
  const std::string bytes = slurp(path);
  const ImageHeader h = read_image_header(bytes, Format::exr);
  EXPECT_EQ(h.width, 1024);
  EXPECT_EQ(h.height, 512);
  EXPECT_EQ(h.channels, 3);
  EXPECT_TRUE(h.is_float);
  const Image image = read_image(bytes, Format::exr);
  EXPECT_EQ(image.pixels.type(), CV_32FC3);
  EXPECT_EQ(image.color_space, ColorSpace::linear);
  // The file's own history attribute says "oiiotool --clamp:min=0", but it is stored
  // with lossy DWAA compression (compression attribute 9), whose ringing may dip just
  // below 0: every sample is finite and none is more than slightly negative.
  EXPECT_TRUE(cv::checkRange(image.pixels));
  double lo = 0;
  cv::minMaxLoc(image.pixels.reshape(1), &lo);
  EXPECT_GE(lo, -0.01);
  for (Format f : {Format::exr, Format::pfm, Format::tiff})
    EXPECT_TRUE(identical(read_image(write_image(image, f), f).pixels, image.pixels));
}

TEST(ImageRealFiles, EveryHdrFileReads) {
  FEST_REQUIRE_TESTDATA(dir, "hdr");
  for (const char* name : {"courtyard.exr", "forest.exr", "matcap_clay_studio.exr", "night.exr"}) {
    const Image image = read_image(slurp(dir + "/" + name), Format::exr);
    EXPECT_EQ(image.pixels.channels(), 3) << name;
    EXPECT_TRUE(cv::checkRange(image.pixels)) << name;
  }
}

// PFM stores rows bottom to top; the sign of the scale is the byte order.
TEST(ImageFixtures, PfmGreyBothByteOrders) {
  for (const char* name : {"image/grey_big_endian.pfm", "image/grey_little_endian.pfm"}) {
    const std::string bytes = slurp(fixture(name));
    ASSERT_FALSE(bytes.empty()) << name;
    const Image image = read_image(bytes, Format::pfm);
    ASSERT_EQ(image.pixels.type(), CV_32FC1) << name;
    ASSERT_EQ(image.pixels.size(), cv::Size(2, 2));
    EXPECT_EQ(image.pixels.at<float>(0, 0), 1.0f) << name;
    EXPECT_EQ(image.pixels.at<float>(0, 1), 2.0f) << name;  // (x=1, y=0)
    EXPECT_EQ(image.pixels.at<float>(1, 0), 3.0f) << name;
    EXPECT_EQ(image.pixels.at<float>(1, 1), 4.0f) << name;
    EXPECT_EQ(image.color_space, ColorSpace::linear);
  }
}

TEST(ImageFixtures, PfmColourBothByteOrdersInRgbOrder) {
  for (const char* name : {"image/colour_big_endian.pfm", "image/colour_little_endian.pfm"}) {
    const Image image = read_image(slurp(fixture(name)), Format::pfm);
    ASSERT_EQ(image.pixels.type(), CV_32FC3) << name;
    EXPECT_EQ(image.pixels.at<cv::Vec3f>(0, 0), cv::Vec3f(0, 0, 1)) << name;  // blue
    EXPECT_EQ(image.pixels.at<cv::Vec3f>(0, 1), cv::Vec3f(1, 0, 0)) << name;  // red at (x=1,y=0)
    EXPECT_EQ(image.pixels.at<cv::Vec3f>(1, 0), cv::Vec3f(0, 1, 0)) << name;  // green
    EXPECT_EQ(image.pixels.at<cv::Vec3f>(1, 1), cv::Vec3f(0.5f, 0.25f, -2.0f)) << name;
  }
}

TEST(ImageFixtures, PfmWrittenLittleEndianBottomUp) {
  Image image = read_image(slurp(fixture("image/grey_big_endian.pfm")), Format::pfm);
  // Written back it is byte for byte the little-endian fixture but for the scale text.
  const std::string written = write_image(image, Format::pfm);
  const std::string expected = slurp(fixture("image/grey_little_endian.pfm"));
  ASSERT_GE(written.size(), 16u);
  EXPECT_EQ(written.substr(written.size() - 16), expected.substr(expected.size() - 16));
  EXPECT_EQ(read_image_header(written, Format::pfm).channels, 1);
}

TEST(ImageFixtures, AsciiPgmWithCommentsAndMaxval1000) {
  const std::string bytes = slurp(fixture("image/comments_ascii.pgm"));
  const ImageHeader h = read_image_header(bytes, Format::pgm);
  EXPECT_EQ(h.width, 2);
  EXPECT_EQ(h.bits, 16);  // maxval 1000 > 255
  const Image image = read_image(bytes, Format::pgm);
  ASSERT_EQ(image.pixels.type(), CV_16UC1);
  // Samples are kept as stored, not rescaled to 65535.
  EXPECT_EQ(image.pixels.at<std::uint16_t>(0, 1), 2);
  EXPECT_EQ(image.pixels.at<std::uint16_t>(1, 0), 3);
}

TEST(ImageFixtures, RawPpmPatternInRgbOrder) {
  const Image image = read_image(slurp(fixture("image/pattern_raw.ppm")), Format::ppm);
  ASSERT_EQ(image.pixels.type(), CV_8UC3);
  EXPECT_EQ(image.pixels.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 0, 0));
  EXPECT_EQ(image.pixels.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 255));
  // And through every other format that holds 8-bit RGB, the red pixel stays put.
  for (Format f : {Format::png, Format::pam, Format::tiff})
    EXPECT_EQ(read_image(write_image(image, f), f).pixels.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 0, 0));
}

// Raw and plain encodings of the same samples read the same (OpenCV does not agree
// with itself here, one reason the Netpbm codec is fest's own).
TEST(ImageFixtures, RawAndPlainPgmAgreeForOddMaxval) {
  const std::string raw = std::string("P5\n2 1\n100\n") + char(50) + char(100);
  const std::string plain = "P2\n2 1\n100\n50 100\n";
  EXPECT_TRUE(identical(read_image(raw, Format::pgm).pixels, read_image(plain, Format::pgm).pixels));
  EXPECT_EQ(read_image(plain, Format::pgm).pixels.at<std::uint8_t>(0, 1), 100);
}

TEST(ImageDescribe, ReportsSizeDepthAndRangesIgnoringNan) {
  Image image;
  image.pixels = cv::Mat(2, 2, CV_32FC2);
  image.pixels.at<cv::Vec2f>(0, 0) = {1.0f, std::nanf("")};
  image.pixels.at<cv::Vec2f>(0, 1) = {-3.0f, 5.0f};
  image.pixels.at<cv::Vec2f>(1, 0) = {std::nanf(""), -1.0f};
  image.pixels.at<cv::Vec2f>(1, 1) = {2.5f, std::nanf("")};
  image.color_space = ColorSpace::linear;
  const nlohmann::json d = describe_image(image);
  EXPECT_EQ(d["width"], 2);
  EXPECT_EQ(d["height"], 2);
  EXPECT_EQ(d["channels"], 2);
  EXPECT_EQ(d["depth"], "float32");
  EXPECT_EQ(d["color_space"], "linear");
  EXPECT_EQ(d["min"], nlohmann::json::array({-3.0, -1.0}));
  EXPECT_EQ(d["max"], nlohmann::json::array({2.5, 5.0}));

  Image u16;
  u16.pixels = cv::Mat(1, 3, CV_16UC1);
  u16.pixels.at<std::uint16_t>(0, 0) = 7;
  u16.pixels.at<std::uint16_t>(0, 1) = 65535;
  u16.pixels.at<std::uint16_t>(0, 2) = 300;
  const nlohmann::json e = describe_image(u16);
  EXPECT_EQ(e["depth"], "uint16");
  EXPECT_EQ(e["color_space"], "srgb");
  EXPECT_EQ(e["min"][0], 7);
  EXPECT_EQ(e["max"][0], 65535);

  Image all_nan;
  all_nan.pixels = cv::Mat(1, 1, CV_32FC1, cv::Scalar(std::nan("")));
  EXPECT_TRUE(describe_image(all_nan)["min"][0].is_null());
  EXPECT_EQ(describe_image(Image{})["channels"], 1);
}

}  // namespace
}  // namespace fest::formats
