// The fast operators (docs/segbrain.md §5) against simple reference implementations written for the
// test: flood-fill components (ids in raster order of first voxels), flood-fill hole
// filling, brute-force distances and balls, direct separable convolution; and the same
// results for any number of worker threads (deterministic output).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <tuple>
#include <vector>

#include "segbrain/filters.hpp"
#include "segbrain/morphology.hpp"
#include "segbrain/parallel.hpp"
#include "segbrain/phantom.hpp"
#include "segbrain/shape.hpp"

#include "test_segbrain_helpers.hpp"

using namespace fest::segbrain;

namespace {

using fest::segbrain::test_support::grid;

Mask random_mask(const Grid& g, std::mt19937& rng, int percent) {
  Mask m(g.size());
  for (auto& v : m) v = static_cast<int>(rng() % 100) < percent;
  return m;
}

struct Xyz {
  long x, y, z;
};
Xyz xyz(const Grid& g, std::size_t i) {
  return {long(i % g.n[0]), long((i / g.n[0]) % g.n[1]), long(i / (g.n[0] * g.n[1]))};
}
bool inside(const Grid& g, long x, long y, long z) {
  return x >= 0 && y >= 0 && z >= 0 && x < long(g.n[0]) && y < long(g.n[1]) && z < long(g.n[2]);
}
bool neighbours(int conn, long dx, long dy, long dz) {
  const long k = std::labs(dx) + std::labs(dy) + std::labs(dz);
  if (k == 0 || std::labs(dx) > 1 || std::labs(dy) > 1 || std::labs(dz) > 1) return false;
  switch (conn) {
    case 4: return dz == 0 && k == 1;
    case 8: return dz == 0;
    case 6: return k == 1;
    case 18: return k <= 2;
    default: return true;
  }
}

// Breadth-first flood fill from every unlabelled voxel in raster order.
Components reference_components(const Grid& g, const Mask& m, int conn) {
  Components c;
  c.label.assign(g.size(), 0);
  c.size.push_back(0);
  for (std::size_t s = 0; s < g.size(); ++s) {
    if (!m[s] || c.label[s]) continue;
    const auto id = static_cast<std::uint32_t>(c.size.size());
    std::vector<std::size_t> queue{s};
    c.label[s] = id;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const Xyz p = xyz(g, queue[q]);
      for (long dz = -1; dz <= 1; ++dz)
        for (long dy = -1; dy <= 1; ++dy)
          for (long dx = -1; dx <= 1; ++dx) {
            if (!neighbours(conn, dx, dy, dz) || !inside(g, p.x + dx, p.y + dy, p.z + dz)) continue;
            const std::size_t j = g.index(std::size_t(p.x + dx), std::size_t(p.y + dy), std::size_t(p.z + dz));
            if (m[j] && !c.label[j]) c.label[j] = id, queue.push_back(j);
          }
    }
    c.size.push_back(queue.size());
  }
  return c;
}

// Background components that reach the grid border (x, y; and z unless per slice) are
// outside; everything else is filled.
Mask reference_fill(const Grid& g, const Mask& m, bool per_slice) {
  Mask inv(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) inv[i] = !m[i];
  Components c = reference_components(g, inv, per_slice ? 4 : 6);
  std::vector<bool> outside(c.size.size(), false);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Xyz p = xyz(g, i);
    const bool border = p.x == 0 || p.y == 0 || p.x + 1 == long(g.n[0]) || p.y + 1 == long(g.n[1]) ||
                        (!per_slice && (p.z == 0 || p.z + 1 == long(g.n[2])));
    if (border && c.label[i]) outside[c.label[i]] = true;
  }
  Mask out(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = !(c.label[i] && outside[c.label[i]]);
  return out;
}

double brute_squared_distance(const Grid& g, const Mask& target, std::size_t i) {
  const Xyz p = xyz(g, i);
  double best = INFINITY;
  for (std::size_t j = 0; j < g.size(); ++j) {
    if (!target[j]) continue;
    const Xyz q = xyz(g, j);
    const double dx = double(p.x - q.x) * g.spacing[0], dy = double(p.y - q.y) * g.spacing[1],
                 dz = double(p.z - q.z) * g.spacing[2];
    best = std::min(best, dx * dx + dy * dy + dz * dz);
  }
  return best;
}

// Runs f with n worker threads, then restores one.
template <typename F>
auto with_threads(int n, F&& f) {
  set_worker_threads(n);
  auto r = f();
  set_worker_threads(1);
  return r;
}

}  // namespace

