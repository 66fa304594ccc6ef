// PNG, JPEG and TIFF through libpng, libjpeg-turbo and libtiff directly. The anchor is
// OpenCV's imgcodecs (an independent front end to the same libraries, which fest used
// before): the same bytes out of the PNG and JPEG encoders, the same pixels out of every
// decoder. Damaged files are bad input with a one-line message, and nothing the codec
// libraries say reaches standard error.

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"
#include "test_image_helpers.hpp"

namespace {

using namespace fest;
using namespace fest::formats;

// fest's RGB(A) order <-> OpenCV's BGR(A) (the swap is its own inverse).
cv::Mat swapped(const cv::Mat& m) {
  cv::Mat out;
  if (m.channels() == 3) cv::cvtColor(m, out, cv::COLOR_BGR2RGB);
  else if (m.channels() == 4) cv::cvtColor(m, out, cv::COLOR_BGRA2RGBA);
  else out = m;
  return out;
}

std::string opencv_encode(const cv::Mat& rgb, const char* ext, const std::vector<int>& params) {
  std::vector<uchar> buf;
  EXPECT_TRUE(cv::imencode(ext, swapped(rgb), buf, params));
  return std::string(buf.begin(), buf.end());
}

cv::Mat opencv_decode(const std::string& bytes) {
  const cv::Mat buf(1, int(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
  return swapped(cv::imdecode(buf, cv::IMREAD_UNCHANGED));
}

// A smooth pattern plus noise, so that filters and the DCT both have work to do.
cv::Mat test_image(int depth, int channels) {
  cv::Mat m = test::random_image(37, 23, depth, channels, 11);
  const double step = depth == CV_8U ? 5 : 1200;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < m.cols * channels; ++x) {
      if (depth == CV_8U) m.ptr<uchar>(y)[x] = cv::saturate_cast<uchar>(step * (x % 40) + y);
      else m.ptr<ushort>(y)[x] = cv::saturate_cast<ushort>(step * (x % 40) + y);
    }
  return m;
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(ImageCodecs, PngBytesAsOpenCvWroteThem) {
  for (int depth : {CV_8U, CV_16U})
    for (int channels : {1, 3, 4})
      for (int level : {0, 1, 6, 9})
        for (bool huffman : {false, true}) {
          Image image{test_image(depth, channels)};
          ImageWriteOptions o;
          o.png_compression = level;
          o.png_huffman_only = huffman;
          const std::string ours = write_image(image, Format::png, o);
          const std::string theirs =
              opencv_encode(image.pixels, ".png",
                            {cv::IMWRITE_PNG_COMPRESSION, level, cv::IMWRITE_PNG_STRATEGY,
                             huffman ? cv::IMWRITE_PNG_STRATEGY_HUFFMAN_ONLY : cv::IMWRITE_PNG_STRATEGY_DEFAULT});
          // Huffman-only above level 0 goes to fest's unfiltered writer (png_unfiltered.cpp).
          if (!huffman || level == 0) {
            EXPECT_EQ(ours, theirs) << depth << " " << channels << " " << level;
          }
          EXPECT_TRUE(same_pixels(read_image(ours, Format::png).pixels, image.pixels));
        }
}

TEST(ImageCodecs, PngPixelsAsOpenCvReadThem) {
  for (int depth : {CV_8U, CV_16U})
    for (int channels : {1, 3, 4}) {
      const std::string png = opencv_encode(test_image(depth, channels), ".png", {cv::IMWRITE_PNG_COMPRESSION, 3});
      EXPECT_TRUE(same_pixels(read_image(png, Format::png).pixels, opencv_decode(png))) << depth << " " << channels;
    }
  // 1-bit grey is expanded to 0 / 255 (libpng scales, as OpenCV asked it to).
  cv::Mat bits(9, 13, CV_8U);
  for (int i = 0; i < int(bits.total()); ++i) bits.data[i] = (i * 7 % 3) ? 255 : 0;
  const std::string png = opencv_encode(bits, ".png", {cv::IMWRITE_PNG_BILEVEL, 1});
  ASSERT_EQ(png[24], 1);  // IHDR bit depth
  EXPECT_TRUE(same_pixels(read_image(png, Format::png).pixels, bits));
}

TEST(ImageCodecs, JpegBytesAndPixelsAsOpenCv) {
  for (int channels : {1, 3})
    for (int quality : {95, 50, 100}) {
      Image image{test_image(CV_8U, channels)};
      ImageWriteOptions o;
      o.jpeg_quality = quality;
      const std::string ours = write_image(image, Format::jpeg, o);
      EXPECT_EQ(ours, opencv_encode(image.pixels, ".jpg", {cv::IMWRITE_JPEG_QUALITY, quality}));
      EXPECT_TRUE(same_pixels(read_image(ours, Format::jpeg).pixels, opencv_decode(ours)));
    }
}

TEST(ImageCodecs, TiffRoundTripAndOpenCvReadsIt) {
  for (int depth : {CV_8U, CV_16U, CV_32F})
    for (int channels : {1, 3, 4}) {
      Image image{test::random_image(45, 31, depth, channels, 3)};
      const std::string tiff = write_image(image, Format::tiff);
      EXPECT_TRUE(same_pixels(read_image(tiff, Format::tiff).pixels, image.pixels)) << depth << " " << channels;
      EXPECT_TRUE(same_pixels(opencv_decode(tiff), image.pixels)) << depth << " " << channels;
    }
  // And fest reads what OpenCV's writer made.
  const cv::Mat rgb = test::random_image(20, 10, CV_16U, 3, 5);
  EXPECT_TRUE(same_pixels(read_image(opencv_encode(rgb, ".tiff", {}), Format::tiff).pixels, rgb));
}

// Bad input, a message of one line, and standard error left untouched.
void expect_quiet_bad_input(const std::string& bytes, Format format, const char* what) {
  testing::internal::CaptureStderr();
  try {
    read_image(bytes, format);
    ADD_FAILURE() << what << ": no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input) << what << ": " << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << what << ": " << e.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << what;
}

TEST(ImageCodecs, DamagedFilesAreQuietBadInput) {
  const std::string png = write_image(Image{test_image(CV_8U, 3)}, Format::png);
  for (std::size_t keep : {png.size() - 1, png.size() - 12, png.size() / 2, std::size_t(60)})
    expect_quiet_bad_input(png.substr(0, keep), Format::png, "truncated PNG");
  std::string bad_crc = png;
  bad_crc[png.find("IDAT") + 10] ^= 0x55;
  expect_quiet_bad_input(bad_crc, Format::png, "PNG with a damaged IDAT");

  ImageWriteOptions o;
  o.jpeg_quality = 90;
  const std::string jpeg = write_image(Image{test_image(CV_8U, 3)}, Format::jpeg, o);
  for (std::size_t keep : {jpeg.size() - 2, jpeg.size() * 2 / 3})
    expect_quiet_bad_input(jpeg.substr(0, keep), Format::jpeg, "truncated JPEG");
  std::string scan = jpeg;
  const std::size_t sos = jpeg.find("\xff\xda");
  ASSERT_NE(sos, std::string::npos);
  for (std::size_t i = sos + 20; i < sos + 40; ++i) scan[i] = char(0xff);  // markers inside the scan
  expect_quiet_bad_input(scan, Format::jpeg, "JPEG with a damaged scan");

  Image smooth{cv::Mat(64, 64, CV_16UC1)};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) smooth.pixels.at<ushort>(y, x) = ushort(100 * x + y);
  std::string tiff = write_image(smooth, Format::tiff);
  // The LZW strips lie between the 8-byte header and the IFD; scramble them.
  const std::size_t ifd = std::uint8_t(tiff[4]) | std::uint8_t(tiff[5]) << 8 | std::uint8_t(tiff[6]) << 16;
  for (std::size_t i = 8; i < ifd && i < 400; ++i) tiff[i] = char(i * 37);
  expect_quiet_bad_input(tiff, Format::tiff, "TIFF with damaged LZW data");
}

}  // namespace
