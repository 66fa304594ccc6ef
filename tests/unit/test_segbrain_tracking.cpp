// Line tracking (docs/segbrain.md §4): the straight line in a uniform-cost grid, a curved
// low-cost channel followed through a costly background, the tubularity of a bright and
// a dark cylinder, and the optic nerves of the synthetic head tracked from the posterior
// pole of each globe to the chiasm zone against the phantom's known centre lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "segbrain/phantom.hpp"
#include "segbrain/tracking.hpp"

#include "test_segbrain_helpers.hpp"

using namespace fest::segbrain;

namespace {

using fest::segbrain::test_support::grid;

std::array<double, 3> pos(const Grid& g, std::size_t i) {
  return {double(i % g.n[0]) * g.spacing[0], double((i / g.n[0]) % g.n[1]) * g.spacing[1],
          double(i / (g.n[0] * g.n[1])) * g.spacing[2]};
}

Mask ball(const Grid& g, const std::array<double, 3>& c, double r) {
  Mask m(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    auto p = pos(g, i);
    m[i] = (p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2]) <= r * r;
  }
  return m;
}

Mask single(const Grid& g, std::size_t x, std::size_t y, std::size_t z) {
  Mask m(g.size(), 0);
  m[g.index(x, y, z)] = 1;
  return m;
}

double distance_to_segment(const std::array<double, 3>& p, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  double d[3], u[3], dd = 0, du = 0;
  for (int k = 0; k < 3; ++k) {
    d[k] = b[k] - a[k];
    u[k] = p[k] - a[k];
    dd += d[k] * d[k];
    du += d[k] * u[k];
  }
  const double t = std::clamp(du / dd, 0.0, 1.0);
  double r2 = 0;
  for (int k = 0; k < 3; ++k) r2 += (u[k] - t * d[k]) * (u[k] - t * d[k]);
  return std::sqrt(r2);
}

