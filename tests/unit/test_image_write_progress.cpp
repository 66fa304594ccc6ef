// ImageWriteOptions::progress: libpng's row callback (and OpenEXR's blocks of lines) reach
// the caller as (rows written, rows), rising to (rows, rows), and listening does not change
// a byte of the file.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "formats/image/image_io.hpp"
#include "test_image_helpers.hpp"

namespace fest::formats {
namespace {

TEST(WriteProgress, RowsRiseToTheImageHeightAndTheBytesAreUnchanged) {
  for (const int depth : {CV_8U, CV_16U}) {
    for (const int channels : {1, 3, 4}) {
      const Image image{fest::test::random_image(37, 301, depth, channels), ColorSpace::srgb};
      std::vector<std::pair<std::uint64_t, std::uint64_t>> calls;
      ImageWriteOptions listening;
      listening.progress = [&calls](std::uint64_t done, std::uint64_t total) { calls.emplace_back(done, total); };
      const std::string with = write_image(image, Format::png, listening);
      const std::string without = write_image(image, Format::png);
      EXPECT_EQ(with, without) << "depth " << depth << ", " << channels << " channels";
      ASSERT_FALSE(calls.empty());
      for (std::size_t i = 0; i < calls.size(); ++i) {
        EXPECT_EQ(calls[i].second, 301u);
        EXPECT_LE(calls[i].first, 301u);
        if (i > 0) {
          EXPECT_GT(calls[i].first, calls[i - 1].first);
        }
      }
      EXPECT_EQ(calls.back().first, 301u);
      // Every 64th row and the last: 64, 128, 192, 256, 301.
      EXPECT_EQ(calls.size(), 5u);
    }
  }
}

TEST(WriteProgress, ExrLinesRiseInBlocksAndTheBytesAreUnchanged) {
  cv::Mat pixels(601, 23, CV_32FC3);
  cv::randu(pixels, cv::Scalar::all(-2.0), cv::Scalar::all(1e4));
  const Image image{pixels, ColorSpace::linear};
  for (const bool half : {false, true}) {
    std::vector<std::uint64_t> done;
    ImageWriteOptions listening;
    listening.exr_half = half;
    listening.progress = [&done](std::uint64_t d, std::uint64_t total) {
      EXPECT_EQ(total, 601u);
      done.push_back(d);
    };
    ImageWriteOptions silent;
    silent.exr_half = half;
    EXPECT_EQ(write_image(image, Format::exr, listening), write_image(image, Format::exr, silent)) << "half " << half;
    // Blocks of 256 lines (16 of OpenEXR's 16-line ZIP blocks), then the rest.
    EXPECT_EQ(done, (std::vector<std::uint64_t>{256, 512, 601}));
  }
}

TEST(WriteProgress, TheBarHelperWritesTheSameBytesSilentlyWhenNotWanted) {
  // 2048 x 2048: above the 4-megapixel threshold, so the bar is made (not drawn: not wanted).
  const Image image{cv::Mat(2048, 2048, CV_8UC1, cv::Scalar(17)), ColorSpace::srgb};
  testing::internal::CaptureStderr();
  const std::string bytes = write_image_with_bar(image, Format::png, {}, false);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(bytes, write_image(image, Format::png));
}

}  // namespace
}  // namespace fest::formats
