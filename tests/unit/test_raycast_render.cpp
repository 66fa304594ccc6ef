// The analytic compositing cases of docs/volrender.md "Validation" (exact answers).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>

#include "raycast/render.hpp"

using namespace fest::raycast;
using fest::volume_pyramid::MinMaxPyramid;
using fest::volume_pyramid::ScalarGrid;

namespace {

ScalarGrid grid(std::size_t n, const std::function<double(std::size_t, std::size_t, std::size_t)>& f) {
  ScalarGrid g;
  g.dims = {n, n, n};
  g.values.resize(g.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) g.values[g.index(i, j, k)] = static_cast<float>(f(i, j, k));
  return g;
}

// Orthographic camera looking along +z through the middle of an n^3 grid.
Camera along_z(std::size_t n, int px = 8) {
  Camera c;
  c.kind = Camera::Kind::orthographic;
  c.width = c.height = px;
  const double m = (n - 1) / 2.0;
  c.eye = {m, m, -10};
  c.forward = {0, 0, 1}, c.right = {1, 0, 0}, c.up = {0, 1, 0};
  c.half_height = m / 2;
  return c;
}

double alpha_of(const ScalarGrid& g, const TransferFunction& tf, RenderOptions o) {
  o.keep_alpha = true;
  o.ert = 1.0;
  const MinMaxPyramid p(g, 1);
  const auto img = render(g, &p, tf, along_z(g.dims[0]), o);
  return img.rgba[(3 * 8 + 3) * 4 + 3];
}

}  // namespace

TEST(RaycastRender, HomogeneousSlabIndependentOfStep) {
  const auto g = grid(33, [](auto, auto, auto) { return 5.0; });
  const TransferFunction tf({{0, 1, 0.5, 0.25, 0.1}, {10, 1, 0.5, 0.25, 0.1}}, 5, 5, OpacityMode::opacity, 1.0);
  for (double step : {1.0, 0.5, 0.3, 0.1}) {
    RenderOptions o;
    o.step = step;
    o.ert = 1.0;
    const MinMaxPyramid p(g, 1);
    const auto img = render(g, &p, tf, along_z(33), o);
    const float* px = &img.rgba[(3 * 8 + 3) * 4];
    const double A = 1 - std::pow(0.9, 32);
    EXPECT_NEAR(px[0], A, 1e-5) << step;
    EXPECT_NEAR(px[1], 0.5 * A, 1e-5) << step;
    EXPECT_NEAR(px[2], 0.25 * A, 1e-5) << step;
  }
}

TEST(RaycastRender, ExtinctionRampIsExactForAnyStep) {
  const auto g = grid(33, [](auto, auto, auto k) { return k / 32.0; });
  const TransferFunction tf({{0, 1, 1, 1, 0}, {1, 1, 1, 1, 0.1}}, 0, 1, OpacityMode::extinction, 1.0);
  for (bool preint : {false, true})
    for (double step : {1.0, 0.5, 0.3, 0.1}) {
      RenderOptions o;
      o.step = step, o.preint = preint;
      EXPECT_NEAR(alpha_of(g, tf, o), 1 - std::exp(-1.6), 1e-6) << step << " preint " << preint;  // 0.798103
    }
}

TEST(RaycastRender, QuadraticSamplesTrapezoidIntegral) {
  const auto g = grid(33, [](auto, auto, auto k) { return (k / 32.0) * (k / 32.0); });
  const TransferFunction tf({{0, 1, 1, 1, 0}, {1, 1, 1, 1, 0.1}}, 0, 1, OpacityMode::extinction, 1.0);
  const double A = 1 - std::exp(-0.1 * 10928.0 / 1024.0);  // 0.656025
  RenderOptions o;
  for (double step : {0.5, 0.25}) {
    o.step = step;
    EXPECT_NEAR(alpha_of(g, tf, o), A, 1e-6) << step;
  }
  o.step = 0.3;
  EXPECT_NEAR(alpha_of(g, tf, o), A, 1e-4);
  o.preint = true;  // exact for the piecewise-linear reconstruction at aligned steps
  o.step = 0.5;
  EXPECT_NEAR(alpha_of(g, tf, o), A, 1e-6);
}

