// Contact sheets (hdrmerge sheet): tiles laid out in rows at the tile width, one exposure
// for the whole sheet (a tile twice as bright stays brighter), the sRGB curve.

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "hdr/contact_sheet.hpp"

namespace {

TEST(HdrContactSheet, LayoutAndCommonExposure) {
  const cv::Mat dim(40, 80, CV_32FC3, cv::Scalar::all(1.0));
  const cv::Mat bright(40, 80, CV_32FC3, cv::Scalar::all(2.0));
  const cv::Mat sheet = fest::hdr::contact_sheet({dim, bright, dim}, 2, 40);
  ASSERT_EQ(sheet.type(), CV_8UC3);
  EXPECT_EQ(sheet.cols, 80);   // 2 columns of 40
  EXPECT_EQ(sheet.rows, 40);   // 2 rows of 20
  // The 99th percentile (2.0) maps to 0.8, so 1.0 maps to 0.4: sRGB 0.4 = 170/255.
  const double expect_dim = 255 * (1.055 * std::pow(0.4, 1 / 2.4) - 0.055);
  const double expect_bright = 255 * (1.055 * std::pow(0.8, 1 / 2.4) - 0.055);
  EXPECT_NEAR(sheet.at<cv::Vec3b>(5, 5)[0], expect_dim, 0.6);
  EXPECT_NEAR(sheet.at<cv::Vec3b>(5, 45)[1], expect_bright, 0.6);
  EXPECT_NEAR(sheet.at<cv::Vec3b>(25, 5)[2], expect_dim, 0.6);
  EXPECT_EQ(sheet.at<cv::Vec3b>(25, 45)[0], 0);  // no fourth tile: black
}

TEST(HdrContactSheet, RefusesBadInput) {
  EXPECT_THROW(fest::hdr::contact_sheet({}, 2, 40), fest::Error);
  EXPECT_THROW(fest::hdr::contact_sheet({cv::Mat(4, 4, CV_8UC3)}, 2, 40), fest::Error);
  EXPECT_THROW(fest::hdr::contact_sheet({cv::Mat(4, 4, CV_32FC3)}, 0, 40), fest::Error);
}

}  // namespace
