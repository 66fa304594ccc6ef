// Trapezoidal step timing (lib/capture/step_profile): checked against the kinematics of
// constant acceleration: a long move lasts n/v + v/a, a short one 2 sqrt(n/a); the speed
// never exceeds v; the profile is symmetric in time.

#include <cmath>

#include <gtest/gtest.h>

#include "capture/step_profile.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture;

TEST(CaptureStepProfile, LongMoveCruisesAtMaxSpeed) {
  const double v = 2000, a = 4000;
  const std::uint32_t n = 10000;  // ramps take v^2/2a = 500 steps each
  EXPECT_NEAR(trapezoid_duration(n, v, a), n / v + v / a, 1e-9);
  const auto t = trapezoid_step_times(n, v, a);
  ASSERT_EQ(t.size(), n);
  EXPECT_EQ(t[0], 0.0);
  for (std::uint32_t k = 1; k < n; ++k) {
    ASSERT_GT(t[k], t[k - 1]);
    EXPECT_LE(1.0 / (t[k] - t[k - 1]), v * (1 + 1e-9));
  }
  // Cruise: one step every 1/v.
  EXPECT_NEAR(t[5000] - t[4999], 1.0 / v, 1e-9);
  // Ramp: s = a t^2 / 2.
  EXPECT_NEAR(t[200], std::sqrt(2 * 200 / a), 1e-12);
}

TEST(CaptureStepProfile, ShortMoveIsATriangle) {
  const double v = 2000, a = 4000;
  const std::uint32_t n = 100;  // would need 1000 steps to reach v
  EXPECT_NEAR(trapezoid_duration(n, v, a), 2 * std::sqrt(n / a), 1e-12);
  const auto t = trapezoid_step_times(n, v, a);
  const double total = trapezoid_duration(n, v, a);
  // Symmetric: the k-th step from the start and from the end mirror each other.
  for (std::uint32_t k = 1; k < n; ++k) EXPECT_NEAR(t[k], total - t[n - k], 1e-9) << k;
}

TEST(CaptureStepProfile, RejectsBadParameters) {
  EXPECT_THROW(trapezoid_step_times(10, 0, 100), fest::Error);
  EXPECT_THROW(trapezoid_duration(10, 100, -1), fest::Error);
  EXPECT_TRUE(trapezoid_step_times(0, 100, 100).empty());
}

}  // namespace
