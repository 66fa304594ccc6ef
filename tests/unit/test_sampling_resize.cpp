// Separable resize (docs/resample.md "Separable passes and their order"): linear light (G1), constants,
// identity, ramps, block means, alpha, thread independence and absurd sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/image.hpp"
#include "sampling/resize.hpp"

using fest::ColorSpace;
using fest::Image;
using fest::sampling::EdgeMode;
using fest::sampling::make_kernel;
using fest::sampling::resize;
using fest::sampling::ResizeOptions;

namespace {

ResizeOptions with_kernel(const char* name) {
  ResizeOptions o;
  o.kernel = make_kernel(name);
  return o;
}

Image float_image(int w, int h, int c, float (*f)(int, int, int)) {
  Image img;
  img.color_space = ColorSpace::linear;
  img.pixels.create(h, w, CV_MAKETYPE(CV_32F, c));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < c; ++ch) img.pixels.ptr<float>(y)[x * c + ch] = f(x, y, ch);
  return img;
}

Image checkerboard(int size, int channels) {
  Image img;
  img.pixels.create(size, size, CV_MAKETYPE(CV_8U, channels));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int ch = 0; ch < channels; ++ch) img.pixels.ptr<uchar>(y)[x * channels + ch] = ((x + y) % 2) ? 255 : 0;
  return img;
}

void expect_status(const std::function<void()>& f, fest::Status s, const std::string& needle) {
  try {
    f();
    ADD_FAILURE() << "no error (expected one mentioning '" << needle << "')";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), s) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(SamplingResize, CheckerboardInLinearLight) {
  // G1: a one-pixel 0/255 sRGB checkerboard halved with `box`: linear mean 0.5, sRGB
  // encode 1.055·0.5^(1/2.4) − 0.055 = 0.73536 → 187.52 → 188 in every pixel.
  const double expected = std::round(255 * (1.055 * std::pow(0.5, 1 / 2.4) - 0.055));
  ASSERT_EQ(expected, 188.0);
  for (int c : {1, 3}) {
    const Image out = resize(checkerboard(64, c), 32, 32, with_kernel("box"));
    ASSERT_EQ(out.pixels.type(), CV_MAKETYPE(CV_8U, c));
    double lo = 0, hi = 0;
    cv::minMaxLoc(out.pixels.reshape(1), &lo, &hi);
    EXPECT_EQ(lo, expected);
    EXPECT_EQ(hi, expected);
    EXPECT_EQ(out.color_space, ColorSpace::srgb);
  }
}

TEST(SamplingResize, CheckerboardInGammaMode) {
  // `--colorspace codes`: the mean of the codes, 127.5, rounds to 128.
  ResizeOptions o = with_kernel("box");
  o.linear_light = false;
  const Image out = resize(checkerboard(64, 3), 32, 32, o);
  double lo = 0, hi = 0;
  cv::minMaxLoc(out.pixels.reshape(1), &lo, &hi);
  EXPECT_EQ(lo, 128.0);
  EXPECT_EQ(hi, 128.0);
}

TEST(SamplingResize, ConstantStaysConstant) {
  const Image in = float_image(37, 23, 3, [](int, int, int ch) { return 0.25f + 0.25f * static_cast<float>(ch); });
  for (const char* k : {"point", "box", "triangle", "gaussian", "bspline", "mitchell", "catrom", "lanczos3",
                        "blackman-harris", "kaiser"}) {
    for (EdgeMode e : {EdgeMode::clamp, EdgeMode::reflect, EdgeMode::wrap}) {
      ResizeOptions o = with_kernel(k);
      o.edge = e;
      for (auto [w, h] : {std::pair{11, 7}, std::pair{80, 50}, std::pair{37, 9}}) {
        const Image out = resize(in, w, h, o);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            for (int ch = 0; ch < 3; ++ch)
              ASSERT_NEAR(out.pixels.ptr<float>(y)[x * 3 + ch], 0.25f + 0.25f * ch, 1e-6)
                  << k << " edge " << static_cast<int>(e) << " " << w << "x" << h << " at " << x << "," << y;
      }
    }
  }
}

TEST(SamplingResize, SameSizeWithInterpolatingKernelIsIdentity) {
  const Image in = float_image(19, 13, 2, [](int x, int y, int ch) {
    return std::sin(0.7f * static_cast<float>(x) + 1.3f * static_cast<float>(y * (ch + 1)));
  });
  for (const char* k : {"point", "box", "triangle", "catrom", "lanczos2", "lanczos3"}) {
    ResizeOptions o = with_kernel(k);
    o.premultiply_alpha = false;  // channel 1 would otherwise act as alpha
    const Image out = resize(in, 19, 13, o);
    EXPECT_LE(cv::norm(out.pixels, in.pixels, cv::NORM_INF), 1e-6) << k;
  }
  // 8-bit codes come back bit-exactly.
  Image codes;
  codes.pixels.create(9, 10, CV_8UC3);
  cv::randu(codes.pixels, 0, 256);
  for (bool linear : {false, true}) {
    ResizeOptions o = with_kernel("lanczos3");
    o.linear_light = linear;
    EXPECT_EQ(cv::norm(resize(codes, 10, 9, o).pixels, codes.pixels, cv::NORM_INF), 0.0) << linear;
  }
}

