// Location and shape operators (lib/segbrain/shape): centroids and boxes of known shapes,
// half-spaces, components selected by distance, geodesic growth that respects its domain,
// mirror Dice and the midsagittal plane of a mirror-symmetric image.
#include <gtest/gtest.h>

#include <cmath>

#include "segbrain/lateral_extent.hpp"
#include "segbrain/morphology.hpp"
#include "segbrain/shape.hpp"

#include "test_segbrain_helpers.hpp"

using namespace fest::segbrain;

namespace {

using fest::segbrain::test_support::grid;

// Box of voxels [x0, x1] x [y0, y1] x [z0, z1] (inclusive).
Mask box(const Grid& g, std::size_t x0, std::size_t x1, std::size_t y0, std::size_t y1, std::size_t z0, std::size_t z1) {
  Mask m(g.size());
  for (std::size_t z = z0; z <= z1; ++z)
    for (std::size_t y = y0; y <= y1; ++y)
      for (std::size_t x = x0; x <= x1; ++x) m[g.index(x, y, z)] = 1;
  return m;
}

}  // namespace

TEST(SegbrainShape, CentroidAndBoxOfABoxInMillimetres) {
  Grid g = grid(20, 20, 10, 1, 2, 3);
  Mask m = box(g, 2, 5, 4, 9, 1, 3);
  Point c = centroid_mm(g, m);
  EXPECT_DOUBLE_EQ(c[0], 3.5 * 1);
  EXPECT_DOUBLE_EQ(c[1], 6.5 * 2);
  EXPECT_DOUBLE_EQ(c[2], 2.0 * 3);
  auto b = bbox_mm(g, m);
  EXPECT_DOUBLE_EQ(b[0], 2);
  EXPECT_DOUBLE_EQ(b[1], 5);
  EXPECT_DOUBLE_EQ(b[2], 8);
  EXPECT_DOUBLE_EQ(b[3], 18);
  EXPECT_DOUBLE_EQ(b[4], 3);
  EXPECT_DOUBLE_EQ(b[5], 9);
  EXPECT_TRUE(std::isnan(centroid_mm(g, Mask(g.size()))[0]));
}

TEST(SegbrainShape, HalfspacesSplitTheGrid) {
  Grid g = grid(6, 7, 8, 1, 1, 2);
  Mask below = halfspace(g, 2, true, 7.0);   // z * 2 < 7: z = 0..3
  Mask above = halfspace(g, 2, false, 7.0);  // z = 4..7
  EXPECT_EQ(count(below), 6u * 7 * 4);
  EXPECT_EQ(count(above), 6u * 7 * 4);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NE(below[i], above[i]);
}

TEST(SegbrainShape, ComponentsNearKeepsCloseLargeParts) {
  Grid g = grid(40, 10, 10);
  Mask m = box(g, 1, 4, 1, 4, 1, 4);                    // 64 voxels, centre x 2.5
  Mask far = box(g, 30, 33, 1, 4, 1, 4);                // 64 voxels, centre x 31.5
  Mask tiny = box(g, 8, 8, 2, 2, 2, 2);                 // 1 voxel, centre x 8
  for (std::size_t i = 0; i < m.size(); ++i) m[i] |= far[i] | tiny[i];
  Mask kept = components_near(g, m, 6, 0.01, {3, 2.5, 2.5}, 10);  // 0.01 ml = 10 voxels
  EXPECT_EQ(count(kept), 64u);
  EXPECT_TRUE(kept[g.index(2, 2, 2)]);
  EXPECT_FALSE(kept[g.index(8, 2, 2)]);
  EXPECT_FALSE(kept[g.index(31, 2, 2)]);
}

TEST(SegbrainShape, ComponentsSizedKeepsTheVolumeRange) {
  Grid g = grid(40, 10, 10, 1, 1, 1);
  Mask m = box(g, 1, 4, 1, 4, 1, 4);                    // 64 voxels = 0.064 ml
  Mask big = box(g, 10, 19, 1, 8, 1, 8);                // 640 voxels
  Mask tiny = box(g, 30, 30, 2, 2, 2, 2);               // 1 voxel
  for (std::size_t i = 0; i < m.size(); ++i) m[i] |= big[i] | tiny[i];
  EXPECT_EQ(count(components_sized(g, m, 6, 0.01, 0.1)), 64u);
  EXPECT_EQ(count(components_sized(g, m, 26, 0.0005, 1.0)), 64u + 640u + 1u);
  EXPECT_EQ(count(components_sized(g, m, 6, 1.0, 2.0)), 0u);
}

