// EXR with extra channels and header attributes (hdrmerge's session EXRs, docs/hdrmerge.md
// §5): the extra "valid" channel and the attributes round-trip; read_image still reads
// the colour of such a file.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/detect.hpp"
#include "formats/image/exr_extras.hpp"
#include "formats/image/image_io.hpp"

namespace {

using namespace fest::formats;

TEST(ImageExrExtras, ValidChannelAndAttributesRoundTrip) {
  cv::Mat rgb(5, 7, CV_32FC3);
  cv::Mat valid(5, 7, CV_32FC1);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) {
      rgb.at<cv::Vec3f>(y, x) = cv::Vec3f(float(x), float(y), 0.25f * float(x + y));
      valid.at<float>(y, x) = float(x * y) / 24.0f;
    }
  ExrExtras extras;
  extras.channels = {{"valid", valid}};
  extras.strings["lightId"] = "L0";
  extras.strings["responseSha256"] = std::string(64, 'a');
  extras.doubles["turntableAngleDeg"] = 44.9994;
  extras.float_vectors["exposures"] = {0.001f, 0.002f, 0.004f};
  const std::string bytes = write_exr_with_extras(rgb, extras, false);

  const fest::Image back = read_image(bytes, detect_format(bytes));
  ASSERT_EQ(back.pixels.type(), CV_32FC3);
  EXPECT_EQ(cv::norm(back.pixels, rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(read_exr_channel(bytes, "valid"), valid, cv::NORM_INF), 0.0);
  EXPECT_THROW(read_exr_channel(bytes, "Z"), fest::Error);

  const ExrExtras attrs = read_exr_attributes(bytes);
  EXPECT_EQ(attrs.strings.at("lightId"), "L0");
  EXPECT_DOUBLE_EQ(attrs.doubles.at("turntableAngleDeg"), 44.9994);
  EXPECT_EQ(attrs.float_vectors.at("exposures"), std::vector<float>({0.001f, 0.002f, 0.004f}));
  EXPECT_TRUE(attrs.srgb_chromaticities);

  // Half channels: values exactly representable come back exactly.
  const std::string half = write_exr_with_extras(rgb, extras, true);
  EXPECT_EQ(cv::norm(read_image(half, Format::exr).pixels, rgb, cv::NORM_INF), 0.0);
  EXPECT_NEAR(cv::norm(read_exr_channel(half, "valid"), valid, cv::NORM_INF), 0.0, 1e-3);
}

TEST(ImageExrExtras, RefusesMismatchedChannels) {
  ExrExtras extras;
  extras.channels = {{"valid", cv::Mat(2, 2, CV_32FC1, cv::Scalar(1))}};
  EXPECT_THROW(write_exr_with_extras(cv::Mat(3, 3, CV_32FC3, cv::Scalar::all(0)), extras, false), fest::Error);
  EXPECT_THROW(write_exr_with_extras(cv::Mat(3, 3, CV_8UC3, cv::Scalar::all(0)), {}, false), fest::Error);
}

}  // namespace
