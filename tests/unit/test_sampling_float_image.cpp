// The working form's decode and encode (lib/sampling/float_image.cpp): 8-bit codes
// decoded through the sRGB table on every path (AVX2 gathers and the scalar tail), and
// the 8-bit rounding floor(255 v + ½) saturated to [0, 255] with NaN -> 0, on values
// chosen at the rounding boundaries.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sampling/float_image.hpp"
#include "sampling/srgb.hpp"

using namespace fest::sampling;

TEST(SamplingFloatImage, SrgbCodesDecodeThroughTheTable) {
  // 3 x 93 = 279 values: not a multiple of 8, so the scalar tail runs too.
  cv::Mat m(2, 93, CV_8UC3);
  for (int y = 0; y < 2; ++y)
    for (int i = 0; i < 279; ++i) m.ptr<std::uint8_t>(y)[i] = static_cast<std::uint8_t>((i * 7 + y * 3) % 256);
  Encoding enc;
  enc.decode_srgb = true;
  std::vector<float> row(279);
  for (int y = 0; y < 2; ++y) {
    decode_row(m, y, enc, row.data());
    for (int i = 0; i < 279; ++i) {
      const std::uint8_t code = m.ptr<std::uint8_t>(y)[i];
      // The table itself against the IEC 61966-2-1 formula in double precision.
      const double c = code / 255.0;
      const double expected = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
      EXPECT_EQ(row[i], srgb8_table()[code]);
      EXPECT_NEAR(row[i], expected, 1e-7);
    }
  }
}

TEST(SamplingFloatImage, EightBitRoundingAndSaturation) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // value -> code: floor(255 v + 0.5), saturated, NaN -> 0
  const std::vector<std::pair<float, int>> cases = {
      {0.0f, 0},     {-0.0f, 0},     {-1.0f, 0},       {-inf, 0},     {nan, 0},
      {1.0f, 255},   {2.0f, 255},    {inf, 255},       {0.5f, 128},  // 127.5 rounds half up
      {127.4f / 255, 127}, {127.6f / 255, 128}, {0.49f / 255, 0}, {0.51f / 255, 1}, {254.49f / 255, 254},
      {254.51f / 255, 255}};
  FloatImage img(static_cast<int>(cases.size()), 1, 1);
  for (std::size_t i = 0; i < cases.size(); ++i) img.data[i] = cases[i].first;
  const cv::Mat out = from_working(img, CV_8U, Encoding{});
  for (std::size_t i = 0; i < cases.size(); ++i)
    EXPECT_EQ(out.ptr<std::uint8_t>(0)[i], cases[i].second) << "value " << cases[i].first;
}

TEST(SamplingFloatImage, FloatOutputKeepsTheValues) {
  FloatImage img(3, 2, 3);
  for (std::size_t i = 0; i < img.data.size(); ++i) img.data[i] = static_cast<float>(i) * -1.25e-3f + 7.0f;
  img.data[4] = std::numeric_limits<float>::infinity();
  const cv::Mat out = from_working(img, CV_32F, Encoding{});
  for (int y = 0; y < 2; ++y)
    for (int i = 0; i < 9; ++i) EXPECT_EQ(out.ptr<float>(y)[i], img.row(y)[i]);
}
