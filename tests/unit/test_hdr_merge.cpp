// Radiance merge: log-RMS error against the known radiance within 2.5 %
// (docs/hdrmerge.md §6), and the properties of docs/hdrmerge.md §5 (time scaling, saturation flags,
// a known response reproduced exactly) plus the checks on bad series.

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "hdr/merge.hpp"
#include "hdr_fixtures.hpp"

namespace {

using namespace fest::hdr;
using namespace fest::hdr::testing;

// RMS of ln E_merged - ln E_true after removing the mean (the scale g(128) = 0 fixes),
// over valid pixels; `offset` receives that mean.
double log_rms(const MergeResult& m, const cv::Mat& truth, double& offset, int& counted) {
  const int ch = truth.channels();
  std::vector<double> d;
  for (int y = 0; y < truth.rows; ++y)
    for (int x = 0; x < truth.cols; ++x) {
      if (m.valid.at<float>(y, x) <= 0) continue;
      for (int c = 0; c < ch; ++c)
        d.push_back(std::log(m.radiance.ptr<float>(y)[x * ch + c]) - std::log(truth.ptr<float>(y)[x * ch + c]));
    }
  counted = int(d.size());
  double mean = 0;
  for (double v : d) mean += v;
  mean /= double(d.size());
  double s = 0;
  for (double v : d) s += (v - mean) * (v - mean);
  offset = mean;
  return std::sqrt(s / double(d.size()));
}

Response true_response(int channels) {
  Response r;
  Curve g{};
  // z = 0 has no finite log; the merge gives it zero weight, any finite value will do.
  g[0] = true_log_inverse(1) - 1;
  for (int z = 1; z < kCodes; ++z) g[std::size_t(z)] = true_log_inverse(z);
  r.g.assign(std::size_t(channels), g);
  return r;
}

TEST(HdrMerge, RecoveredResponseGivesRadianceWithinTolerance) {
  const cv::Mat truth = synthetic_radiance(160, 120, 3);
  const ExposureStack stack = bracket(truth);
  const MergeResult m = merge_debevec(stack, recover_response_debevec(stack), 2);
  double offset = 0;
  int counted = 0;
  EXPECT_LE(log_rms(m, truth, offset, counted), 0.025);
  EXPECT_EQ(counted, 160 * 120 * 3);  // 4 decades fit in 12 stops: every pixel valid
  // The scale: g(128) = 0 means E = 1 gives code 128 at dt = 1, so E_merged = E (255/128)^2.2.
  EXPECT_NEAR(offset, 2.2 * std::log(255.0 / 128.0), 0.03);
}

TEST(HdrMerge, TrueResponseOnNoiselessSeriesIsNearExact) {
  const cv::Mat truth = synthetic_radiance(64, 48, 1);
  const ExposureStack stack = bracket(truth, 0.0);
  const MergeResult m = merge_debevec(stack, true_response(1), 1);
  double offset = 0;
  int counted = 0;
  // Only 8-bit rounding remains: uniform error of +-0.5 DN is 2.2 * 0.29 / z in ln E per
  // exposure, 0.01 at z = 64, less after the weighted average over exposures.
  EXPECT_LE(log_rms(m, truth, offset, counted), 0.01);
}

TEST(HdrMerge, ThreadsDoNotChangeTheResult) {
  const ExposureStack stack = bracket(synthetic_radiance(61, 47, 3));
  const Response r = true_response(3);
  const MergeResult a = merge_debevec(stack, r, 1), b = merge_debevec(stack, r, 3);
  EXPECT_EQ(cv::norm(a.radiance, b.radiance, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.valid, b.valid, cv::NORM_INF), 0.0);
}

TEST(HdrMerge, ScalingAllTimesScalesRadianceInversely) {
  ExposureStack stack = bracket(synthetic_radiance(40, 30, 1));
  const Response r = true_response(1);
  const MergeResult a = merge_debevec(stack, r);
  for (double& t : stack.times) t *= 4;
  const MergeResult b = merge_debevec(stack, r);
  for (int i = 0; i < 40 * 30; ++i)
    EXPECT_NEAR(b.radiance.ptr<float>()[i] * 4 / a.radiance.ptr<float>()[i], 1.0, 1e-5);
}

TEST(HdrMerge, SingleCodeReproducesInverseResponseOverTime) {
  // Every exposure shows code 100 -> ln E = weighted mean of g(100) - ln dt_j.
  ExposureStack s;
  s.times = {0.5, 2.0};
  s.images = {cv::Mat(2, 2, CV_8UC1, cv::Scalar(100)), cv::Mat(2, 2, CV_8UC1, cv::Scalar(100))};
  const MergeResult m = merge_debevec(s, true_response(1));
  const double expected = std::exp(true_log_inverse(100) - 0.5 * (std::log(0.5) + std::log(2.0)));
  EXPECT_NEAR(m.radiance.at<float>(0, 0), expected, 1e-5 * expected);
  EXPECT_NEAR(m.valid.at<float>(0, 0), 100.0 / 127.0, 1e-6);
}

TEST(HdrMerge, SaturatedEverywhereIsFlaggedWithShortestExposureEstimate) {
  ExposureStack s;
  s.times = {0.01, 0.1};
  cv::Mat a(1, 2, CV_8UC1), b(1, 2, CV_8UC1);
  a.at<std::uint8_t>(0, 0) = 255;  b.at<std::uint8_t>(0, 0) = 255;  // saturated in both
  a.at<std::uint8_t>(0, 1) = 0;    b.at<std::uint8_t>(0, 1) = 0;    // black in both
  s.images = {a, b};
  const MergeResult m = merge_debevec(s, true_response(1));
  EXPECT_EQ(m.valid.at<float>(0, 0), 0.0f);
  EXPECT_EQ(m.valid.at<float>(0, 1), 0.0f);
  EXPECT_NEAR(m.radiance.at<float>(0, 0), std::exp(true_log_inverse(255) - std::log(0.01)), 1e-3);
  EXPECT_NEAR(m.radiance.at<float>(0, 1), std::exp(true_log_inverse(1) - 1 - std::log(0.1)), 1e-6);
}

fest::Status status_of(const ExposureStack& s) {
  try {
    merge_debevec(s, true_response(s.images.empty() ? 1 : s.images.front().channels()));
  } catch (const fest::Error& e) {
    return e.status();
  }
  return fest::Status::ok;
}

TEST(HdrMerge, RejectsBadSeries) {
  const cv::Mat a(4, 4, CV_8UC1, cv::Scalar(50));
  ExposureStack one{{a}, {0.1}};
  EXPECT_EQ(status_of(one), fest::Status::bad_input);
  ExposureStack sizes{{a, cv::Mat(4, 5, CV_8UC1, cv::Scalar(50))}, {0.1, 0.2}};
  EXPECT_EQ(status_of(sizes), fest::Status::bad_input);
  ExposureStack channels{{a, cv::Mat(4, 4, CV_8UC3, cv::Scalar(50))}, {0.1, 0.2}};
  EXPECT_EQ(status_of(channels), fest::Status::bad_input);
  ExposureStack order{{a, a}, {0.2, 0.1}};
  EXPECT_EQ(status_of(order), fest::Status::bad_input);
  ExposureStack equal{{a, a}, {0.1, 0.1}};
  EXPECT_EQ(status_of(equal), fest::Status::bad_input);
  ExposureStack count{{a, a}, {0.1}};
  EXPECT_EQ(status_of(count), fest::Status::bad_input);
  ExposureStack deep{{cv::Mat(4, 4, CV_16UC1), cv::Mat(4, 4, CV_16UC1)}, {0.1, 0.2}};
  EXPECT_EQ(status_of(deep), fest::Status::bad_input);
  ExposureStack negative{{a, a}, {-0.1, 0.2}};
  EXPECT_EQ(status_of(negative), fest::Status::bad_input);
  ExposureStack fine{{a, a}, {0.1, 0.2}};
  EXPECT_EQ(status_of(fine), fest::Status::ok);
}

}  // namespace
