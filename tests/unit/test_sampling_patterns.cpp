// Sample patterns and supersampled rendering (docs/resample.md "Rendering analytic scenes"): stratification properties,
// reproducibility, and the S1 convergence slopes (jittered ≈ −0.75, random ≈ −0.5).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "sampling/render.hpp"
#include "sampling/sample_patterns.hpp"
#include "sampling/scenes.hpp"

using namespace fest::sampling;

TEST(SamplingPatterns, JitterHasOneSamplePerCell) {
  const auto s = pixel_samples(Pattern::jitter, 64, 3, 10, 20);
  ASSERT_EQ(s.size(), 64u);
  std::set<int> cells;
  for (const auto& p : s) cells.insert(static_cast<int>(p.x * 8) + 8 * static_cast<int>(p.y * 8));
  EXPECT_EQ(cells.size(), 64u);
}

TEST(SamplingPatterns, RooksHaveOneSamplePerRowAndColumn) {
  const auto s = pixel_samples(Pattern::rooks, 37, 5, 1, 2);
  std::set<int> rows, cols;
  for (const auto& p : s) {
    cols.insert(static_cast<int>(p.x * 37));
    rows.insert(static_cast<int>(p.y * 37));
  }
  EXPECT_EQ(rows.size(), 37u);
  EXPECT_EQ(cols.size(), 37u);
}

TEST(SamplingPatterns, PoissonRespectsItsMinimumDistance) {
  const int n = 16;
  const auto s = pixel_samples(Pattern::poisson, n, 9, 4, 4);
  ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
  const double d = 0.75 / std::sqrt(n);
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      double dx = std::fabs(s[i].x - s[j].x), dy = std::fabs(s[i].y - s[j].y);
      dx = std::min(dx, 1 - dx);
      dy = std::min(dy, 1 - dy);
      EXPECT_GE(std::hypot(dx, dy), d - 1e-12);
    }
}

TEST(SamplingPatterns, SobolIsStratifiedInEveryDyadicInterval) {
  // Owen scrambling keeps the (0, 2)-net property: 16 points, one in each 1/16 column,
  // each 1/16 row, and each 1/4 x 1/4 square.
  const auto s = pixel_samples(Pattern::sobol, 16, 11, 3, 7);
  std::set<int> cols, rows, squares;
  for (const auto& p : s) {
    cols.insert(static_cast<int>(p.x * 16));
    rows.insert(static_cast<int>(p.y * 16));
    squares.insert(static_cast<int>(p.x * 4) + 4 * static_cast<int>(p.y * 4));
  }
  EXPECT_EQ(cols.size(), 16u);
  EXPECT_EQ(rows.size(), 16u);
  EXPECT_EQ(squares.size(), 16u);
}

TEST(SamplingPatterns, ReproducibleAndInsideThePixel) {
  for (Pattern p : {Pattern::regular, Pattern::jitter, Pattern::random, Pattern::rooks, Pattern::rgss,
                    Pattern::poisson, Pattern::halton, Pattern::sobol}) {
    const int n = p == Pattern::rgss ? 4 : 16;
    const auto a = pixel_samples(p, n, 42, 5, 6), b = pixel_samples(p, n, 42, 5, 6);
    ASSERT_EQ(a.size(), static_cast<std::size_t>(n)) << pattern_name(p);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].x, b[i].x);
      EXPECT_EQ(a[i].y, b[i].y);
      EXPECT_TRUE(a[i].x >= 0 && a[i].x < 1 && a[i].y >= 0 && a[i].y < 1) << pattern_name(p);
    }
  }
}

namespace {

// RMSE over the edge pixels (0 < ground truth < 1) of the S1 scene.
double edge_rmse(Pattern p, int n, std::uint64_t seed, const FloatImage& truth) {
  RenderOptions o;
  o.width = o.height = 64;
  o.samples = n;
  o.pattern = p;
  o.seed = seed;
  const FloatImage img = render(make_scene("edges", {}, 64, 64), o);
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < img.data.size(); ++i)
    if (truth.data[i] > 1e-6f && truth.data[i] < 1 - 1e-6f) {
      sum += std::pow(img.data[i] - truth.data[i], 2);
      ++count;
    }
  return std::sqrt(sum / count);
}

// Least-squares slope of log RMSE against log N over N = 4, 16, 64, 256 (mean of 3 seeds).
double error_slope(Pattern p, const FloatImage& truth) {
  std::vector<double> lx, ly;
  for (int n : {4, 16, 64, 256}) {
    double e = 0;
    for (std::uint64_t seed : {1, 2, 3}) e += edge_rmse(p, n, seed, truth) / 3;
    lx.push_back(std::log(n));
    ly.push_back(std::log(e));
  }
  const double mx = (lx[0] + lx[1] + lx[2] + lx[3]) / 4, my = (ly[0] + ly[1] + ly[2] + ly[3]) / 4;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 4; ++i) {
    sxy += (lx[i] - mx) * (ly[i] - my);
    sxx += (lx[i] - mx) * (lx[i] - mx);
  }
  return sxy / sxx;
}

}  // namespace

TEST(SamplingRender, ConvergenceSlopesOfJitteredAndRandomSampling) {
  // S1 (docs/resample.md "Figures reproduced"): a 64² disk XOR half-plane, box pixel filter. Ground truth: 16384
  // stratified samples per pixel (its own error, ~1e-4, is far below the N = 256 errors).
  RenderOptions gt;
  gt.width = gt.height = 64;
  gt.samples = 16384;
  gt.pattern = Pattern::jitter;
  gt.seed = 99;
  const FloatImage truth = render(make_scene("edges", {}, 64, 64), gt);
  const double jitter = error_slope(Pattern::jitter, truth);
  const double random = error_slope(Pattern::random, truth);
  RecordProperty("jitter_slope", std::to_string(jitter));
  RecordProperty("random_slope", std::to_string(random));
  // Theory: stratified sampling of an edge gives N^{-3/4}, independent samples N^{-1/2}.
  EXPECT_GT(jitter, -0.85);
  EXPECT_LT(jitter, -0.65);
  EXPECT_GT(random, -0.58);
  EXPECT_LT(random, -0.42);
}

TEST(SamplingRender, BoxFilteredSineIsTheSincScaledCosine) {
  // (1/Δ)∫ over a pixel of ½ + ½cos(2πf x) = ½ + ½ sinc(f) cos(2πf x_c) (an analytic case).
  const double f = 0.3, pi = std::acos(-1.0);
  RenderOptions o;
  o.width = 32;
  o.height = 2;
  o.samples = 4096;
  o.pattern = Pattern::regular;
  const FloatImage img = render(make_scene("sine", {{"f", f}}, 32, 2), o);
  const double sinc = std::sin(pi * f) / (pi * f);
  for (int x = 0; x < 32; ++x) EXPECT_NEAR(img.row(0)[x], 0.5 + 0.5 * sinc * std::cos(2 * pi * f * (x + 0.5)), 2e-4);
}

TEST(SamplingRender, WideFilterIsThreadIndependent) {
  RenderOptions o;
  o.width = 40;
  o.height = 33;
  o.samples = 4;
  o.pattern = Pattern::rooks;
  o.pixel_filter = make_kernel("mitchell");
  o.threads = 1;
  const Scene s = make_scene("siemens", {}, 40, 33);
  const FloatImage a = render(s, o);
  o.threads = 3;
  const FloatImage b = render(s, o);
  EXPECT_EQ(a.data, b.data);
}
