// Region division and aggregation of the edge-based find_brain on hand-made slices (and
// the tissue classes of --tissue on a two-Gaussian mixture): a
// "head" square whose border ring is skin, a "brain" square divided by one edge line
// into two brain-like regions, a dark region beside them; two slices, the upper one
// shifted by a voxel so propagation needs the overlap rule.
#include <gtest/gtest.h>

#include <algorithm>

#include <random>

#include "segbrain/classify.hpp"
#include "segbrain/regions.hpp"

using namespace fest::segbrain;

namespace {

struct Scene {
  Grid g;
  Mask head, edges, skin;
  Image img;
};

// 30 x 30 x 3 voxels of 1 mm: head = all but the outer voxel ring; skin = the head's
// outer 2 voxels; in every slice z a brain square x, y in [6 + z, 18 + z] of intensity
// 100 cut by the edge line x = 11 + z, surrounded by an edge ring, and a dark square
// (20) in x, y [24, 26] inside an edge ring too.
Scene scene() {
  Scene s;
  s.g.n = {30, 30, 3};
  const std::size_t n = s.g.size();
  s.head.assign(n, 0);
  s.edges.assign(n, 0);
  s.skin.assign(n, 0);
  s.img.assign(n, 60.0f);
  for (std::size_t z = 0; z < 3; ++z)
    for (std::size_t y = 0; y < 30; ++y)
      for (std::size_t x = 0; x < 30; ++x) {
        const std::size_t i = s.g.index(x, y, z);
        const bool in_head = x >= 1 && x <= 28 && y >= 1 && y <= 28;
        s.head[i] = in_head;
        s.skin[i] = in_head && (x <= 2 || x >= 27 || y <= 2 || y >= 27);
        const std::size_t b0 = 6 + z, b1 = 18 + z;
        const bool brain = x >= b0 && x <= b1 && y >= b0 && y <= b1;
        const bool ring = x + 1 >= b0 && x <= b1 + 1 && y + 1 >= b0 && y <= b1 + 1 && !brain;
        if (brain) s.img[i] = 100;
        if (ring || (brain && x == 11 + z)) s.edges[i] = 1;
        const bool dark = x >= 24 && x <= 26 && y >= 24 && y <= 26;
        if (dark) s.img[i] = 20;
        if (!dark && x >= 23 && x <= 27 && y >= 23 && y <= 27 && !brain && !ring) s.edges[i] = 1;
      }
  return s;
}

}  // namespace

TEST(SegbrainRegions, DivisionTableAndAdjacency) {
  Scene s = scene();
  Regions r = divide_into_regions(s.g, s.edges, s.head, s.img, s.skin, true);
  // Per slice: the outside (skin contact), two brain halves, the dark square.
  ASSERT_EQ(r.table.size(), 1u + 3 * 4);
  const std::uint32_t left = r.label[s.g.index(8, 8, 0)], right = r.label[s.g.index(15, 8, 0)];
  const std::uint32_t outside = r.label[s.g.index(4, 4, 0)], dark = r.label[s.g.index(25, 25, 0)];
  ASSERT_NE(left, right);
  EXPECT_DOUBLE_EQ(r.table[left].mean, 100);
  EXPECT_EQ(r.table[left].voxels, 5u * 13);   // x 6..10, y 6..18
  EXPECT_EQ(r.table[right].voxels, 7u * 13);  // x 12..18
  EXPECT_DOUBLE_EQ(r.table[dark].mean, 20);
  EXPECT_TRUE(r.table[outside].skin_contact);
  EXPECT_FALSE(r.table[left].skin_contact);
  auto adj = [&](std::uint32_t a, std::uint32_t b) {
    return std::find(r.adjacent[a].begin(), r.adjacent[a].end(), b) != r.adjacent[a].end();
  };
  EXPECT_TRUE(adj(left, right));
  EXPECT_TRUE(adj(left, outside));
  EXPECT_TRUE(adj(dark, outside));
  EXPECT_FALSE(adj(left, dark));
}

TEST(SegbrainRegions, StartingRegionAndAggregationAcrossSlices) {
  Scene s = scene();
  Regions r = divide_into_regions(s.g, s.edges, s.head, s.img, s.skin, true);
  // Reference slice at 50 % of the head's S-extent (slices 0..2): slice 1. The larger
  // brain half (right) starts; the outside (skin) and the dark square never join.
  const std::uint32_t start = brain_starting_region(s.g, r, s.head, 80, 120, 0.5);
  ASSERT_NE(start, 0u);
  EXPECT_EQ(r.table[start].slice, 1u);
  EXPECT_EQ(start, r.label[s.g.index(17, 10, 1)]);
  Mask m = aggregate_brain_regions(s.g, r, start, 80, 120, 0.3, 10);
  for (std::size_t z = 0; z < 3; ++z)
    for (std::size_t y = 0; y < 30; ++y)
      for (std::size_t x = 0; x < 30; ++x) {
        const std::size_t b0 = 6 + z, b1 = 18 + z;
        const bool brain = x >= b0 && x <= b1 && y >= b0 && y <= b1;
        // The brain square of every slice including its inner edge line; nothing else.
        EXPECT_EQ(m[s.g.index(x, y, z)], brain ? 1 : 0) << x << "," << y << "," << z;
      }
  // A window that excludes the brain intensity finds no start.
  EXPECT_EQ(brain_starting_region(s.g, r, s.head, 0, 50, 0.5), 0u);
}

// Tissue classes (--tissue): two-class k-means of a two-Gaussian mixture finds the two
// means; nearest-mean labelling splits at their midpoint.
TEST(SegbrainClassify, KMeansOfTwoGaussiansAndNearestClass) {
  std::mt19937 rng(7);
  std::normal_distribution<double> gm(80, 4), wm(110, 4);
  Image img;
  for (int i = 0; i < 20000; ++i) img.push_back(float(i % 3 == 0 ? gm(rng) : wm(rng)));
  Mask all(img.size(), 1);
  auto means = kmeans_1d(img, all, 2);
  ASSERT_EQ(means.size(), 2u);
  EXPECT_NEAR(means[0], 80, 0.5);
  EXPECT_NEAR(means[1], 110, 0.5);
  Mask low = nearest_class(img, all, means, 0);
  for (std::size_t i = 0; i < img.size(); ++i) EXPECT_EQ(low[i] != 0, img[i] < 0.5 * (means[0] + means[1]));
  EXPECT_TRUE(kmeans_1d(img, Mask(img.size(), 0), 2).empty());
  auto three = kmeans_1d(img, all, 3);
  EXPECT_TRUE(three[0] < three[1] && three[1] < three[2]);
}
