// The table-driven 8-bit sRGB encoder must give exactly the code of the formula (docs/resample.md
// "Streaming", encode) with from_working's rounding: floor(255 s + 0.5), saturated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "sampling/srgb.hpp"

using fest::sampling::linear_to_srgb;
using fest::sampling::linear_to_srgb8;

namespace {

int formula_code(float l) {
  const float scaled = linear_to_srgb(l) * 255.0f + 0.5f;
  if (!(scaled > 0)) return 0;
  if (scaled >= 255.0f) return 255;
  return static_cast<int>(std::floor(scaled));
}

float from_bits(std::uint32_t b) {
  float f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

}  // namespace

TEST(SamplingSrgb, EightBitEncoderMatchesTheFormulaOnASweepOfFloats) {
  // Every 97th float bit pattern from 0 to 1.5 (about 11 million values, all exponents).
  for (std::uint32_t b = 0; b <= 0x3fc00000u; b += 97) {
    const float l = from_bits(b);
    ASSERT_EQ(linear_to_srgb8(l), formula_code(l)) << l;
  }
}

TEST(SamplingSrgb, EightBitEncoderMatchesTheFormulaAtEveryCodeBoundary) {
  // Around the linear value of each code's boundary (k - 0.5)/255 in sRGB, ±64 ulps.
  for (int k = 1; k < 256; ++k) {
    const float edge = fest::sampling::srgb_to_linear(static_cast<float>((k - 0.5) / 255.0));
    std::uint32_t b;
    std::memcpy(&b, &edge, sizeof b);
    for (std::uint32_t d = b - 64; d <= b + 64; ++d) ASSERT_EQ(linear_to_srgb8(from_bits(d)), formula_code(from_bits(d))) << k;
  }
}

TEST(SamplingSrgb, EightBitEncoderSaturatesAndMapsNanToZero) {
  EXPECT_EQ(linear_to_srgb8(-1.0f), 0);
  EXPECT_EQ(linear_to_srgb8(0.0f), 0);
  EXPECT_EQ(linear_to_srgb8(1.0f), 255);
  EXPECT_EQ(linear_to_srgb8(7.5f), 255);
  EXPECT_EQ(linear_to_srgb8(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(linear_to_srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
}