TEST(SegbrainFastOps, ComponentsMatchFloodFillForEveryConnectivity) {
  std::mt19937 rng(11);
  for (int conn : {4, 8, 6, 18, 26})
    for (int percent : {15, 35, 55}) {
      Grid g = grid(13, 11, 9);
      Mask m = random_mask(g, rng, percent);
      Components ref = reference_components(g, m, conn);
      Components got = connected_components(g, m, conn);
      EXPECT_EQ(got.label, ref.label) << "conn " << conn << ", " << percent << " %";
      EXPECT_EQ(got.size, ref.size) << "conn " << conn << ", " << percent << " %";
      // The largest component: ties to the lower id (first in raster order).
      Mask big(g.size(), 0);
      if (ref.size.size() > 1) {
        const auto best = std::uint32_t(std::max_element(ref.size.begin() + 1, ref.size.end()) - ref.size.begin());
        for (std::size_t i = 0; i < g.size(); ++i) big[i] = ref.label[i] == best;
      }
      EXPECT_EQ(largest_component(g, m, conn), big) << "conn " << conn;
    }
  // Long runs (whole 8-byte words alike), values other than 1, rows of every remainder.
  for (std::size_t nx : {37u, 40u, 41u}) {
    Grid g = grid(nx, 23, 11);
    Mask m(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      const Xyz p = xyz(g, i);
      const long dx = p.x - 12, dy = p.y - 11, dz = p.z - 5;
      const bool ball = dx * dx + dy * dy + 4 * dz * dz <= 100, slab = p.x > 26 && p.y % 7 != 3;
      m[i] = static_cast<std::uint8_t>((ball || slab) && rng() % 50 != 0 ? 1 + rng() % 3 : 0);
    }
    for (int conn : {6, 26}) {
      Components ref = reference_components(g, m, conn), got = connected_components(g, m, conn);
      EXPECT_EQ(got.label, ref.label) << "nx " << nx << " conn " << conn;
      EXPECT_EQ(got.size, ref.size) << "nx " << nx << " conn " << conn;
    }
    EXPECT_EQ(fill_holes(g, m, false), reference_fill(g, m, false)) << "nx " << nx;
    EXPECT_EQ(fill_holes(g, m, true), reference_fill(g, m, true)) << "nx " << nx;
  }
  Grid g = grid(5, 4, 3);
  EXPECT_EQ(connected_components(g, Mask(g.size(), 0), 26).size.size(), 1u);
  EXPECT_EQ(connected_components(g, Mask(g.size(), 1), 6).size, (std::vector<std::size_t>{0, 60}));
}

TEST(SegbrainFastOps, FillHolesMatchesFloodFill) {
  std::mt19937 rng(12);
  for (int percent : {30, 50, 70}) {
    Grid g = grid(14, 12, 10);
    Mask m = random_mask(g, rng, percent);
    EXPECT_EQ(fill_holes(g, m, false), reference_fill(g, m, false)) << percent << " %";
    EXPECT_EQ(fill_holes(g, m, true), reference_fill(g, m, true)) << percent << " %";
  }
}

TEST(SegbrainFastOps, ErodeDilateDepthMatchBruteForce) {
  std::mt19937 rng(13);
  // Radii below and above the direct-window limit, anisotropic spacing, masks that touch
  // the grid border and masks confined to a corner (the cropped box).
  for (int trial = 0; trial < 4; ++trial) {
    Grid g = grid(12, 10, 9, 0.8 + 0.3 * trial, 1.1, 1.7 - 0.2 * trial);
    Mask m = random_mask(g, rng, 20 + 20 * trial);
    if (trial == 3)
      for (std::size_t i = 0; i < g.size(); ++i) {
        const Xyz p = xyz(g, i);
        m[i] = m[i] && p.x > 3 && p.x < 9 && p.y > 2 && p.y < 7 && p.z > 1 && p.z < 6;
      }
    Mask comp(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) comp[i] = !m[i];
    std::vector<double> to_mask(g.size()), to_comp(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      to_mask[i] = brute_squared_distance(g, m, i);
      to_comp[i] = brute_squared_distance(g, comp, i);
    }
    std::vector<double> dep = depth(g, m);
    for (std::size_t i = 0; i < g.size(); ++i) {
      const double want = m[i] ? (std::isinf(to_comp[i]) ? INFINITY : std::sqrt(to_comp[i])) : 0.0;
      if (std::isinf(want)) EXPECT_TRUE(std::isinf(dep[i]));
      else EXPECT_NEAR(dep[i], want, 1e-9) << "voxel " << i;
    }
    for (double r : {0.0, 0.5, 1.0, 1.9, 3.0, 7.5, 1e9}) {
      Mask er(g.size()), di(g.size());
      for (std::size_t i = 0; i < g.size(); ++i) {
        er[i] = m[i] && to_comp[i] > r * r;
        di[i] = to_mask[i] <= r * r;
      }
      EXPECT_EQ(erode(g, m, r), er) << "trial " << trial << " r " << r;
      EXPECT_EQ(dilate(g, m, r), di) << "trial " << trial << " r " << r;
    }
    EXPECT_EQ(count(erode(g, m, NAN)), 0u);  // as d > NaN and d <= NaN: never
    EXPECT_EQ(count(dilate(g, m, NAN)), 0u);
  }
}

