// Silhouette masks (docs/hdrmerge.md §5): a dark object with a hole and a dark speck
// against a bright backlit background -> the object's disc, hole filled, speck dropped.

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "capture/silhouette.hpp"
#include "core/error.hpp"

namespace {

TEST(CaptureSilhouette, LargestComponentWithHolesFilled) {
  cv::Mat shot(120, 160, CV_16UC3, cv::Scalar::all(60000));
  cv::circle(shot, {80, 60}, 30, cv::Scalar::all(2000), cv::FILLED);
  cv::circle(shot, {80, 60}, 8, cv::Scalar::all(60000), cv::FILLED);  // a bright hole (a highlight)
  cv::rectangle(shot, cv::Rect(5, 5, 4, 4), cv::Scalar::all(1000), cv::FILLED);  // dust on the backlight
  const cv::Mat mask = fest::capture::silhouette_mask(shot);
  ASSERT_EQ(mask.type(), CV_8UC1);
  cv::Mat disc(120, 160, CV_8UC1, cv::Scalar(0));
  cv::circle(disc, {80, 60}, 30, cv::Scalar(255), cv::FILLED);
  EXPECT_EQ(cv::countNonZero(mask != disc), 0);
  EXPECT_EQ(mask.at<std::uint8_t>(6, 6), 0);
  EXPECT_EQ(mask.at<std::uint8_t>(60, 80), 255);
}

TEST(CaptureSilhouette, NoContrastIsBadInput) {
  EXPECT_THROW(fest::capture::silhouette_mask(cv::Mat(10, 10, CV_8UC1, cv::Scalar(7))), fest::Error);
  EXPECT_THROW(fest::capture::silhouette_mask(cv::Mat(10, 10, CV_32FC1, cv::Scalar(7))), fest::Error);
}

}  // namespace
