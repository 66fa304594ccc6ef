// lib/core/rng.hpp's SplitMix64: the reference stream (Vigna's splitmix64.c from state 0)
// and the ranges of its uniforms; Rng stays seeded through the same function.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"

namespace {

TEST(CoreRng, SplitMix64FollowsTheReferenceStream) {
  fest::SplitMix64 r(0);
  EXPECT_EQ(r.next(), 0xe220a8397b1dcdafull);
  EXPECT_EQ(r.next(), 0x6e789e6aa1b965f4ull);
  EXPECT_EQ(r.next(), 0x06c45d188009454full);
  EXPECT_EQ(r.next(), 0xf88bb8a8724c81ecull);
  std::uint64_t state = 0;
  EXPECT_EQ(fest::splitmix64(state), 0xe220a8397b1dcdafull);
  EXPECT_EQ(state, 0x9e3779b97f4a7c15ull);
}

TEST(CoreRng, SplitMix64UniformsStayInTheirRanges) {
  fest::SplitMix64 r(42);
  double sum = 0;
  for (int i = 0; i < 10000; ++i) {
    const double a = r.uniform(), b = r.uniform_open(), n = r.normal();
    EXPECT_GE(a, 0.0);
    EXPECT_LT(a, 1.0);
    EXPECT_GT(b, 0.0);
    EXPECT_LT(b, 1.0);
    EXPECT_TRUE(std::isfinite(n));
    sum += n;
  }
  EXPECT_NEAR(sum / 10000, 0.0, 0.05);  // mean of N(0,1): sd of the mean is 0.01
}

TEST(CoreRng, SameSeedSameStream) {
  fest::Rng a(7), b(7);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(a.next(), b.next());
}

}  // namespace
