// formats/image/image_stream: concatenated PGM/PPM and PNG frames split into frames.
#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "formats/image/image_io.hpp"
#include "formats/image/image_stream.hpp"

using namespace fest;

namespace {
std::string frame(int w, int h, formats::Format f, int value) {
  cv::Mat m(h, w, CV_8UC1, cv::Scalar(value));
  return formats::write_image({m, ColorSpace::srgb}, f);
}
}  // namespace

TEST(ImageStream, SplitsConcatenatedNetpbmAndPng) {
  for (const char* name : {"pgm", "png"}) {
    const formats::Format f = formats::output_format_from_name(name).format;
    const std::string a = frame(7, 5, f, 10), b = frame(7, 5, f, 200), c = frame(3, 2, f, 99);
    const std::string stream = a + b + c;  // the parts view into it
    const auto parts = formats::split_image_stream(stream);
    ASSERT_EQ(parts.size(), 3u) << name;
    EXPECT_EQ(parts[0], a);
    EXPECT_EQ(parts[1], b);
    EXPECT_EQ(parts[2], c);
  }
}

TEST(ImageStream, OneImageIsOneFrame) {
  const std::string tiff_like = "II*\0not really";
  EXPECT_EQ(formats::split_image_stream(tiff_like).size(), 1u);
}

TEST(ImageStream, RefusesTruncationAndJunk) {
  const formats::Format pgm = formats::output_format_from_name("pgm").format;
  const formats::Format png = formats::output_format_from_name("png").format;
  const std::string a = frame(7, 5, pgm, 10);
  test::expect_bad_input([&] { formats::split_image_stream(a + a.substr(0, a.size() - 3)); }, "frame 1");
  test::expect_bad_input([&] { formats::split_image_stream(a + "junk"); }, "after frame 1");
  const std::string p = frame(7, 5, png, 10);
  test::expect_bad_input([&] { formats::split_image_stream(p + p.substr(0, 20)); }, "frame 1 (PNG) is truncated");
  test::expect_bad_input([&] { formats::split_image_stream(""); }, "empty");
  test::expect_bad_input([&] { formats::split_image_stream("P2\n2 1\n255\n1 2\n"); }, "ASCII");
}
