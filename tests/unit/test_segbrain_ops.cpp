// Operators against analytic cases (docs/segbrain.md §3): exact distance transform (a point, and
// brute force on random anisotropic grids), morphology laws, hole filling, components
// for 6/18/26 connectivity, Otsu on a two-class mixture, Gaussian moments, region growing,
// reorientation round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "segbrain/canonical.hpp"
#include "segbrain/filters.hpp"
#include "segbrain/measures.hpp"
#include "segbrain/morphology.hpp"
#include "segbrain/phantom.hpp"

#include "test_segbrain_helpers.hpp"

using namespace fest::segbrain;

namespace {

using fest::segbrain::test_support::grid;

Mask ball(const Grid& g, double cx, double cy, double cz, double r) {
  Mask m(g.size());
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        double dx = (x - cx) * g.spacing[0], dy = (y - cy) * g.spacing[1], dz = (z - cz) * g.spacing[2];
        m[g.index(x, y, z)] = dx * dx + dy * dy + dz * dz <= r * r;
      }
  return m;
}

}  // namespace

TEST(SegbrainOps, DistanceTransformOfAPointIsEuclidean) {
  Grid g = grid(17, 13, 11, 1.0, 0.7, 2.5);
  Mask m(g.size(), 0);
  m[g.index(5, 6, 4)] = 1;
  auto d = squared_distance(g, m);
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        double dx = (double(x) - 5) * 1.0, dy = (double(y) - 6) * 0.7, dz = (double(z) - 4) * 2.5;
        EXPECT_NEAR(d[g.index(x, y, z)], dx * dx + dy * dy + dz * dz, 1e-9);
      }
  auto none = squared_distance(g, Mask(g.size(), 0));
  EXPECT_TRUE(std::isinf(none[0]));
}

TEST(SegbrainOps, DistanceTransformMatchesBruteForce) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 5; ++trial) {
    Grid g = grid(9, 8, 7, 0.5 + trial * 0.3, 1.2, 0.9);
    Mask m(g.size());
    for (auto& v : m) v = rng() % 17 == 0;
    auto d = squared_distance(g, m);
    for (std::size_t i = 0; i < g.size(); ++i) {
      double best = INFINITY;
      for (std::size_t j = 0; j < g.size(); ++j) {
        if (!m[j]) continue;
        double dx = (double(i % 9) - double(j % 9)) * g.spacing[0];
        double dy = (double((i / 9) % 8) - double((j / 9) % 8)) * g.spacing[1];
        double dz = (double(i / 72) - double(j / 72)) * g.spacing[2];
        best = std::min(best, dx * dx + dy * dy + dz * dz);
      }
      if (std::isinf(best)) EXPECT_TRUE(std::isinf(d[i]));
      else EXPECT_NEAR(d[i], best, 1e-9);
    }
  }
}

TEST(SegbrainOps, MorphologyLaws) {
  Grid g = grid(30, 30, 30);
  std::mt19937 rng(5);
  Mask m = ball(g, 14, 15, 15, 9);
  for (int k = 0; k < 60; ++k) m[rng() % g.size()] ^= 1;  // salt and pepper
  Mask o = open(g, m, 2), c = close(g, m, 2);
  for (std::size_t i = 0; i < g.size(); ++i) {
    EXPECT_LE(o[i], m[i]);
    EXPECT_LE(m[i], c[i]);
  }
  EXPECT_EQ(open(g, o, 2), o);   // idempotent
  EXPECT_EQ(close(g, c, 2), c);
  Mask not_m(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) not_m[i] = !m[i];
  Mask o_not = open(g, not_m, 2);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_EQ(c[i], !o_not[i]);  // duality
  // Erosion of a ball of radius 9 by 3 is the ball of radius 6.
  Mask b = ball(g, 15, 15, 15, 9), e = erode(g, b, 3), b6 = ball(g, 15, 15, 15, 6);
  EXPECT_LE(std::abs(long(count(e)) - long(count(b6))), long(count(b6) / 20));
}

