#pragma once
// Shared helpers of the image tests: patterned images, and assertions on fest::Error.

#include <cstdint>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"

namespace fest::test {

// Random samples over the whole range of the depth (floats: signed, wide range), with a
// fixed seed so failures reproduce.
inline cv::Mat random_image(int width, int height, int depth, int channels, std::uint64_t seed = 7) {
  cv::Mat m(height, width, CV_MAKETYPE(depth, channels));
  cv::RNG rng(seed);
  if (depth == CV_8U) rng.fill(m, cv::RNG::UNIFORM, 0, 256);
  else if (depth == CV_16U) rng.fill(m, cv::RNG::UNIFORM, 0, 65536);
  else rng.fill(m, cv::RNG::UNIFORM, -1000.0, 1000.0);
  return m;
}

// The orientation pattern: all zero but pixel (x=1, y=0) full red and (x=0, y=1) full
// blue (channel 2), so a flip, a transpose or a BGR swap each show.
inline cv::Mat orientation_image(int depth, int channels) {
  cv::Mat m(3, 4, CV_MAKETYPE(depth, channels), cv::Scalar::all(0));
  const double full = depth == CV_8U ? 255 : depth == CV_16U ? 65535 : 1.0;
  auto set = [&](int x, int y, int c, double v) {
    if (depth == CV_8U) m.ptr<std::uint8_t>(y)[x * channels + c] = static_cast<std::uint8_t>(v);
    else if (depth == CV_16U) m.ptr<std::uint16_t>(y)[x * channels + c] = static_cast<std::uint16_t>(v);
    else m.ptr<float>(y)[x * channels + c] = static_cast<float>(v);
  };
  set(1, 0, 0, full);
  if (channels >= 3) set(0, 1, 2, full);
  else set(0, 1, 0, full / 2);
  if (channels == 2 || channels == 4) set(3, 2, channels - 1, full);  // alpha corner
  return m;
}

inline bool identical(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

}  // namespace fest::test

// Asserts that `statement` throws fest::Error with Status::bad_input.
#define EXPECT_BAD_INPUT(statement)                                                        \
  do {                                                                                     \
    try {                                                                                  \
      statement;                                                                           \
      ADD_FAILURE() << "expected fest::Error(bad_input) from: " #statement;                \
    } catch (const ::fest::Error& e) {                                                     \
      EXPECT_EQ(e.status(), ::fest::Status::bad_input) << e.what();                        \
    }                                                                                      \
  } while (0)