TEST(SegbrainFastOps, GaussianMatchesDirectConvolution) {
  Grid g = grid(11, 9, 7, 1.0, 1.5, 2.0);
  std::mt19937 rng(14);
  Image img(g.size());
  for (auto& v : img) v = float(rng() % 1000) / 10.0f;
  const double sigma = 1.7;
  Image want = img;
  for (int a = 0; a < 3; ++a) {
    const double s = sigma / g.spacing[a];
    const int r = int(std::ceil(3 * s));
    std::vector<double> w;
    double sum = 0;
    for (int k = -r; k <= r; ++k) w.push_back(std::exp(-0.5 * k * k / (s * s))), sum += w.back();
    Image next(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      const Xyz p = xyz(g, i);
      double acc = 0;
      for (int k = -r; k <= r; ++k) {
        long c[3] = {p.x, p.y, p.z};
        c[a] = std::clamp<long>(c[a] + k, 0, long(g.n[a]) - 1);  // replicated border
        acc += w[std::size_t(k + r)] / sum * want[g.index(std::size_t(c[0]), std::size_t(c[1]), std::size_t(c[2]))];
      }
      next[i] = float(acc);
    }
    want = next;
  }
  Image got = gaussian_smooth(g, img, sigma);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-4) << "voxel " << i;
}

TEST(SegbrainFastOps, ResultsDoNotDependOnTheThreadCount) {
  PhantomOptions o;
  o.size = {48, 56, 40};
  o.spacing = {3.0, 2.5, 3.5};
  Phantom p = make_phantom(o);
  const Grid& g = p.grid;
  Mask m = threshold(p.t1, 40, 120);
  auto ops = [&] {
    Components c = connected_components(g, m, 26);
    return std::make_tuple(gaussian_smooth(g, p.t1, 2.0), c.label, c.size, squared_distance(g, m), depth(g, m),
                           erode(g, m, 3.0), dilate(g, m, 12.0), close(g, m, 4.0), fill_holes(g, m, false),
                           fill_holes(g, m, true), largest_component(g, m, 6));
  };
  const auto one = with_threads(1, ops);
  for (int n : {2, 3, 7}) EXPECT_TRUE(with_threads(n, ops) == one) << n << " threads";
}

TEST(SegbrainFastOps, ThresholdMatchesDoubleComparisons) {
  // Bounds that floats cannot hold exactly, infinities, NaN and out-of-range values: the
  // float comparisons must select exactly what lo <= x <= hi in double selects.
  Image img = {0.0f, 0.1f, 0.2f, 1.0f, -1.0f, 1e30f, -1e30f, INFINITY, -INFINITY, NAN,
               std::nextafter(0.1f, 1.0f), std::nextafter(0.1f, 0.0f), 3.4e38f, -3.4e38f};
  const double bounds[] = {0.1, -0.1, 0.2, 1.0, 1e-40, 1e300, -1e300, INFINITY, -INFINITY, NAN, 0.30000000000000004,
                           double(std::nextafter(0.1f, 1.0f)), 3.5e38, -3.5e38};
  for (double lo : bounds)
    for (double hi : bounds) {
      Mask got = threshold(img, lo, hi);
      for (std::size_t i = 0; i < img.size(); ++i)
        EXPECT_EQ(got[i], img[i] >= lo && img[i] <= hi) << "x " << img[i] << " in [" << lo << ", " << hi << "]";
    }
}

TEST(SegbrainFastOps, MaskLogicAndHalfspaces) {
  std::mt19937 rng(15);
  Grid g = grid(9, 7, 5, 1.5, 2.0, 2.5);
  Mask a = random_mask(g, rng, 50), b = random_mask(g, rng, 50);
  a[3] = 7;  // any nonzero value counts as in
  const Mask both = combine(a, b, MaskLogic::both), either = combine(a, b, MaskLogic::either),
             first = combine(a, b, MaskLogic::first_only);
  for (std::size_t i = 0; i < g.size(); ++i) {
    EXPECT_EQ(both[i], a[i] && b[i]);
    EXPECT_EQ(either[i], a[i] || b[i]);
    EXPECT_EQ(first[i], a[i] && !b[i]);
  }
  for (int axis = 0; axis < 3; ++axis)
    for (bool below : {true, false}) {
      Mask h = halfspace(g, axis, below, 4.5);
      for (std::size_t i = 0; i < g.size(); ++i) {
        const Xyz p = xyz(g, i);
        const double v = double(axis == 0 ? p.x : axis == 1 ? p.y : p.z) * g.spacing[std::size_t(axis)];
        EXPECT_EQ(h[i], below ? v < 4.5 : v > 4.5) << "axis " << axis;
      }
    }
}