TEST(SegbrainOps, FillHolesOfAHollowBall) {
  Grid g = grid(25, 25, 25);
  Mask solid = ball(g, 12, 12, 12, 9), inner = ball(g, 12, 12, 12, 6), shell(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) shell[i] = solid[i] && !inner[i];
  EXPECT_EQ(fill_holes(g, shell, false), solid);
  EXPECT_EQ(fill_holes(g, shell, true), solid);  // every axial section is a closed ring or a disc
  // A tube open at both ends along z is filled slice by slice but not as a volume.
  Mask tube(g.size());
  for (std::size_t z = 0; z < 25; ++z)
    for (std::size_t y = 0; y < 25; ++y)
      for (std::size_t x = 0; x < 25; ++x) {
        double r = std::hypot(double(x) - 12, double(y) - 12);
        tube[g.index(x, y, z)] = r >= 5 && r <= 7;
      }
  EXPECT_EQ(fill_holes(g, tube, false), tube);
  EXPECT_GT(count(fill_holes(g, tube, true)), count(tube));
}

TEST(SegbrainOps, ComponentCountsByConnectivity) {
  Grid g = grid(5, 5, 5);
  Mask m(g.size(), 0);
  m[g.index(1, 1, 1)] = 1;
  m[g.index(2, 2, 1)] = 1;  // edge neighbour of the first (18- and 26-connected)
  m[g.index(3, 3, 2)] = 1;  // corner neighbour of the second (26-connected only)
  m[g.index(0, 4, 4)] = 1;  // isolated
  EXPECT_EQ(connected_components(g, m, 6).size.size() - 1, 4u);
  EXPECT_EQ(connected_components(g, m, 18).size.size() - 1, 3u);
  EXPECT_EQ(connected_components(g, m, 26).size.size() - 1, 2u);
  EXPECT_EQ(count(largest_component(g, m, 26)), 3u);
  EXPECT_EQ(connected_components(g, m, 8).size.size() - 1, 3u);  // per slice: the first two share z = 1
}

TEST(SegbrainOps, OtsuSplitsTwoGaussians) {
  // Equal weights and spreads: by symmetry the optimum is the midpoint of the means,
  // both for overlapping classes and for separated ones (the middle of the gap).
  std::mt19937 rng(11);
  std::normal_distribution<double> a(40, 5), b(120, 5);
  {
    std::normal_distribution<double> wa(40, 20), wb(120, 20);
    Image wide;
    for (int i = 0; i < 200000; ++i) wide.push_back(float(i % 2 ? wa(rng) : wb(rng)));
    EXPECT_NEAR(otsu_threshold(wide, {}), 80, 0.01 * 80);
  }
  Image img;
  for (int i = 0; i < 20000; ++i) img.push_back(float(i % 2 ? a(rng) : b(rng)));
  double t = otsu_threshold(img, {});
  float top_low = 0, bottom_high = 1e9;
  for (std::size_t i = 0; i < img.size(); ++i) {
    if (i % 2) top_low = std::max(top_low, img[i]);
    else bottom_high = std::min(bottom_high, img[i]);
  }
  EXPECT_GT(t, top_low);  // any threshold in the empty gap is optimal
  EXPECT_LT(t, bottom_high);
  EXPECT_NEAR(percentile(img, {}, 25), 40, 2);  // the median of the lower class
}

TEST(SegbrainOps, GaussianKeepsMeanAndHasTheRightVariance) {
  Grid g = grid(41, 41, 41, 1, 1, 2);
  Image img(g.size(), 0);
  img[g.index(20, 20, 20)] = 1;
  Image s = gaussian_smooth(g, img, 2.0);
  double sum = 0, var_x = 0, var_z = 0;
  for (std::size_t z = 0; z < 41; ++z)
    for (std::size_t y = 0; y < 41; ++y)
      for (std::size_t x = 0; x < 41; ++x) {
        double v = s[g.index(x, y, z)];
        sum += v;
        var_x += v * (double(x) - 20) * (double(x) - 20);
        var_z += v * (double(z) - 20) * 2 * (double(z) - 20) * 2;
      }
  EXPECT_NEAR(sum, 1.0, 1e-5);
  EXPECT_NEAR(var_x, 4.0, 0.05);   // sigma 2 mm squared
  EXPECT_NEAR(var_z, 4.0, 0.3);    // coarser sampling along z
}

TEST(SegbrainOps, RegionGrowStaysInItsWindow) {
  Grid g = grid(10, 10, 10);
  Image img(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) img[i] = (i % 10) < 5 ? 100.0f : 10.0f;  // two halves in x
  Mask seed(g.size(), 0);
  seed[g.index(1, 1, 1)] = 1;
  Mask r = region_grow(g, img, seed, 50, 150, 6, {});
  EXPECT_EQ(count(r), 500u);
}

