#include "brdffit/project.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "brdffit/nnls.hpp"
#include "brdffit_test_data.hpp"

using namespace fest::brdffit;
using fest::reflectance::LafortuneBrdf;

namespace {

// f_L = t f_a + (1 - t) f_b as a single "BRDF" for the generator.
struct Blend {
  LafortuneBrdf a, b;
  double t;
};

LumitexelSet blend_set(const LafortuneBrdf& a, const LafortuneBrdf& b, int count, int per, std::vector<double>& t) {
  // Generate each material separately on the same directions and mix the radiance.
  auto sa = brdffit_test::make_set(count, per, 77, 0.0, [&](int) { return a; });
  auto sb = brdffit_test::make_set(count, per, 77, 0.0, [&](int) { return b; });
  std::mt19937_64 rng(78);
  std::normal_distribution<double> g(0, 0.01);
  for (int i = 0; i < count; ++i) {
    const double ti = static_cast<double>(i) / (count - 1);  // linear "over the surface"
    t.push_back(ti);
    const Lumitexel& l = sa.lumitexels[static_cast<std::size_t>(i)];
    for (std::size_t k = l.first_sample; k < l.first_sample + l.count; ++k)
      for (int c = 0; c < 3; ++c)
        sa.samples[k].r[c] = static_cast<float>((ti * sa.samples[k].r[c] + (1 - ti) * sb.samples[k].r[c]) * (1 + g(rng)));
  }
  return sa;
}

}  // namespace

TEST(BrdffitProject, KnownBlendOfTwoBasisBrdfsIsRecovered) {
  // docs/brdffit.md §7: weights within 0.05 (RMS) of the truth with >= 6 samples.
  const auto mats = brdffit_test::three_materials();
  std::vector<double> t;
  const LumitexelSet set = blend_set(mats[0], mats[1], 400, 8, t);
  const auto local = local_samples(set, 2);
  std::vector<MaterialCluster> clusters(2);
  clusters[0].params = from_brdf(ModelSpec{}, mats[0]);
  clusters[1].params = from_brdf(ModelSpec{}, mats[1]);
  ProjectOptions o;
  o.basis = 2;
  const Projection p = project_lumitexels(set, local, ModelSpec{}, clusters, o);
  ASSERT_EQ(p.basis_size, 2);
  ASSERT_EQ(p.basis.cluster_basis[0], (std::vector<int>{0, 1}));
  ASSERT_EQ(p.basis.cluster_basis[1], (std::vector<int>{1, 0}));
  double sq = 0, sum = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double wa = p.cluster[i] == 0 ? p.weights[2 * i] : p.weights[2 * i + 1];
    const double wb = p.cluster[i] == 0 ? p.weights[2 * i + 1] : p.weights[2 * i];
    sq += (wa - t[i]) * (wa - t[i]) + (wb - (1 - t[i])) * (wb - (1 - t[i]));
    sum += wa + wb;
  }
  const double rms = std::sqrt(sq / (2.0 * static_cast<double>(t.size())));
  std::printf("blend weights RMS error %.4f\n", rms);
  EXPECT_LE(rms, 0.05);
  EXPECT_NEAR(sum / static_cast<double>(t.size()), 1.0, 0.02);
  // Clusters follow the dominant material.
  EXPECT_EQ(p.cluster.front(), 1);
  EXPECT_EQ(p.cluster.back(), 0);
}

TEST(BrdffitProject, RgbWeightsAndNonNegativeWeights) {
  const auto mats = brdffit_test::three_materials();
  std::vector<double> t;
  const LumitexelSet set = blend_set(mats[0], mats[2], 50, 8, t);
  const auto local = local_samples(set, 1);
  std::vector<MaterialCluster> clusters(2);
  clusters[0].params = from_brdf(ModelSpec{}, mats[0]);
  clusters[1].params = from_brdf(ModelSpec{}, mats[2]);
  ProjectOptions o;
  o.basis = 2;
  o.weights = WeightMode::rgb;
  const Projection p = project_lumitexels(set, local, ModelSpec{}, clusters, o);
  ASSERT_EQ(p.values_per_lumitexel(), 6);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double expect = p.cluster[i] == 0 ? t[i] : 1 - t[i];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.weights[6 * i + 2 * static_cast<std::size_t>(c)], expect, 0.1) << i << " " << c;
  }
  o.weights = WeightMode::scalar;
  o.nonneg = true;
  const Projection q = project_lumitexels(set, local, ModelSpec{}, clusters, o);
  for (float w : q.weights) EXPECT_GE(w, 0.0f);
}

TEST(BrdffitProject, ProjectedModelBeatsThePerClusterModel) {
  // docs/brdffit.md §7 (the chapter's Fig. 8.6 vs 8.7): one cluster fitted to a blend, then
  // projection into 4 basis BRDFs: strictly smaller error.
  const auto mats = brdffit_test::three_materials();
  std::vector<double> t;
  const LumitexelSet set = blend_set(mats[1], mats[2], 300, 8, t);
  const auto local = local_samples(set, 2);
  ClusterOptions co;
  co.clusters = 1;
  co.fit.threads = 2;
  const ClusterResult cr = cluster_lumitexels(set, local, co);
  ProjectOptions o;
  o.basis = 4;
  o.split = co;
  const Projection p = project_lumitexels(set, local, cr.model, cr.clusters, o);
  EXPECT_EQ(p.basis.cluster_basis[0].size(), 3u);  // f_C and its two trial children
  const ProjectionError e = projection_error(set, local, p, 2);
  std::printf("projected error %.4g vs per-cluster %.4g\n", e.projected, e.per_cluster);
  EXPECT_LT(e.projected, e.per_cluster);
  EXPECT_NEAR(e.per_cluster, cr.total_error, 1e-6 * cr.total_error);
}

TEST(BrdffitProject, TooFewSamplesGiveThePureClusterBrdf) {
  const auto mats = brdffit_test::three_materials();
  const LumitexelSet set = brdffit_test::make_set(1, 1, 3, 0.0, [&](int) { return mats[0]; });
  const auto local = local_samples(set, 1);
  const ModelEvaluator a(ModelSpec{}, from_brdf(ModelSpec{}, mats[0])), b(ModelSpec{}, from_brdf(ModelSpec{}, mats[1]));
  float w[2] = {-7, -7};
  solve_weights(local.data(), 1, {&a, &b}, ProjectOptions{}, 2, w);
  EXPECT_EQ(w[0], 1.0f);
  EXPECT_EQ(w[1], 0.0f);
}

TEST(BrdffitNnls, MatchesLeastSquaresWhenPositiveAndClampsOtherwise) {
  Eigen::MatrixXd a(4, 2);
  a << 1, 0, 0, 1, 1, 1, 2, 1;
  const Eigen::Vector2d x_true(0.5, 2.0);
  const Eigen::VectorXd x = nnls(a, a * x_true);
  EXPECT_NEAR((x - x_true).norm(), 0, 1e-12);
  // b = a (1, -1): the unconstrained solution is negative in x2; the constrained optimum
  // has x2 = 0 and x1 = (a1 . b) / |a1|^2.
  const Eigen::VectorXd b = a * Eigen::Vector2d(1, -1);
  const Eigen::VectorXd y = nnls(a, b);
  EXPECT_EQ(y[1], 0.0);
  EXPECT_NEAR(y[0], a.col(0).dot(b) / a.col(0).squaredNorm(), 1e-12);
}
