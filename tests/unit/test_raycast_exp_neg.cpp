// exp_neg (lib/raycast/exp_neg.hpp): exp(-y) within 2 ulp of libm's exp over the whole
// range the caster uses, exactly 1 at 0 (a sample with tau = 0 gets alpha = 0 exactly), 0
// past the normal range, NaN kept.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "raycast/exp_neg.hpp"

using fest::raycast::exp_neg;

namespace {
double ulps(double a, double b) { return std::abs(a - b) / (std::nextafter(b, INFINITY) - b); }
}  // namespace

TEST(RaycastExpNeg, WithinTwoUlpOfLibm) {
  double worst = 0;
  for (double scale : {1e-12, 1e-6, 1e-3, 0.1, 1.0, 10.0, 100.0, 708.0}) {
    for (int i = 0; i <= 20000; ++i) {
      const double y = scale * i / 20000.0;
      worst = std::max(worst, ulps(exp_neg(y), std::exp(-y)));
    }
  }
  EXPECT_LE(worst, 2.0);
}

TEST(RaycastExpNeg, EdgeValues) {
  EXPECT_EQ(exp_neg(0.0), 1.0);
  EXPECT_EQ(1 - exp_neg(0.0), 0.0);
  EXPECT_EQ(exp_neg(709.0), 0.0);
  EXPECT_EQ(exp_neg(std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_TRUE(std::isnan(exp_neg(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_DOUBLE_EQ(exp_neg(std::log(2.0)), 0.5);
}
