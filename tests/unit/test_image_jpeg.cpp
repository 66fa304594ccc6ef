// JPEG reading: the header walk gives size and components before anything is decoded,
// malformed headers are bad input; what the writer refuses (16 bits, alpha that is not
// opaque, quality 0) and the alpha it drops (opaque everywhere). test_image_codecs.cpp
// checks the writer's bytes.

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "expect_error.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "testdata.hpp"

namespace {

using namespace fest;
using namespace fest::formats;

// A JPEG encoded by OpenCV (libjpeg) from a known image.
std::string encode_jpeg(const cv::Mat& bgr_or_grey, int quality = 95) {
  std::vector<uchar> buf;
  EXPECT_TRUE(cv::imencode(".jpg", bgr_or_grey, buf, {cv::IMWRITE_JPEG_QUALITY, quality}));
  return std::string(buf.begin(), buf.end());
}

TEST(ImageJpeg, DetectedByItsSignature) {
  const std::string jpeg = encode_jpeg(cv::Mat(8, 8, CV_8U, cv::Scalar(100)));
  EXPECT_EQ(detect_format(jpeg), Format::jpeg);
  EXPECT_EQ(kind_of(Format::jpeg), Kind::image);
  EXPECT_EQ(output_format_from_name("jpg").format, Format::jpeg);
}

TEST(ImageJpeg, ReadsGreyAndColour) {
  cv::Mat grey(48, 64, CV_8U);
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x) grey.at<uchar>(y, x) = uchar(2 * x + y);
  const Image g = read_image(encode_jpeg(grey), Format::jpeg);
  ASSERT_EQ(g.pixels.type(), CV_8UC1);
  EXPECT_EQ(g.pixels.size(), grey.size());
  EXPECT_LT(cv::norm(g.pixels, grey, cv::NORM_INF), 6);  // lossy, but close at quality 95

  // Pure red in OpenCV's BGR comes back as R in fest's RGB order.
  const cv::Mat red(16, 24, CV_8UC3, cv::Scalar(0, 0, 255));
  const ImageHeader h = read_image_header(encode_jpeg(red), Format::jpeg);
  EXPECT_EQ(h.width, 24);
  EXPECT_EQ(h.height, 16);
  EXPECT_EQ(h.channels, 3);
  EXPECT_EQ(h.bits, 8);
  const Image c = read_image(encode_jpeg(red), Format::jpeg);
  ASSERT_EQ(c.pixels.type(), CV_8UC3);
  const cv::Vec3b p = c.pixels.at<cv::Vec3b>(8, 12);
  EXPECT_GT(p[0], 240);
  EXPECT_LT(p[2], 15);
}

TEST(ImageJpeg, MalformedHeadersAreBadInput) {
  const std::string jpeg = encode_jpeg(cv::Mat(16, 16, CV_8U, cv::Scalar(50)));
  test::expect_bad_input([&] { read_image_header(jpeg.substr(0, 3), Format::jpeg); }, "JPEG header");
  test::expect_bad_input([&] { read_image_header(jpeg.substr(0, 40), Format::jpeg); }, "JPEG header");
  test::expect_bad_input([&] { read_image_header("\xff\xd8\xff\xd9", Format::jpeg); }, "end of image");
  // Hand-made segments: a 12-bit frame, a frame of 0 lines, an overlong segment.
  const std::string soi("\xff\xd8", 2);
  const std::string sof12("\xff\xc0\x00\x0b\x0c\x00\x10\x00\x10\x01\x01\x11\x00", 13);
  test::expect_bad_input([&] { read_image_header(soi + sof12, Format::jpeg); }, "12-bit");
  const std::string sof0lines("\xff\xc0\x00\x0b\x08\x00\x00\x00\x10\x01\x01\x11\x00", 13);
  test::expect_bad_input([&] { read_image_header(soi + sof0lines, Format::jpeg); }, "not positive");
  const std::string overlong("\xff\xe0\x40\x00JFIF", 8);
  test::expect_bad_input([&] { read_image_header(soi + overlong, Format::jpeg); }, "past the end");
  // A valid header over corrupt entropy-coded data.
  std::string corrupt = jpeg;
  corrupt.resize(corrupt.size() / 2);
  test::expect_bad_input([&] { read_image(corrupt + std::string(64, '\0'), Format::jpeg); }, "JPEG");
}

