// devices/v4l2_frame: MJPEG frames as UVC cameras send them (including without Huffman
// tables), truncated or corrupt frames as bad input, and the raw formats passed through.

#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "devices/v4l2_frame.hpp"
#include "formats/image/image_io.hpp"

namespace {

using namespace fest;
using capture::RawFrame;

// A smooth 64 x 48 colour picture and its JPEG (formats/ encoder, standard tables).
Image test_picture() {
  Image img;
  img.pixels.create(48, 64, CV_8UC3);
  for (int r = 0; r < 48; ++r)
    for (int c = 0; c < 64; ++c) img.pixels.at<cv::Vec3b>(r, c) = cv::Vec3b(uchar(4 * c), uchar(5 * r), 128);
  return img;
}

std::string jpeg_of(const Image& img) {
  formats::ImageWriteOptions o;
  o.jpeg_quality = 95;
  return formats::write_image(img, formats::Format::jpeg, o);
}

// UVC cameras leave the DHT segments out of their MJPEG frames (the decoder is to use
// the tables of the JPEG standard, Annex K.3): drop them up to the start of scan.
std::string without_huffman_tables(const std::string& jpeg) {
  std::string out = jpeg.substr(0, 2);
  std::size_t at = 2;
  while (at + 4 <= jpeg.size()) {
    const auto marker = std::uint8_t(jpeg[at + 1]);
    const std::size_t length = std::size_t(std::uint8_t(jpeg[at + 2])) << 8 | std::uint8_t(jpeg[at + 3]);
    if (marker == 0xDA) break;  // scan: copy the rest as it is
    if (marker != 0xC4) out += jpeg.substr(at, 2 + length);
    at += 2 + length;
  }
  return out + jpeg.substr(at);
}

Error error_of(const RawFrame& f) {
  try {
    devices::decode_v4l2_frame(f);
  } catch (const Error& e) {
    return e;
  }
  return Error(Status::ok, "no error");
}

TEST(DevicesV4l2Frame, MjpegDecodesToRgbOfTheNegotiatedSize) {
  const Image pic = test_picture();
  const std::string jpeg = jpeg_of(pic);
  const Image got = devices::decode_v4l2_frame({capture::fourcc_mjpg, 64, 48, 0, jpeg});
  ASSERT_EQ(got.pixels.type(), CV_8UC3);
  ASSERT_EQ(got.pixels.size(), pic.pixels.size());
  EXPECT_GT(cv::PSNR(got.pixels, pic.pixels), 35.0);  // quality 95 on a smooth picture
}

TEST(DevicesV4l2Frame, MjpegWithoutHuffmanTablesUsesTheStandardOnes) {
  const std::string jpeg = jpeg_of(test_picture());
  const std::string bare = without_huffman_tables(jpeg);
  ASSERT_LT(bare.size(), jpeg.size());
  ASSERT_EQ(bare.find("\xFF\xC4"), std::string::npos);
  const Image a = devices::decode_v4l2_frame({capture::fourcc_mjpg, 64, 48, 0, jpeg});
  const Image b = devices::decode_v4l2_frame({capture::fourcc_mjpg, 64, 48, 0, bare});
  // The encoder used the standard tables too, so the pixels are identical.
  EXPECT_EQ(cv::norm(a.pixels, b.pixels, cv::NORM_INF), 0.0);
}

TEST(DevicesV4l2Frame, GreyMjpegBecomesRgb) {
  Image grey;
  grey.pixels = cv::Mat(16, 16, CV_8UC1, cv::Scalar(77));
  const Image got = devices::decode_v4l2_frame({capture::fourcc_mjpg, 16, 16, 0, jpeg_of(grey)});
  ASSERT_EQ(got.pixels.type(), CV_8UC3);
  EXPECT_NEAR(got.pixels.at<cv::Vec3b>(8, 8)[0], 77, 1);
  EXPECT_EQ(got.pixels.at<cv::Vec3b>(8, 8)[0], got.pixels.at<cv::Vec3b>(8, 8)[2]);
}

TEST(DevicesV4l2Frame, TruncatedOrCorruptMjpegIsBadInput) {
  const std::string jpeg = jpeg_of(test_picture());
  for (const std::size_t keep : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(20), jpeg.size() / 2,
                                 jpeg.size() - 2}) {
    const Error e = error_of({capture::fourcc_mjpg, 64, 48, 0, std::string_view(jpeg).substr(0, keep)});
    EXPECT_EQ(e.status(), Status::bad_input) << keep << ": " << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("MJPEG frame", 0), 0u) << e.what();
  }
  std::string flipped = jpeg;
  for (std::size_t i = flipped.size() / 2; i < flipped.size() / 2 + 64; ++i) flipped[i] = char(0xFF);
  EXPECT_EQ(error_of({capture::fourcc_mjpg, 64, 48, 0, flipped}).status(), Status::bad_input);
  EXPECT_EQ(error_of({capture::fourcc_mjpg, 64, 48, 0, std::string(4096, '\0')}).status(), Status::bad_input);
}

TEST(DevicesV4l2Frame, MjpegOfAnotherSizeIsRefused) {
  const Error e = error_of({capture::fourcc_mjpg, 640, 480, 0, jpeg_of(test_picture())});
  EXPECT_EQ(e.status(), Status::bad_input);
  EXPECT_STREQ(e.what(), "MJPEG frame: 64 x 48 pixels, the format negotiated 640 x 480");
}

TEST(DevicesV4l2Frame, SupportedFormats) {
  for (const char* f : {"YUYV", "MJPG", "GREY", "RGB3", "Y16"})
    EXPECT_TRUE(devices::is_supported_v4l2_format(capture::fourcc_from_name(f))) << f;
  EXPECT_FALSE(devices::is_supported_v4l2_format(capture::fourcc_from_name("NV12")));
  const std::string grey = "\x01\x02";
  EXPECT_EQ(devices::decode_v4l2_frame({capture::fourcc_grey, 2, 1, 2, grey}).pixels.at<cv::Vec3b>(0, 1),
            cv::Vec3b(2, 2, 2));
}

}  // namespace