TEST(SegbrainOps, MeasuresOnSimpleShapes) {
  Grid g = grid(40, 40, 40, 2, 2, 2);
  Mask head = ball(g, 20, 20, 20, 36), inner = ball(g, 20, 20, 20, 20);
  EXPECT_EQ(skin_contact_fraction(g, inner, head, 3.0), 0.0);
  EXPECT_EQ(skin_contact_fraction(g, head, head, 100.0), 1.0);
  // Two concentric discs have the same compactness: ratio 1.
  EXPECT_NEAR(contour_length_ratio(g, ball(g, 20, 20, 20, 30), head), 1.0, 0.15);
  auto [change, dice_min] = slice_consistency(g, Mask(g.size(), 1));
  EXPECT_EQ(change, 0.0);
  EXPECT_EQ(dice_min, 1.0);
  EXPECT_EQ(dice(head, head), 1.0);
}

TEST(SegbrainOps, ReorientationRoundTrip) {
  fest::Volume v;
  v.resize(4, 3, 2);
  for (std::size_t i = 0; i < v.size(); ++i) v.voxels[i] = double(i);
  // Voxel axes: x -> Left, y -> Superior, z -> Anterior ("LSA", the ITK head's order).
  v.direction = {-1, 0, 0, 0, 0, 1, 0, 1, 0};
  Reorientation r = find_reorientation(v);
  EXPECT_EQ(r.code, "LSA");
  Grid g = canonical_grid(v, r);
  EXPECT_EQ(g.n[0], 4u);
  EXPECT_EQ(g.n[1], 2u);
  EXPECT_EQ(g.n[2], 3u);
  Image c = to_canonical(v, r);
  // Canonical (R index 0, A 0, S 0) is the source voxel at x = 3 (leftmost flipped), z = 0, y = 0.
  EXPECT_EQ(c[0], float(v.index(3, 0, 0)));
  std::vector<double> back = from_canonical(std::vector<double>(c.begin(), c.end()), v, r);
  EXPECT_EQ(back, v.voxels);
}

TEST(SegbrainOps, PhantomIsDeterministicAndLabelled) {
  PhantomOptions o;
  o.size = {40, 48, 40};
  o.spacing = {4, 4, 4};
  Phantom a = make_phantom(o), b = make_phantom(o);
  EXPECT_EQ(a.t1, b.t1);
  std::size_t brain = 0, eye = 0;
  for (auto l : a.truth) {
    brain += l == 3;
    eye += l == 10;
  }
  // Brain ellipsoid 58 x 76 x 56 mm semi-axes: about 1.03 l.
  EXPECT_NEAR(brain * 64 / 1000.0, 4.0 / 3 * M_PI * 58 * 76 * 56 / 1000, 120);
  EXPECT_GT(eye, 0u);
}

// fill_holes across coronal and sagittal sections (docs/segbrain.md §1, brain-only
// volumes): a tube open at both ends along one axis is filled only in the sections
// across that axis, on a grid whose three sizes differ (so a swapped axis shows).
TEST(SegbrainOps, FillHolesAcrossEachSectionAxis) {
  Grid g = grid(21, 23, 25);
  for (int axis = 0; axis < 3; ++axis) {
    Mask tube(g.size()), filled(g.size());
    for (std::size_t z = 0; z < g.n[2]; ++z)
      for (std::size_t y = 0; y < g.n[1]; ++y)
        for (std::size_t x = 0; x < g.n[0]; ++x) {
          const double p[3] = {double(x) - 10, double(y) - 11, double(z) - 12};
          // The two coordinates across the tube's axis.
          const double u = p[(axis + 1) % 3], v = p[(axis + 2) % 3];
          const double r = std::hypot(u, v);
          tube[g.index(x, y, z)] = r >= 5 && r <= 7;
          filled[g.index(x, y, z)] = r <= 7;
        }
    for (int sec = 0; sec < 3; ++sec) {
      const Mask out = fill_holes_sections(g, tube, sec);
      if (sec == axis) EXPECT_EQ(out, filled) << "tube along axis " << axis << ", sections across " << sec;
      else EXPECT_EQ(out, tube) << "tube along axis " << axis << ", sections across " << sec;
    }
  }
}