double dist(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

TEST(SegbrainTracking, StraightLineInUniformCost) {
  Grid g = grid(50, 30, 30, 0.8, 1, 1);
  Image cost(g.size(), 1.0f);
  auto p = line_track(g, cost, single(g, 5, 10, 10), single(g, 45, 10, 10), 5);
  ASSERT_EQ(p.size(), 41u);
  for (std::size_t k = 0; k < p.size(); ++k) EXPECT_EQ(p[k], g.index(5 + k, 10, 10));
  EXPECT_NEAR(path_length_mm(g, p), 40 * 0.8, 1e-9);
  // The space diagonal: 20 steps of sqrt(3) (spacing 1), exact to well under 1 %.
  Grid h = grid(30, 30, 30);
  Image uc(h.size(), 1.0f);
  auto q = line_track(h, uc, single(h, 5, 5, 5), single(h, 25, 25, 25), 5);
  ASSERT_EQ(q.size(), 21u);
  EXPECT_NEAR(path_length_mm(h, q), 20 * std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(path_length_mm(h, q, 4), 20 * std::sqrt(3.0), 1e-9);
}

TEST(SegbrainTracking, FollowsACheapCurvedChannel) {
  // A quarter circle of radius 20 voxels in the slice z = 10, cost 1 inside a channel of
  // half-width 1.5, 50 outside: the path stays in the channel although the chord is
  // shorter.
  Grid g = grid(40, 40, 20);
  Image cost(g.size(), 50.0f);
  for (std::size_t z = 0; z < 20; ++z)
    for (std::size_t y = 0; y < 40; ++y)
      for (std::size_t x = 0; x < 40; ++x) {
        const double rr = std::hypot(double(x) - 5, double(y) - 5), dz = double(z) - 10;
        if (std::hypot(rr - 20, dz) <= 1.5) cost[g.index(x, y, z)] = 1.0f;
      }
  auto p = line_track(g, cost, single(g, 25, 5, 10), single(g, 5, 25, 10), 5);
  ASSERT_FALSE(p.empty());
  for (std::size_t i : p) EXPECT_EQ(cost[i], 1.0f);
  EXPECT_NEAR(path_length_mm(g, p, 4), 0.5 * M_PI * 20, 0.06 * 0.5 * M_PI * 20);
  // Impassable (infinite) cost everywhere but the start: nothing reaches the end.
  Image wall(g.size(), INFINITY);
  wall[g.index(25, 5, 10)] = 1;
  EXPECT_TRUE(line_track(g, wall, single(g, 25, 5, 10), single(g, 5, 25, 10), 5).empty());
}

TEST(SegbrainTracking, TubularityOfBrightAndDarkCylinders) {
  Grid g = grid(32, 32, 32);
  Image bright(g.size()), dark(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    auto p = pos(g, i);
    const double r = std::hypot(p[0] - 15.5, p[1] - 15.5);  // along S
    bright[i] = r <= 2.0 ? 100.0f : 20.0f;
    dark[i] = r <= 2.0 ? 20.0f : 100.0f;
  }
  Mask none;
  Image vb = vesselness(g, bright, 1.5, Polarity::bright, none);
  Image vd = vesselness(g, bright, 1.5, Polarity::dark, none);
  Image va = vesselness(g, dark, 1.5, Polarity::any, none);
  const std::size_t axis = g.index(15, 15, 16), off = g.index(4, 4, 16);
  EXPECT_GT(vb[axis], 0.5);
  EXPECT_LT(vb[off], 0.05);
  EXPECT_EQ(vd[axis], 0.0f);
  EXPECT_GT(va[axis], 0.5);  // a dark tube for the polarity `any`
  for (float v : vb) EXPECT_TRUE(v >= 0 && v < 1);
}

TEST(SegbrainTracking, OpticNervesOfThePhantomFollowTheirCentreLines) {
  PhantomOptions o;  // 160x192x160 at 1 mm, noise 3 %, bias 20 %
  Phantom ph = make_phantom(o);
  const Grid& g = ph.grid;
  // Phantom positions are relative to the grid centre; the canonical grid's mm start at
  // voxel 0.
  auto canon = [&](const std::array<double, 3>& p) {
    std::array<double, 3> q;
    for (int a = 0; a < 3; ++a) q[a] = p[a] + 0.5 * double(g.n[a] - 1) * g.spacing[a];
    return q;
  };
  const auto nerves = phantom_nerves();
  const auto eyes = phantom_eye_centres();
  const auto chiasm = canon(nerves[0].to);
  // Search box: the eyes to 65 mm behind them; the chiasm zone a midline strip 35-65 mm
  // behind and 0-25 mm above the eye centres (the knowledge base's priors).
  const auto e0 = canon(eyes[0]), e1 = canon(eyes[1]);
  Mask roi(g.size()), zone(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    auto p = pos(g, i);
    roi[i] = p[0] >= e0[0] - 10 && p[0] <= e1[0] + 10 && p[1] >= e0[1] - 75 && p[1] <= e0[1] && p[2] >= e0[2] - 15 &&
             p[2] <= e0[2] + 35;
    zone[i] = std::abs(p[0] - chiasm[0]) <= 2 && p[1] >= e0[1] - 65 && p[1] <= e0[1] - 35 && p[2] >= e0[2] &&
              p[2] <= e0[2] + 25;
  }
  Image v = vesselness(g, ph.t1, 1.5, Polarity::any, roi);
  Image cost(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    const bool in_window = ph.t1[i] >= 0.5 * 110 && ph.t1[i] <= 1.1 * 110;
    cost[i] = static_cast<float>(1.0 / (0.05 + v[i]) * (in_window ? 1 : 5));
  }
  for (int side = 0; side < 2; ++side) {
    const auto pole = canon(nerves[side].from);
    auto path = line_track(g, cost, ball(g, pole, 2), zone, 10);
    ASSERT_FALSE(path.empty());
    // Tolerance: every voxel of the tracked line within 1.5 mm (a voxel and a half) of
    // the phantom's centre line; the start within the 2 mm start ball, the end within
    // 4 mm of the chiasm point (the zone is entered up to 2 mm off the midline).
    double worst = 0;
    for (std::size_t i : path) worst = std::max(worst, distance_to_segment(pos(g, i), pole, chiasm));
    EXPECT_LE(worst, 1.5) << "side " << side;
    EXPECT_LE(dist(pos(g, path.front()), pole), 2.0 + 1e-9);
    EXPECT_LE(dist(pos(g, path.back()), chiasm), 4.0);
    // Its length is that of the segment less what the start ball and the zone cut off.
    const double truth = dist(pole, chiasm);
    EXPECT_NEAR(path_length_mm(g, path, 4), truth, 8.0);
    EXPECT_GT(path_length_mm(g, path, 4), 35.0);
  }
}