TEST(RaycastRender, MipOfABox) {
  const auto g = grid(64, [](auto i, auto j, auto k) { return (i >= 20 && i < 40 && j >= 20 && j < 40 && k >= 30 && k < 35) ? 1.0 : 0.0; });
  const TransferFunction tf({{0, 0, 0, 0, 0}, {1, 1, 1, 1, 1}}, 0, 1, OpacityMode::opacity, 1.0);
  RenderOptions o;
  o.mode = Mode::mip;
  o.window = std::array<double, 2>{0, 1};
  Camera c = along_z(64, 64);
  c.half_height = 31.5;  // one pixel per voxel column, pixel centres on the sample columns
  const MinMaxPyramid p(g, 1);
  const auto img = render(g, &p, tf, c, o);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      // pixel centre x = i (0..63), y = 63 - j
      const int x = i, y = 63 - j;
      const double v = img.rgba[(static_cast<std::size_t>(j) * 64 + i) * 4];
      if (x >= 20 && x < 40 && y >= 20 && y < 40) {
        EXPECT_NEAR(v, 1.0, 1e-7);
      }
      if (x < 19 || x > 40 || y < 19 || y > 40) {
        EXPECT_NEAR(v, 0.0, 1e-7);
      }
    }
}

TEST(RaycastRender, MipOfFEqualsMinipOfMinusF) {
  const auto f = grid(20, [](auto i, auto j, auto k) { return std::sin(0.3 * i) * std::cos(0.2 * j) + 0.01 * k; });
  auto neg = f;
  for (auto& v : neg.values) v = -v;
  const TransferFunction tf({{-2, 0, 0, 0, 0}, {2, 1, 1, 1, 1}}, -2, 2, OpacityMode::opacity, 1.0);
  RenderOptions o;
  o.mode = Mode::mip;
  o.window = std::array<double, 2>{-2, 2};
  const auto a = render(f, nullptr, tf, along_z(20), o);
  o.mode = Mode::minip;
  o.window = std::array<double, 2>{-2, 2};
  const auto b = render(neg, nullptr, tf, along_z(20), o);
  for (std::size_t p = 0; p < a.rgba.size(); p += 4) EXPECT_NEAR(a.rgba[p], 1.0 - b.rgba[p], 1e-6);
}

// Skipping on/off and one/two threads give identical bytes (docs/volrender.md "Acceleration").
TEST(RaycastRender, SkippingAndThreadsDoNotChangeBytes) {
  const auto g = grid(48, [](auto i, auto j, auto k) {
    const double d = (i - 30.0) * (i - 30.0) + (j - 20.0) * (j - 20.0) + (k - 25.0) * (k - 25.0);
    return 100 * std::exp(-d / 40);
  });
  const TransferFunction tf({{0, 0, 0, 0, 0}, {20, 0.2, 0.5, 1, 0}, {60, 1, 0.8, 0.2, 0.3}, {100, 1, 1, 1, 0.8}}, 0, 100,
                            OpacityMode::opacity, 1.0);
  const MinMaxPyramid p(g, 1);
  Camera c = orbit_camera({23.5, 23.5, 23.5}, 40, 30, 20, 0, 30, 1, 40, 32);
  for (Mode m : {Mode::dvr, Mode::iso, Mode::mip}) {
    RenderOptions o;
    o.mode = m;
    o.shade = true;
    o.isos = {{50, 0.6, std::nullopt}, {20, 0.3, std::nullopt}};
    const auto a = render(g, &p, tf, c, o);
    o.skip_empty = false;
    const auto b = render(g, &p, tf, c, o);
    o.skip_empty = true;
    o.threads = 2;
    const auto d = render(g, &p, tf, c, o);
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_EQ(a.rgba, d.rgba);
    EXPECT_GT(a.stats.skipped, 0u);
    EXPECT_LT(a.stats.samples, b.stats.samples);
  }
}

