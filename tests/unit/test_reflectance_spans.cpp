// The rasteriser's row spans against the per-pixel test they replace: every pixel of the
// bounding box tested with the three edge functions (the rasteriser's loop before spans),
// on random, sliver, nearly horizontal and pixel-centre-aligned triangles; silhouette runs
// against the filled silhouette; the run XOR against a pixel count.

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "reflectance/rasterizer.hpp"
#include "reflectance/silhouette_runs.hpp"
#include "reflectance/triangle_scan.hpp"
#include "test_reflectance_helpers.hpp"

namespace {

using namespace fest::reflectance;
using scan::ScreenVertex;

// The per-pixel loop: every centre of the clipped bounding box, inclusive on edges.
std::vector<std::pair<int, int>> brute_force(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int width,
                                          int height) {
  std::vector<std::pair<int, int>> out;  // row by row, left to right
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area == 0 || !std::isfinite(area)) return out;
  const int px0 = std::max(0, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}))));
  const int px1 = std::min(width - 1, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}))));
  const int py0 = std::max(0, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}))));
  const int py1 = std::min(height - 1, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}))));
  const double sign = area > 0 ? 1.0 : -1.0;
  for (int y = py0; y <= py1; ++y)
    for (int x = px0; x <= px1; ++x) {
      const double w0 = (c.x - b.x) * (y - b.y) - (c.y - b.y) * (x - b.x);
      const double w1 = (a.x - c.x) * (y - c.y) - (a.y - c.y) * (x - c.x);
      const double w2 = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
      if (sign * w0 < 0 || sign * w1 < 0 || sign * w2 < 0) continue;
      out.push_back({y, x});
    }
  return out;
}

std::vector<std::pair<int, int>> by_spans(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int width,
                                       int height) {
  std::vector<std::pair<int, int>> out;
  int last_row = -1;
  scan::scan_spans(a, b, c, width, 0, height, [&](int y, int x0, int x1) {
    EXPECT_GT(y, last_row);  // one span per row, rows ascending
    last_row = y;
    EXPECT_LE(x0, x1);
    for (int x = x0; x <= x1; ++x) out.push_back({y, x});
  });
  return out;
}


PinholeCamera looking_at_origin(const Eigen::Vector3d& eye, int w, int h, double f) {
  PinholeCamera c;
  c.width = w;
  c.height = h;
  c.fx = c.fy = f;
  c.cx = 0.5 * (w - 1) + 3.3;
  c.cy = 0.5 * (h - 1) - 2.1;
  c.R = look_at_rotation(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  c.t = -c.R * eye;
  return c;
}

}  // namespace

TEST(RasterSpans, EqualThePerPixelTestOnRandomTriangles) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-8.0, 72.0);
  std::uniform_int_distribution<int> grid(-4, 68);
  std::uniform_real_distribution<double> tiny(-1e-9, 1e-9);
  const int w = 64, h = 48;
  int covered = 0;
  for (int k = 0; k < 3000; ++k) {
    ScreenVertex v[3];
    for (auto& p : v) p = {u(rng), u(rng), 1.0};
    switch (k % 6) {
      case 1:  // vertices on pixel centres: edges through many centres
        for (auto& p : v) p = {double(grid(rng)), double(grid(rng)), 1.0};
        break;
      case 2:  // a sliver
        v[2] = {0.5 * (v[0].x + v[1].x) + tiny(rng), 0.5 * (v[0].y + v[1].y) + tiny(rng), 1.0};
        break;
      case 3:  // a nearly horizontal edge
        v[1].y = v[0].y + tiny(rng);
        break;
      case 4:  // a horizontal edge on a row of centres
        v[0].y = v[1].y = double(grid(rng));
        break;
      case 5:  // a small triangle
        v[1] = {v[0].x + 0.3 * (u(rng) - 32) / 40, v[0].y + 0.3 * (u(rng) - 32) / 40, 1.0};
        v[2] = {v[0].x + 0.3 * (u(rng) - 32) / 40, v[0].y + 0.3 * (u(rng) - 32) / 40, 1.0};
        break;
      default:
        break;
    }
    const auto expected = brute_force(v[0], v[1], v[2], w, h);
    ASSERT_EQ(by_spans(v[0], v[1], v[2], w, h), expected) << "triangle " << k;
    ASSERT_EQ(by_spans(v[0], v[2], v[1], w, h), brute_force(v[0], v[2], v[1], w, h)) << "triangle " << k << " reversed";
    covered += static_cast<int>(expected.size());
  }
  EXPECT_GT(covered, 50000);
}

TEST(RasterSpans, SilhouetteRunsAreTheFilledSilhouette) {
  const TriangleMesh m = fest::test::octahedron_sphere(4);
  for (const Eigen::Vector3d& eye : {Eigen::Vector3d(0.3, -3.5, 1.2), Eigen::Vector3d(2.0, 1.0, -1.5)}) {
    const PinholeCamera cam = looking_at_origin(eye, 173, 131, 120);
    const std::vector<std::uint8_t> filled = rasterize_silhouette(m, cam, 1);
    const CoverageRuns expected = runs_of_mask(filled.data(), cam.width, cam.height, static_cast<std::size_t>(cam.width));
    EXPECT_GT(expected.pixel_count(), 3000u);
    for (int threads : {1, 3}) {
      const CoverageRuns runs = silhouette_runs(m, cam, threads);
      EXPECT_EQ(runs.row_begin, expected.row_begin);
      ASSERT_EQ(runs.runs.size(), expected.runs.size());
      for (std::size_t i = 0; i < runs.runs.size(); ++i) {
        EXPECT_EQ(runs.runs[i].begin, expected.runs[i].begin);
        EXPECT_EQ(runs.runs[i].end, expected.runs[i].end);
      }
    }
  }
}

TEST(RasterSpans, SymmetricDifferenceCountsPixelsInExactlyOne) {
  std::mt19937_64 rng(3);
  std::bernoulli_distribution coin(0.5);
  const int w = 37, h = 23;
  std::vector<std::uint8_t> a(static_cast<std::size_t>(w) * h), b(a.size());
  for (int trial = 0; trial < 20; ++trial) {
    // Blocky images (runs of random lengths) plus a few isolated pixels.
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (i % 5 == 0 || coin(rng)) a[i] = coin(rng);
      if (i % 3 == 0 || coin(rng)) b[i] = coin(rng);
    }
    std::size_t expected = 0;
    for (std::size_t i = 0; i < a.size(); ++i) expected += (a[i] != 0) != (b[i] != 0);
    const CoverageRuns ra = runs_of_mask(a.data(), w, h, w), rb = runs_of_mask(b.data(), w, h, w);
    EXPECT_EQ(symmetric_difference(ra, rb), expected);
    EXPECT_EQ(symmetric_difference(rb, ra), expected);
    EXPECT_EQ(symmetric_difference(ra, ra), 0u);
  }
}