TEST(SegbrainShape, SymmetricPairPicksTheMirroredComponents) {
  Grid g = grid(60, 20, 20);
  // Mirror plane x = 30: boxes centred at x 12 and 48 (same y, z) form the pair; a box at
  // x 40 shifted in y does not mirror the one at x 12 as well, nor one at x 20 (too close).
  Mask m = box(g, 10, 14, 4, 8, 4, 8);
  for (auto b : {box(g, 46, 50, 4, 8, 4, 8), box(g, 38, 42, 12, 16, 4, 8), box(g, 18, 22, 12, 16, 12, 16)})
    for (std::size_t i = 0; i < m.size(); ++i) m[i] |= b[i];
  double score = 0;
  Mask pair = symmetric_pair(g, m, 6, 30, 30, 40, score);
  EXPECT_EQ(count(pair), 2u * 125);
  EXPECT_TRUE(pair[g.index(12, 6, 6)]);
  EXPECT_TRUE(pair[g.index(48, 6, 6)]);
  EXPECT_NEAR(score, 0, 1e-9);
  // No pair at a left-right distance of 50-60 mm.
  EXPECT_EQ(count(symmetric_pair(g, m, 6, 30, 50, 60, score)), 0u);
  EXPECT_TRUE(std::isinf(score));
}

TEST(SegbrainShape, GeodesicDilationFollowsItsDomain) {
  // A U-shaped corridor: straight-line distance from the seed to the far arm is small,
  // the path inside the corridor long.
  Grid g = grid(30, 30, 1);
  Mask within = box(g, 0, 2, 0, 29, 0, 0);
  Mask right = box(g, 6, 8, 0, 29, 0, 0);
  Mask bottom = box(g, 0, 8, 27, 29, 0, 0);
  for (std::size_t i = 0; i < within.size(); ++i) within[i] |= right[i] | bottom[i];
  Mask seed(g.size());
  seed[g.index(1, 0, 0)] = 1;
  Mask grown = geodesic_dilate(g, seed, within, 10.0);
  EXPECT_TRUE(grown[g.index(1, 10, 0)]);    // 10 mm straight down the left arm
  EXPECT_FALSE(grown[g.index(1, 12, 0)]);
  EXPECT_FALSE(grown[g.index(7, 0, 0)]);    // 6 mm away, but not through the corridor
  for (std::size_t i = 0; i < grown.size(); ++i) {
    if (grown[i]) {
      EXPECT_TRUE(within[i] || seed[i]);
    }
  }
  // A radius longer than the corridor reaches the other arm's end.
  EXPECT_TRUE(geodesic_dilate(g, seed, within, 80.0)[g.index(7, 0, 0)]);
}

TEST(SegbrainShape, MirrorDiceAndMidsagittalPlane) {
  Grid g = grid(41, 20, 10, 1.5, 1, 1);
  // Two boxes mirror-symmetric about x = 21 (31.5 mm): x 10..14 and 28..32.
  Mask pair = box(g, 10, 14, 5, 14, 2, 7);
  Mask other = box(g, 28, 32, 5, 14, 2, 7);
  for (std::size_t i = 0; i < pair.size(); ++i) pair[i] |= other[i];
  EXPECT_DOUBLE_EQ(mirror_dice(g, pair, 21 * 1.5), 1.0);
  EXPECT_LT(mirror_dice(g, pair, 18 * 1.5), 0.5);
  EXPECT_DOUBLE_EQ(mirror_dice(g, box(g, 10, 14, 5, 14, 2, 7), 21 * 1.5), 0.0);
  // An image whose intensities are symmetric about x = 23 (34.5 mm), inside a mask
  // centred elsewhere: the plane search finds 34.5 mm, not the mask's centroid.
  Image img(g.size());
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        const double d = std::abs(double(x) - 23.0);
        img[g.index(x, y, z)] = static_cast<float>(std::cos(0.7 * d) * 50 + 10 * std::sin(0.9 * double(y)) + 100);
      }
  Mask all = box(g, 8, 40, 0, 19, 0, 9);  // centroid x 24 -> 36 mm
  EXPECT_NEAR(midsagittal_r_mm(g, img, all, 15), 23 * 1.5, 0.75 + 1e-9);
}