// The skipping block size (pyramid finest level 1, 2 or 3, with coarser levels skipping
// larger nodes), the gradient source (on the fly, a shading volume built by render() or
// passed in) and pre-integration give the same bytes as the plain march.
TEST(RaycastRender, SkipLevelsAndShadingVolumeDoNotChangeBytes) {
  const auto g = grid(40, [](auto i, auto j, auto k) {
    const double d1 = (i - 12.0) * (i - 12.0) + (j - 20.0) * (j - 20.0) + (k - 25.0) * (k - 25.0);
    const double d2 = (i - 28.0) * (i - 28.0) + (j - 14.0) * (j - 14.0) + (k - 10.0) * (k - 10.0);
    return 100 * std::exp(-d1 / 30) + 70 * std::exp(-d2 / 12);
  });
  const TransferFunction tf({{0, 0, 0, 0, 0}, {15, 0.2, 0.5, 1, 0}, {60, 1, 0.8, 0.2, 0.3}, {100, 1, 1, 1, 0.8}}, 0, 100,
                            OpacityMode::opacity, 1.0);
  Camera c = orbit_camera({19.5, 19.5, 19.5}, 34, 40, 25, 0, 30, 1, 40, 32);
  const auto sv = shading_volume(g, 2);
  for (Mode m : {Mode::dvr, Mode::iso}) {
    RenderOptions o;
    o.mode = m;
    o.shade = true;
    o.isos = {{50, 0.6, std::nullopt}, {20, 0.3, std::nullopt}};
    o.skip_empty = false;
    const auto plain = render(g, nullptr, tf, c, o);
    o.skip_empty = true;
    for (int level : {1, 2, 3}) {
      const MinMaxPyramid p(g, 1, level);
      const auto a = render(g, &p, tf, c, o);
      EXPECT_EQ(plain.rgba, a.rgba) << "level " << level;
      EXPECT_GT(a.stats.skipped, 0u);
      o.gradient_cache = true;
      const auto b = render(g, &p, tf, c, o);
      const auto d = render(g, &p, tf, c, o, nullptr, nullptr, &sv);
      EXPECT_EQ(b.rgba, d.rgba) << "level " << level;
      for (std::size_t q = 0; q < a.rgba.size(); ++q) EXPECT_NEAR(a.rgba[q], b.rgba[q], 1e-5);
      o.gradient_cache = false;
    }
  }
}

// Iso depth of a sphere SDF: analytic ray-sphere distance (orthographic view). Tolerance:
// trilinear reconstruction of |x| - R errs by up to 3 h^2 / (8 R) = 0.0125 voxel, the
// bisection by step/256 = 0.002 voxel.
TEST(RaycastRender, IsoDepthOfASphere) {
  const double R = 30, m = 47.5;
  const auto g = grid(96, [&](auto i, auto j, auto k) { return R - std::sqrt((i - m) * (i - m) + (j - m) * (j - m) + (k - m) * (k - m)); });
  const TransferFunction tf({{-50, 1, 1, 1, 1}, {50, 1, 1, 1, 1}}, -50, 50, OpacityMode::opacity, 1.0);
  RenderOptions o;
  o.mode = Mode::iso;
  o.isos = {{0, 1, std::nullopt}};
  Camera c = along_z(96, 32);
  c.half_height = 20;
  const MinMaxPyramid p(g, 1);
  const auto img = render(g, &p, tf, c, o);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const Ray r = c.ray(i + 0.5, j + 0.5);
      const double dx = r.origin[0] - m, dy = r.origin[1] - m;
      if (dx * dx + dy * dy > (R - 2) * (R - 2)) continue;
      const double expect = (m - std::sqrt(R * R - dx * dx - dy * dy)) - r.origin[2];
      EXPECT_NEAR(img.depth[static_cast<std::size_t>(j) * 32 + i], expect, 0.0125 + 0.002);
    }
}