TEST(SamplingResize, RampStaysRampUnderMinification) {
  // v(i) = 0.5 (i + 0.5) + 1 along x. Output o is centred on input coordinate
  // (o + 0.5)/s. For an integer reduction k the taps lie symmetrically about that centre
  // (at u ± j for k odd, u ± (j + 1/2) for k even), so an even kernel with normalised
  // weights reproduces the ramp: away from the borders the output is 0.5 (o + 0.5)/s + 1.
  // (At other ratios the taps' phase breaks the symmetry and only constants are exact.)
  const Image in = float_image(60, 4, 1, [](int x, int, int) { return 0.5f * (static_cast<float>(x) + 0.5f) + 1; });
  for (const char* k : {"triangle", "mitchell", "catrom", "lanczos3", "gaussian", "bspline"}) {
    for (int w : {30, 20, 15}) {
      const double s = w / 60.0;
      const double reach = make_kernel(k).radius / s + 1;
      const Image out = resize(in, w, 4, with_kernel(k));
      for (int o = 0; o < w; ++o) {
        const double u = (o + 0.5) / s;
        if (u < reach || u > 60 - reach) continue;
        EXPECT_NEAR(out.pixels.ptr<float>(2)[o], 0.5 * u + 1, 1e-4) << k << " w=" << w << " o=" << o;
      }
    }
  }
}

TEST(SamplingResize, IntegerBoxDownscaleIsBlockMean) {
  const Image in = float_image(12, 9, 1, [](int x, int y, int) { return static_cast<float>((x * 7 + y * 13) % 17); });
  const Image out = resize(in, 4, 3, with_kernel("box"));
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      double sum = 0;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) sum += (((3 * x + i) * 7 + (3 * y + j) * 13) % 17);
      EXPECT_NEAR(out.pixels.ptr<float>(y)[x], sum / 9, 1e-5);
    }
}

TEST(SamplingResize, SixteenBitAndFloatSrgb) {
  // Mid-grey in linear light (0.5) encoded as sRGB 16-bit stays put under any kernel.
  Image in;
  in.pixels = cv::Mat(8, 8, CV_16UC1, cv::Scalar(48000));
  EXPECT_EQ(cv::norm(resize(in, 3, 5, with_kernel("lanczos3")).pixels, cv::Mat(5, 3, CV_16UC1, cv::Scalar(48000)),
                     cv::NORM_INF),
            0.0);
}

TEST(SamplingResize, TransparentColourDoesNotBleed) {
  // Left half opaque blue, right half fully transparent red: premultiplied filtering
  // gives no red anywhere, and alpha falls off across the boundary.
  Image in;
  in.color_space = ColorSpace::linear;
  in.pixels.create(8, 8, CV_32FC4);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      float* p = in.pixels.ptr<float>(y) + 4 * x;
      if (x < 4) { p[0] = 0; p[1] = 0; p[2] = 1; p[3] = 1; }
      else { p[0] = 1; p[1] = 0; p[2] = 0; p[3] = 0; }
    }
  const Image out = resize(in, 4, 4, with_kernel("triangle"));
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const float* p = out.pixels.ptr<float>(y) + 4 * x;
      EXPECT_EQ(p[0], 0.0f) << x;
      if (p[3] > 1e-6f) {
        EXPECT_NEAR(p[2], 1.0f, 1e-6) << x;
      }
    }
  EXPECT_NEAR(out.pixels.ptr<float>(0)[3], 1.0f, 1e-6);  // x = 0: only opaque input
  EXPECT_NEAR(out.pixels.ptr<float>(0)[4 * 3 + 3], 0.0f, 1e-6);
}

TEST(SamplingResize, OutputIndependentOfThreadCount) {
  const Image in = float_image(53, 41, 3, [](int x, int y, int ch) {
    return std::cos(0.37f * static_cast<float>(x * (ch + 1)) - 0.21f * static_cast<float>(y));
  });
  ResizeOptions o = with_kernel("lanczos3");
  o.threads = 1;
  const Image one = resize(in, 29, 67, o);
  for (int t : {2, 3, 7}) {
    o.threads = t;
    const Image many = resize(in, 29, 67, o);
    EXPECT_EQ(cv::norm(one.pixels, many.pixels, cv::NORM_INF), 0.0) << t;
  }
}

TEST(SamplingResize, AbsurdSizesAndInputs) {
  const Image in = float_image(4, 4, 1, [](int, int, int) { return 0.0f; });
  expect_status([&] { resize(in, 0, 10); }, fest::Status::usage, "must be positive");
  expect_status([&] { resize(in, 10, -1); }, fest::Status::usage, "must be positive");
  expect_status([&] { resize(in, 70000, 70000); }, fest::Status::usage, "2^31");
  EXPECT_NO_THROW(resize(in, 2, 2, with_kernel("sinc")));  // the DCT path (no finite support needed)
  expect_status([&] { resize(Image{}, 4, 4); }, fest::Status::bad_input, "empty");
  Image doubles;
  doubles.pixels = cv::Mat(4, 4, CV_64FC1, cv::Scalar(0));
  expect_status([&] { resize(doubles, 2, 2); }, fest::Status::bad_input, "depth");
  Image five;
  five.pixels = cv::Mat(4, 4, CV_8UC(5), cv::Scalar::all(0));
  expect_status([&] { resize(five, 2, 2); }, fest::Status::bad_input, "channels");
  ResizeOptions o;
  o.threads = -2;
  expect_status([&] { resize(in, 2, 2, o); }, fest::Status::usage, "threads");
}
