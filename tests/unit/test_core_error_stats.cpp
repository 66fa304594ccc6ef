// lib/core/error_stats.hpp (RMSE, PSNR, largest difference) and reworded_error.hpp (a
// library's error in the user's words), against values worked by hand.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/error_stats.hpp"
#include "core/reworded_error.hpp"

namespace {

TEST(CoreErrorStats, RmsePsnrAndMaximumByHand) {
  fest::ErrorAccumulator e;
  for (double d : {0.0, 0.3, 0.4}) e.add(d);  // squares 0, 0.09, 0.16: mean 1/12
  EXPECT_EQ(e.n, 3);
  EXPECT_DOUBLE_EQ(e.max_abs, 0.4);
  EXPECT_DOUBLE_EQ(e.rmse(), std::sqrt(0.25 / 3));
  EXPECT_DOUBLE_EQ(e.psnr(1.0), 20 * std::log10(1 / std::sqrt(0.25 / 3)));
  // PSNR against a peak of 255 for an RMSE of 2.55: 20 log10(100) = 40 dB.
  EXPECT_NEAR(fest::psnr_db(2.55, 255), 40.0, 1e-12);
}

TEST(CoreErrorStats, IdenticalAndEmptyAreInfinitePsnr) {
  fest::ErrorAccumulator none;
  EXPECT_EQ(none.rmse(), 0);
  EXPECT_EQ(none.psnr(1), std::numeric_limits<double>::infinity());
  EXPECT_EQ(fest::psnr_db(std::nan(""), 1), std::numeric_limits<double>::infinity());
  fest::ErrorAccumulator inf;
  inf.add(std::numeric_limits<double>::infinity());
  EXPECT_EQ(inf.psnr(1), -std::numeric_limits<double>::infinity());
}

TEST(CoreRewordedError, DomainPhrasesBecomeTheUsersWordsKeepingTheStatus) {
  try {
    fest::with_rewording({{"zone plate:", "metrics --zoneplate:"}},
                         [] { throw fest::bad_input("zone plate: the 3x3 image has no pixel in the band"); });
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    EXPECT_EQ(std::string(e.what()), "metrics --zoneplate: the 3x3 image has no pixel in the band");
  }
  EXPECT_EQ(fest::with_rewording({{"a", "b"}}, [] { return 7; }), 7);
  const fest::Error untouched = fest::reworded(fest::usage_error("nothing to change"), {{"zone plate:", "x"}});
  EXPECT_EQ(std::string(untouched.what()), "nothing to change");
  EXPECT_EQ(untouched.status(), fest::Status::usage);
}

}  // namespace