TEST(RaycastRender, PixelMaskCastsOnlyMarkedPixels) {
  const auto g = grid(17, [](std::size_t i, std::size_t j, std::size_t k) { return double(i + j + k); });
  const TransferFunction tf({{0, 1, 0.2, 0.1, 0.3}, {48, 0.1, 0.5, 1, 0.6}}, 0, 48, OpacityMode::opacity, 1.0);
  RenderOptions o;
  o.background = {0.25, 0.5, 0.75};
  const MinMaxPyramid p(g, 1);
  const auto full = render(g, &p, tf, along_z(17), o);
  o.pixel_mask.assign(64, 0);
  for (int q = 0; q < 64; q += 3) o.pixel_mask[q] = 1;  // 22 pixels
  const auto masked = render(g, &p, tf, along_z(17), o);
  EXPECT_EQ(masked.stats.rays, 22u);
  for (int q = 0; q < 64; ++q)
    for (int c = 0; c < 4; ++c) {
      const float want = o.pixel_mask[q] ? full.rgba[4 * q + c] : c < 3 ? float(o.background[c]) : 1.0f;
      EXPECT_EQ(masked.rgba[4 * q + c], want) << q << " " << c;
    }
  o.pixel_mask.assign(63, 1);
  EXPECT_THROW(render(g, &p, tf, along_z(17), o), std::invalid_argument);
}

// Integer data get the int16 shading volume {f, 2 grad f} (half the bytes); it holds the
// same numbers as the float layout {f, grad f}, built here independently (central
// differences, one-sided at the border), so the images are the same bytes.
TEST(RaycastRender, Int16ShadingVolumeGivesTheFloatLayoutsBytes) {
  const auto g = grid(36, [](auto i, auto j, auto k) {
    const double d = (i - 15.0) * (i - 15.0) + (j - 19.0) * (j - 19.0) + (k - 17.0) * (k - 17.0);
    return std::round(1000 * std::exp(-d / 60) - 200);
  });
  const auto sv16 = shading_volume(g, 2);
  ASSERT_TRUE(sv16.data16 && !sv16.data);
  ShadingVolume svf;
  svf.samples = g.size();
  svf.data.reset(static_cast<float*>(std::malloc(4 * sizeof(float) * g.size())));
  const std::size_t n = g.dims[0];
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t q[3] = {i, j, k};
        float* out = &svf.data[4 * g.index(i, j, k)];
        out[0] = g.at(i, j, k);
        for (int a = 0; a < 3; ++a) {
          std::size_t lo[3] = {i, j, k}, hi[3] = {i, j, k};
          if (q[a] > 0) --lo[a];
          if (q[a] + 1 < n) ++hi[a];
          out[1 + a] = static_cast<float>((double(g.at(hi[0], hi[1], hi[2])) - g.at(lo[0], lo[1], lo[2])) / double(hi[a] - lo[a]));
        }
      }
  const TransferFunction tf({{-200, 0, 0, 0, 0}, {100, 0.2, 0.5, 1, 0}, {400, 1, 0.8, 0.2, 0.3}, {800, 1, 1, 1, 0.8}}, -200, 800,
                            OpacityMode::opacity, 1.0);
  const MinMaxPyramid p(g, 1, 2);
  Camera c = orbit_camera({17.5, 17.5, 17.5}, 30, 40, 25, 0, 30, 1, 40, 32);
  for (Mode m : {Mode::dvr, Mode::iso}) {
    RenderOptions o;
    o.mode = m;
    o.shade = true;
    o.gradient_cache = true;
    o.isos = {{300, 0.6, std::nullopt}};
    const auto a = render(g, &p, tf, c, o, nullptr, nullptr, &sv16);
    const auto b = render(g, &p, tf, c, o, nullptr, nullptr, &svf);
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_GT(a.stats.samples, 0u);
  }
}
