// Robertson-Borman-Stevenson response recovery on series of the known gamma-2.2 camera
// (hdr_fixtures.hpp): the recovered ln I must match 2.2 ln(z/128) within 2 %
// on z in [10, 245], and the radiance merged with it within 2.5 % log-RMS.

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "hdr/merge.hpp"
#include "hdr/robertson.hpp"
#include "hdr_fixtures.hpp"

namespace {

using namespace fest::hdr;
using namespace fest::hdr::testing;

TEST(HdrRobertson, RecoversGammaResponseWithinTwoPercent) {
  const ExposureStack stack = bracket(synthetic_radiance(160, 120, 3));
  const Response r = recover_response_robertson(stack);
  ASSERT_EQ(r.channels(), 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(r.g[std::size_t(c)][128], 0.0);
    double worst = 0;
    for (int z = 10; z <= 245; ++z)
      worst = std::max(worst, std::abs(std::expm1(r.g[std::size_t(c)][std::size_t(z)] - true_log_inverse(z))));
    EXPECT_LE(worst, 0.02) << "channel " << c;
  }
}

TEST(HdrRobertson, MergedRadianceWithinTolerance) {
  const cv::Mat truth = synthetic_radiance(160, 120, 1);
  const ExposureStack stack = bracket(truth);
  const MergeResult m = merge_debevec(stack, recover_response_robertson(stack));
  double sum = 0, sum2 = 0;
  for (int i = 0; i < 160 * 120; ++i) {
    const double d = std::log(m.radiance.ptr<float>()[i] / truth.ptr<float>()[i]);
    sum += d;
    sum2 += d * d;
  }
  const double mean = sum / (160 * 120);
  EXPECT_LE(std::sqrt(sum2 / (160 * 120) - mean * mean), 0.025);
}

TEST(HdrRobertson, RejectsBadOptions) {
  const ExposureStack stack = bracket(synthetic_radiance(32, 24, 1));
  RobertsonOptions o;
  o.iterations = 0;
  EXPECT_THROW(recover_response_robertson(stack, o), fest::Error);
}

}  // namespace