// docs/segbrain.md §5, "The brainstem": a row's side ends where it leaves the tissue; a
// side that runs to the limit is the chord between the bounded rows above and below. A
// column on the plane R = 20 mm; tissue is bounded 6 mm out at the lowest section and 10 mm
// out at the highest, unbounded in between (limit 12 mm): the last tissue voxel lies
// 6 - sx and 10 - sx mm out, and the open sections in between get the linear
// interpolation, e(z) = (6 - sx) + 0.4 z. The smoothing median of a linear profile is the
// profile itself away from the ends; the same in mm at half the voxel size.
TEST(SegbrainShape, LateralExtentEndsAtTheBoundaryAndBridgesBetween) {
  for (double sx : {1.0, 0.5}) {
    const std::size_t nx = static_cast<std::size_t>(40 / sx) + 1, plane = static_cast<std::size_t>(20 / sx);
    Grid g = grid(nx, 5, 11, sx, 1, 1);
    Mask cand(g.size()), within(g.size(), 1);
    for (std::size_t z = 0; z < 11; ++z)
      for (std::size_t y = 0; y < 5; ++y) cand[g.index(plane, y, z)] = 1;
    for (std::size_t y = 0; y < 5; ++y) {
      const std::size_t low = static_cast<std::size_t>(6 / sx), high = static_cast<std::size_t>(10 / sx);
      within[g.index(plane - low, y, 0)] = within[g.index(plane + low, y, 0)] = 0;
      within[g.index(plane - high, y, 10)] = within[g.index(plane + high, y, 10)] = 0;
    }
    LateralExtentStats st;
    Mask out = lateral_extent(g, cand, within, 20.0, 12.0, &st);
    EXPECT_EQ(st.sides, 110u);
    EXPECT_EQ(st.open_sides, 90u);  // sections 1..9, both sides, 5 rows each
    for (std::size_t z = 2; z <= 8; ++z)
      for (std::size_t y = 0; y < 5; ++y) {
        const double end = (6 - sx) + 0.4 * double(z);
        std::size_t n = 0;
        for (std::size_t x = 0; x < nx; ++x) n += out[g.index(x, y, z)];
        EXPECT_EQ(n, 2 * static_cast<std::size_t>(std::floor(end / sx + 1e-9)) + 1) << "sx " << sx << " z " << z;
        EXPECT_TRUE(out[g.index(plane, y, z)]);
      }
    // The closed sections themselves: the voxels up to the boundary, not past it (the
    // window of the lowest section reaches two open sections above it, hence the median
    // of 6 - sx, 6.4 - sx, 6.8 - sx: 6.4 - sx).
    std::size_t n0 = 0;
    for (std::size_t x = 0; x < nx; ++x) n0 += out[g.index(x, 2, 0)];
    EXPECT_EQ(n0, 2 * static_cast<std::size_t>(std::floor((6.4 - sx) / sx + 1e-9)) + 1) << "sx " << sx;
  }
}

// Rows without a candidate voxel stay empty; a section whose rows all run to the limit
// and have no bounded row above, below or beside them takes the limit itself.
TEST(SegbrainShape, LateralExtentKeepsEmptyRowsAndFallsBackToTheLimit) {
  Grid g = grid(31, 3, 3);
  Mask cand(g.size()), within(g.size(), 1);
  cand[g.index(15, 1, 1)] = 1;
  LateralExtentStats st;
  Mask out = lateral_extent(g, cand, within, 15.0, 4.0, &st);
  EXPECT_EQ(st.sides, 2u);
  EXPECT_EQ(st.open_sides, 2u);
  EXPECT_EQ(count(out), 9u);  // 15 - 4 .. 15 + 4 in the one row
  for (std::size_t x = 11; x <= 19; ++x) EXPECT_TRUE(out[g.index(x, 1, 1)]);
}
