#include "brdffit/cluster.hpp"

#include <algorithm>
#include <map>

#include <gtest/gtest.h>

#include "brdffit_test_data.hpp"
#include "core/error.hpp"

using namespace fest::brdffit;

namespace {

// Fraction of lumitexels labelled like the truth under the best matching of labels (the
// clusters are few, so try every permutation).
double labelled_right(const std::vector<std::uint16_t>& got, const std::vector<int>& truth, int k) {
  std::vector<int> perm(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) perm[static_cast<std::size_t>(i)] = i;
  double best = 0;
  do {
    std::size_t right = 0;
    for (std::size_t i = 0; i < got.size(); ++i) right += perm[got[i]] == truth[i];
    best = std::max(best, static_cast<double>(right) / static_cast<double>(got.size()));
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

struct Scene {
  LumitexelSet set;
  std::vector<int> truth;
};

Scene scene(int materials, unsigned seed) {
  const auto mats = brdffit_test::three_materials();
  Scene s;
  s.set = brdffit_test::make_set(1500, 6, seed, 0.01, [&](int i) {
    s.truth.push_back(i % materials);
    return mats[static_cast<std::size_t>(i % materials)];
  });
  return s;
}

}  // namespace

TEST(BrdffitCluster, TwoAndThreeMaterialsFoundWithTheRightAssignment) {
  // docs/brdffit.md §7: >= 98 % of lumitexels labelled right, 6 samples each, 1 % noise.
  for (int k : {2, 3}) {
    const Scene s = scene(k, 20 + static_cast<unsigned>(k));
    ClusterOptions o;
    o.clusters = k;
    o.fit.threads = 2;
    const ClusterResult r = cluster_lumitexels(s.set, local_samples(s.set, 2), o);
    ASSERT_EQ(static_cast<int>(r.clusters.size()), k);
    const double rate = labelled_right(r.assignment, s.truth, k);
    std::printf("%d materials: %.4f labelled right, %zu splits\n", k, rate, r.history.size());
    EXPECT_GE(rate, 0.98);
    EXPECT_EQ(static_cast<int>(r.history.size()), k - 1);
    for (const SplitRecord& h : r.history) EXPECT_LT(h.error_after, h.error_before);
  }
}

TEST(BrdffitCluster, AutoStopsAtTheNumberOfMaterials) {
  const Scene s = scene(3, 31);
  ClusterOptions o;
  o.clusters = 0;
  o.fit.threads = 2;
  const ClusterResult r = cluster_lumitexels(s.set, local_samples(s.set, 2), o);
  for (const SplitRecord& h : r.history) std::printf("split %d: %g -> %g\n", h.split, h.error_before, h.error_after);
  EXPECT_EQ(r.clusters.size(), 3u);
  EXPECT_GE(labelled_right(r.assignment, s.truth, static_cast<int>(r.clusters.size())), 0.98);
}

TEST(BrdffitCluster, SameResultWithOneOrTwoThreads) {
  const Scene s = scene(2, 5);
  ClusterOptions o;
  o.clusters = 2;
  o.fit.threads = 1;
  const ClusterResult a = cluster_lumitexels(s.set, local_samples(s.set, 1), o);
  o.fit.threads = 2;
  const ClusterResult b = cluster_lumitexels(s.set, local_samples(s.set, 2), o);
  EXPECT_EQ(a.assignment, b.assignment);
  ASSERT_EQ(a.clusters.size(), b.clusters.size());
  for (std::size_t j = 0; j < a.clusters.size(); ++j) EXPECT_EQ(a.clusters[j].params, b.clusters[j].params);
}

TEST(BrdffitCluster, NoSamplesAndBadOptionsAreRefused) {
  LumitexelSet empty;
  empty.lumitexels.resize(3);
  ClusterOptions o;
  try {
    cluster_lumitexels(empty, local_samples(empty, 1), o);
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
  }
  const Scene s = scene(2, 1);
  o.split_scale = -1;
  try {
    cluster_lumitexels(s.set, local_samples(s.set, 1), o);
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
  }
}
