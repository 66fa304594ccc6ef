// lib/capture/pixel_formats: V4L2 frames -> Image. The expected colours come from the
// BT.601 equations (Kr = 0.299, Kb = 0.114, limited range 16-235 / 16-240) evaluated
// here in double precision, from the published 8-bit YCbCr values of the 100 % and 75 %
// colour bars (ITU-R BT.601 / SMPTE EG 1), and from an independent implementation:
// OpenCV's cvtColor(COLOR_YUV2RGB_YUYV), which uses the same equations in 20-bit fixed
// point.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "capture/pixel_formats.hpp"
#include "core/error.hpp"

namespace {

using namespace fest;
using namespace fest::capture;

// The inverse of BT.601's limited-range encoding, straight from the equations.
double expected_channel(int channel, int y, int cb, int cr) {
  const double kr = 0.299, kb = 0.114, kg = 1 - kr - kb;
  const double l = (y - 16) * 255.0 / 219.0, u = (cb - 128) * 255.0 / 112.0, v = (cr - 128) * 255.0 / 112.0;
  const double rgb[3] = {l + (1 - kr) * v, l - (1 - kb) * kb / kg * u - (1 - kr) * kr / kg * v, l + (1 - kb) * u};
  return std::min(255.0, std::max(0.0, rgb[channel]));
}

void expect_rgb(const Rgb8& p, int r, int g, int b, int tolerance, const std::string& what) {
  EXPECT_NEAR(p.r, r, tolerance) << what;
  EXPECT_NEAR(p.g, g, tolerance) << what;
  EXPECT_NEAR(p.b, b, tolerance) << what;
}

TEST(CapturePixelFormats, BlackAndWhiteAreTheEndsOfTheLimitedRange) {
  expect_rgb(bt601_limited_to_rgb(16, 128, 128), 0, 0, 0, 0, "Y=16 is black");
  expect_rgb(bt601_limited_to_rgb(235, 128, 128), 255, 255, 255, 0, "Y=235 is white");
  // 255/219 * (126-16) = 128.08
  expect_rgb(bt601_limited_to_rgb(126, 128, 128), 128, 128, 128, 0, "Y=126 is mid grey");
  // Footroom and headroom clamp rather than wrap.
  expect_rgb(bt601_limited_to_rgb(0, 128, 128), 0, 0, 0, 0, "below black");
  expect_rgb(bt601_limited_to_rgb(255, 128, 128), 255, 255, 255, 0, "above white");
  // R and B go negative and clamp; G = 255/112 (0.886*0.114 + 0.701*0.299)/0.587 * 112 = 134.9
  expect_rgb(bt601_limited_to_rgb(16, 16, 16), 0, 135, 0, 0, "extreme chroma clamps");
}

TEST(CapturePixelFormats, ColourBars) {
  struct Bar {
    const char* name;
    int y, cb, cr, r, g, b;
  };
  // 8-bit BT.601 YCbCr of the 100 % bars and two 75 % bars (191 = 0.75 * 255).
  const Bar bars[] = {
      {"white", 235, 128, 128, 255, 255, 255}, {"yellow", 210, 16, 146, 255, 255, 0},
      {"cyan", 170, 166, 16, 0, 255, 255},     {"green", 145, 54, 34, 0, 255, 0},
      {"magenta", 106, 202, 222, 255, 0, 255}, {"red", 81, 90, 240, 255, 0, 0},
      {"blue", 41, 240, 110, 0, 0, 255},       {"black", 16, 128, 128, 0, 0, 0},
      {"75% white", 180, 128, 128, 191, 191, 191}, {"75% yellow", 162, 44, 142, 191, 191, 0},
  };
  // The published YCbCr values are themselves rounded, so +-1 (the equations give e.g.
  // 192 for 75 % yellow's red).
  for (const Bar& b : bars) expect_rgb(bt601_limited_to_rgb(b.y, b.cb, b.cr), b.r, b.g, b.b, 1, b.name);
}

TEST(CapturePixelFormats, FixedPointMatchesTheEquationsEverywhere) {
  int off_by_one = 0, total = 0;
  for (int y = 0; y < 256; y += 3)
    for (int cb = 0; cb < 256; cb += 5)
      for (int cr = 0; cr < 256; cr += 5) {
        const Rgb8 p = bt601_limited_to_rgb(y, cb, cr);
        const int got[3] = {p.r, p.g, p.b};
        for (int c = 0; c < 3; ++c) {
          const double want = expected_channel(c, y, cb, cr);
          // Rounded to nearest, up to the fixed-point coefficients' error (< 0.01).
          ASSERT_LE(std::abs(got[c] - want), 0.51)
              << "y=" << y << " cb=" << cb << " cr=" << cr << " channel " << c;
          off_by_one += got[c] != int(std::lround(want));
          ++total;
        }
      }
  // 16.16 fixed point differs from double rounding only at near-ties.
  EXPECT_LT(off_by_one, total / 1000) << off_by_one << " of " << total;
}

std::string bytes(std::initializer_list<int> v) {
  std::string s;
  for (const int b : v) s += char(b);
  return s;
}

TEST(CapturePixelFormats, YuyvPairsShareTheirChromaAndRowsHonourTheStride) {
  // 4 x 2 pixels, stride 10 (2 bytes of padding per row). Row 0: black and white with
  // neutral chroma, then a pure red pair; row 1: blue then mid grey.
  const std::string data = bytes({16, 128, 235, 128, 81, 90, 81, 240, 0xEE, 0xEE,  //
                                  41, 240, 41, 110, 126, 128, 126, 128, 0xEE, 0xEE});
  const Image img = unpack_raw_frame({fourcc_yuyv, 4, 2, 10, data});
  ASSERT_EQ(img.pixels.type(), CV_8UC3);
  ASSERT_EQ(img.pixels.cols, 4);
  ASSERT_EQ(img.pixels.rows, 2);
  const auto px = [&](int r, int c) { return img.pixels.at<cv::Vec3b>(r, c); };
  EXPECT_EQ(px(0, 0), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(px(0, 1), cv::Vec3b(255, 255, 255));
  EXPECT_NEAR(px(0, 2)[0], 255, 1);
  EXPECT_NEAR(px(0, 2)[1], 0, 1);
  EXPECT_NEAR(px(0, 2)[2], 0, 1);
  EXPECT_EQ(px(0, 2), px(0, 3));
  EXPECT_NEAR(px(1, 0)[2], 255, 1);
  EXPECT_NEAR(px(1, 1)[0], 0, 1);
  EXPECT_EQ(px(1, 2), cv::Vec3b(128, 128, 128));
}

TEST(CapturePixelFormats, YuyvAgreesWithOpenCvWithinOneLevel) {
  const int w = 256, h = 64;
  // Legal studio-range samples: OpenCV clamps Y - 16 at 0 before scaling, the equation
  // does not (footroom below Y = 16 with strong chroma differs; both clamp the result).
  cv::Mat luma(h, w, CV_8UC1), chroma(h, w, CV_8UC1), yuyv;
  cv::RNG rng(21);
  rng.fill(luma, cv::RNG::UNIFORM, 16, 236);
  rng.fill(chroma, cv::RNG::UNIFORM, 16, 241);
  cv::merge(std::vector<cv::Mat>{luma, chroma}, yuyv);
  cv::Mat anchor;
  cv::cvtColor(yuyv, anchor, cv::COLOR_YUV2RGB_YUYV);
  const Image ours = unpack_raw_frame(
      {fourcc_yuyv, w, h, int(yuyv.step), std::string_view(reinterpret_cast<const char*>(yuyv.data), yuyv.total() * 2)});
  ASSERT_EQ(ours.pixels.type(), anchor.type());
  EXPECT_LE(cv::norm(ours.pixels, anchor, cv::NORM_INF), 1.0);
  cv::Mat diff;
  cv::absdiff(ours.pixels, anchor, diff);
  EXPECT_LT(cv::countNonZero(diff.reshape(1)), int(diff.total() * 3) / 20) << "more than 5 % off by one";
}

TEST(CapturePixelFormats, GreyRgbAndY16) {
  const Image g = unpack_raw_frame({fourcc_grey, 3, 1, 3, bytes({0, 100, 255})});
  ASSERT_EQ(g.pixels.type(), CV_8UC3);
  EXPECT_EQ(g.pixels.at<cv::Vec3b>(0, 1), cv::Vec3b(100, 100, 100));
  const Image c = unpack_raw_frame({fourcc_rgb3, 2, 1, 6, bytes({1, 2, 3, 4, 5, 6})});
  EXPECT_EQ(c.pixels.at<cv::Vec3b>(0, 1), cv::Vec3b(4, 5, 6));
  // Little-endian 16-bit samples, delivered unconverted.
  const Image w = unpack_raw_frame({fourcc_y16, 2, 2, 6, bytes({0x34, 0x12, 0xFF, 0xFF, 9, 9, 0, 0, 1, 0, 9, 9})});
  ASSERT_EQ(w.pixels.type(), CV_16UC1);
  EXPECT_EQ(w.pixels.at<std::uint16_t>(0, 0), 0x1234);
  EXPECT_EQ(w.pixels.at<std::uint16_t>(0, 1), 0xFFFF);
  EXPECT_EQ(w.pixels.at<std::uint16_t>(1, 0), 0);
  EXPECT_EQ(w.pixels.at<std::uint16_t>(1, 1), 1);
}

std::string message_of(const RawFrame& f) {
  try {
    unpack_raw_frame(f);
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    return e.what();
  }
  return "no error";
}

TEST(CapturePixelFormats, MalformedFramesAreBadInput) {
  const std::string eight(8, '\x80');
  EXPECT_EQ(message_of({fourcc_yuyv, 4, 2, 8, eight}), "YUYV frame: 8 bytes, 4 x 2 pixels need 16");
  EXPECT_EQ(message_of({fourcc_yuyv, 4, 1, 6, eight}),
            "YUYV frame: 6 bytes per line is shorter than a row of 4 pixels (8 bytes)");
  EXPECT_EQ(message_of({fourcc_yuyv, 3, 1, 6, eight}), "YUYV frame: width 3 is odd (pixels come in pairs)");
  EXPECT_EQ(message_of({fourcc_y16, 0, 1, 0, eight}), "Y16 frame: size 0 x 1 is not positive");
  EXPECT_EQ(message_of({fourcc('N', 'V', '1', '2'), 2, 2, 2, eight}),
            "camera frame: pixel format 'NV12' is not an uncompressed one fest unpacks");
  EXPECT_EQ(message_of({fourcc_mjpg, 2, 2, 2, eight}),
            "camera frame: pixel format 'MJPG' is not an uncompressed one fest unpacks");
  // The last row needs only its pixels, not the padding after them.
  EXPECT_NO_THROW(unpack_raw_frame({fourcc_grey, 2, 2, 6, bytes({1, 2, 0, 0, 0, 0, 3, 4})}));
}

TEST(CapturePixelFormats, FourccNames) {
  EXPECT_EQ(fourcc_from_name("YUYV"), fourcc_yuyv);
  EXPECT_EQ(fourcc_from_name("Y16"), fourcc_y16);
  EXPECT_EQ(fourcc_yuyv, 0x56595559u);  // v4l2_fourcc('Y','U','Y','V')
  EXPECT_EQ(fourcc_name(fourcc_y16), "Y16");
  EXPECT_EQ(fourcc_name(fourcc_mjpg), "MJPG");
  EXPECT_EQ(fourcc_name(0x01020304u), "????");
  EXPECT_EQ(fourcc_from_name(""), 0u);
  EXPECT_EQ(fourcc_from_name("ABCDE"), 0u);
}

}  // namespace