TEST(ImageJpeg, CmykIsRefusedByName) {
  const std::string soi("\xff\xd8", 2);
  const std::string sof4("\xff\xc0\x00\x14\x08\x00\x10\x00\x10\x04\x01\x11\x00\x02\x11\x00\x03\x11\x00\x04\x11\x00", 22);
  test::expect_bad_input([&] { read_image_header(soi + sof4, Format::jpeg); }, "CMYK");
}

TEST(ImageJpeg, WriterRefusesWhatItWouldLose) {
  const cv::Mat grey(4, 4, CV_8U, cv::Scalar(1));
  ImageWriteOptions lossless;
  lossless.jpeg_quality = 0;
  test::expect_bad_input([&] { write_image(Image{grey}, Format::jpeg, lossless); }, "lossy");
  test::expect_bad_input([] { write_image(Image{cv::Mat(4, 4, CV_16U, cv::Scalar(1))}, Format::jpeg); }, "8-bit");
  test::expect_bad_input([] { write_image(Image{cv::Mat(4, 4, CV_32F, cv::Scalar(1))}, Format::jpeg); }, "8-bit");
  // One pixel of 16 half transparent: refused with the count, for JPEG and PPM alike.
  cv::Mat rgba(4, 4, CV_8UC4, cv::Scalar(10, 20, 30, 255));
  rgba.at<cv::Vec4b>(2, 1)[3] = 128;
  test::expect_bad_input([&] { write_image(Image{rgba}, Format::jpeg); }, "1 of 16 pixels are not opaque");
  test::expect_bad_input([&] { write_image(Image{rgba}, Format::ppm); }, "alpha channel");
  cv::Mat grey_alpha(4, 4, CV_8UC2, cv::Scalar(10, 0));
  test::expect_bad_input([&] { write_image(Image{grey_alpha}, Format::jpeg); }, "16 of 16 pixels");
}

TEST(ImageJpeg, OpaqueAlphaIsDroppedAsItHoldsNothing) {
  const cv::Mat rgba(4, 4, CV_8UC4, cv::Scalar(10, 20, 30, 255));
  const cv::Mat rgb(4, 4, CV_8UC3, cv::Scalar(10, 20, 30));
  EXPECT_EQ(write_image(Image{rgba}, Format::jpeg), write_image(Image{rgb}, Format::jpeg));
  EXPECT_EQ(write_image(Image{rgba}, Format::ppm), write_image(Image{rgb}, Format::ppm));
  const cv::Mat ga(4, 4, CV_16UC2, cv::Scalar(1000, 65535));
  EXPECT_EQ(write_image(Image{ga}, Format::pgm), write_image(Image{cv::Mat(4, 4, CV_16U, cv::Scalar(1000))}, Format::pgm));
}

TEST(ImageJpeg, ReadsOpenCvSampleChessboard) {
  FEST_REQUIRE_TESTDATA(path, "calib/left01.jpg");
  const std::string bytes = test::slurp(path);
  ASSERT_EQ(detect_format(bytes), Format::jpeg);
  const Image image = read_image(bytes, Format::jpeg);
  EXPECT_EQ(image.pixels.cols, 640);
  EXPECT_EQ(image.pixels.rows, 480);
}

// flatten: alpha 0 gives the background itself, alpha 1 the colour itself (the linear-light
// round trip of an 8-bit code returns the code); a grey image takes the background's
// Rec. 709 luminance.
TEST(ImageJpeg, FlattenCompositesOverTheBackground) {
  cv::Mat rgba(1, 2, CV_8UC4);
  rgba.at<cv::Vec4b>(0, 0) = {10, 20, 30, 0};
  rgba.at<cv::Vec4b>(0, 1) = {10, 20, 30, 255};
  ImageWriteOptions o;
  o.flatten = true;
  o.background = {51 / 255.0, 102 / 255.0, 153 / 255.0};
  const cv::Mat flat = read_image(write_image(Image{rgba}, Format::ppm, o), Format::ppm).pixels;
  EXPECT_EQ(flat.at<cv::Vec3b>(0, 0), cv::Vec3b(51, 102, 153));
  EXPECT_EQ(flat.at<cv::Vec3b>(0, 1), cv::Vec3b(10, 20, 30));
  const cv::Mat ga(1, 1, CV_8UC2, cv::Scalar(0, 0));
  o.background = {1, 1, 1};
  EXPECT_EQ(read_image(write_image(Image{ga}, Format::pgm, o), Format::pgm).pixels.at<uchar>(0, 0), 255);
  EXPECT_NO_THROW(write_image(Image{rgba}, Format::jpeg, o));
}

}  // namespace
