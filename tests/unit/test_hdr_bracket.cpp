// The simulated camera: Z = round(255 min(1, E dt)^(1/gamma) + noise), checked at values
// computed by hand, and its bad inputs.

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "hdr/bracket.hpp"

namespace {

using namespace fest::hdr;

TEST(HdrBracket, NoiselessValuesFollowTheModel) {
  cv::Mat e(1, 4, CV_32FC1);
  e.at<float>(0, 0) = 0.25f;   // (0.25 * 1)^(1/2) = 0.5 -> 127.5 -> 128
  e.at<float>(0, 1) = 4.0f;    // clipped at 1 -> 255
  e.at<float>(0, 2) = 0.0f;    // 0
  e.at<float>(0, 3) = 0.0144f; // sqrt(0.0144) = 0.12 -> 30.6 -> 31
  CameraModel cam;
  cam.gamma = 2;
  cam.noise_dn = 0;
  const cv::Mat z = expose(e, 1.0, cam, 1);
  EXPECT_EQ(z.at<std::uint8_t>(0, 0), 128);
  EXPECT_EQ(z.at<std::uint8_t>(0, 1), 255);
  EXPECT_EQ(z.at<std::uint8_t>(0, 2), 0);
  EXPECT_EQ(z.at<std::uint8_t>(0, 3), 31);
  EXPECT_DOUBLE_EQ(model_log_inverse(cam, 128), 0.0);
  EXPECT_DOUBLE_EQ(model_log_inverse(cam, 64), 2 * std::log(0.5));
}

TEST(HdrBracket, NoiseHasTheRequestedSpreadAndIsSeeded) {
  const cv::Mat e(100, 100, CV_32FC1, cv::Scalar(0.25));
  CameraModel cam;
  cam.gamma = 2;
  cam.noise_dn = 2;
  const cv::Mat a = expose(e, 1.0, cam, 5), b = expose(e, 1.0, cam, 5), c = expose(e, 1.0, cam, 6);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
  cv::Scalar mean, sd;
  cv::meanStdDev(a, mean, sd);
  EXPECT_NEAR(mean[0], 127.5, 0.1);
  // Rounding adds 1/12 DN^2 of variance to the 4 of the noise.
  EXPECT_NEAR(sd[0], std::sqrt(4 + 1.0 / 12), 0.1);
}

TEST(HdrBracket, RejectsBadInput) {
  EXPECT_THROW(expose(cv::Mat(2, 2, CV_8UC1, cv::Scalar(1)), 1.0, {}, 1), fest::Error);
  EXPECT_THROW(expose(cv::Mat(2, 2, CV_32FC1, cv::Scalar(std::nan(""))), 1.0, {}, 1), fest::Error);
  CameraModel noiseless;
  noiseless.noise_dn = 0;
  EXPECT_EQ(cv::countNonZero(expose(cv::Mat(2, 2, CV_32FC1, cv::Scalar(-1)), 1.0, noiseless, 1)), 0);
  EXPECT_THROW(expose(cv::Mat(2, 2, CV_32FC1, cv::Scalar(1)), 0.0, {}, 1), fest::Error);
}

}  // namespace
