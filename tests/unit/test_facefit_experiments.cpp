// The chapter's experiments (docs/facefit.md §5, figs. 1.3-1.5 analogues) on the synthetic face
// population G2: a 99-component model from 100 training faces, 20 novel test faces,
// feature sets of 17, 50 and "1000" random vertices (736 at this test's 32×32 grid).
// Every expectation is a property the mathematics predicts, not a recorded number.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "facefit/evaluate.hpp"
#include "facefit/fit.hpp"
#include "facefit/pca_build.hpp"
#include "facefit/synth.hpp"

using namespace fest::facefit;

namespace {

struct Population {
  Model model;
  std::vector<Eigen::VectorXd> train, test;
  SynthLandmarks sets;
  std::vector<std::uint32_t> set17, set50, set1000;
  double mean_deviation = 0;  // E_full of the mean face against the training faces
};

std::vector<std::uint32_t> vertices_of(const std::vector<NamedVertex>& s) {
  std::vector<std::uint32_t> v;
  for (const auto& nv : s) v.push_back(nv.vertex);
  return v;
}

const Population& population() {
  static const Population p = [] {
    Population q;
    const int R = 32;
    Rng rng(1);
    for (int i = 0; i < 120; ++i) (i < 100 ? q.train : q.test).push_back(face_shape(draw_face(rng, 1.0), R));
    Eigen::MatrixXd X(q.train[0].size(), 100);
    for (int i = 0; i < 100; ++i) X.col(i) = q.train[static_cast<std::size_t>(i)];
    q.model = build_model(X, 3, {});
    q.sets = synth_landmarks(R, 1);
    q.model.eval_mask = q.sets.eval_mask;
    q.set17 = vertices_of(q.sets.set17);
    q.set50 = vertices_of(q.sets.set50);
    q.set1000 = vertices_of(q.sets.set1000);
    const Eigen::VectorXd mean = Eigen::Map<const Eigen::VectorXd>(q.model.mean.data(), static_cast<Eigen::Index>(q.model.mean.size()));
    for (int i = 0; i < 20; ++i) q.mean_deviation += mean_error(vertex_errors(mean, q.train[static_cast<std::size_t>(i)], 3), q.sets.eval_mask) / 20;
    return q;
  }();
  return p;
}

std::vector<Eigen::VectorXd> first(const std::vector<Eigen::VectorXd>& v, std::size_t n) {
  return {v.begin(), v.begin() + static_cast<std::ptrdiff_t>(std::min(n, v.size()))};
}

// Mean over faces of each column, per η (rows come face-major, then η).
std::vector<double> mean_curve(const std::vector<SweepRow>& rows, std::size_t etas, double SweepRow::*field) {
  std::vector<double> m(etas, 0.0);
  for (std::size_t i = 0; i < rows.size(); ++i) m[i % etas] += rows[i].*field / static_cast<double>(rows.size() / etas);
  return m;
}

std::size_t argmin(const std::vector<double>& v) { return static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin()); }

const std::vector<double> kGrid = {0, 1e-4, 1e-3, 1e-2, 0.1, 0.3, 1, 2, 3, 10, 100, 1000};

}  // namespace

TEST(FacefitExperiments, ModelHas99Components) {
  const auto& p = population();
  EXPECT_EQ(p.model.components, 99u);
  EXPECT_EQ(p.set17.size(), 17u);
  EXPECT_EQ(p.set50.size(), 50u);
}

TEST(FacefitExperiments, TrainingFacesAtEtaZeroAreRecovered) {
  // T4: a training face lies in the span; with 2f = 100 ≥ 99 measurements the solution
  // is unique, so it is recovered up to float32 rounding of the basis.
  const auto& p = population();
  const auto rows = sweep(p.model, first(p.train, 20), p.set50, {0.0}, {{99, 0, 0}}, p.model.eval_mask, 1);
  for (const auto& r : rows) {
    EXPECT_LT(r.E_full, 1e-3 * p.mean_deviation) << "face " << r.face;
    EXPECT_LT(r.E_r, 1e-3) << "face " << r.face;
  }
  // f = 17: 34 < 99 measurements, non-unique; the minimum-norm answer is shorter than
  // the true coefficients (mean ‖c‖ of training faces is √99) and misses detail.
  const auto rows17 = sweep(p.model, first(p.train, 20), p.set17, {0.0}, {{99, 0, 0}}, p.model.eval_mask, 1);
  double norm_c = 0, e_full = 0;
  for (const auto& r : rows17) {
    norm_c += r.norm_c / 20;
    e_full += r.E_full / 20;
  }
  EXPECT_LT(norm_c, std::sqrt(99.0));
  EXPECT_GT(e_full, 0.05 * p.mean_deviation);
}

TEST(FacefitExperiments, NovelFacesGiveAUShapedCurve) {
  // T2: for faces outside the span, η = 0 over-fits (tiny E_r, distorted face) and large
  // η returns the mean; the best η lies strictly inside the grid. E_r grows and ‖c‖
  // shrinks with η for every face (ridge regression).
  const auto& p = population();
  const auto rows = sweep(p.model, p.test, p.set50, kGrid, {{99, 0, 0}}, p.model.eval_mask, 1);
  const auto e_full = mean_curve(rows, kGrid.size(), &SweepRow::E_full);
  const std::size_t best = argmin(e_full);
  EXPECT_GT(best, 1u);
  EXPECT_LT(best, kGrid.size() - 2);
  EXPECT_LT(e_full[best], 0.8 * e_full[0]);
  EXPECT_LT(e_full[best], 0.8 * e_full.back());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i % kGrid.size() == 0) continue;
    EXPECT_GE(rows[i].E_r, rows[i - 1].E_r * (1 - 1e-9));
    EXPECT_LE(rows[i].norm_c, rows[i - 1].norm_c * (1 + 1e-9));
  }
}

TEST(FacefitExperiments, MorePointsAndMoreComponentsGiveLowerError) {
  // T3: at each configuration's best η, E_full(17) > E_full(50) > E_full(1000), and the
  // full model is at least as good as the first 40 components where the measurement
  // determines the coefficients (f = 50, 1000).
  const auto& p = population();
  auto best = [&](const std::vector<std::uint32_t>& set, std::size_t k) {
    const auto rows = sweep(p.model, p.test, set, kGrid, {{k, 0, 0}}, p.model.eval_mask, 1);
    const auto curve = mean_curve(rows, kGrid.size(), &SweepRow::E_full);
    return *std::min_element(curve.begin(), curve.end());
  };
  const double e17 = best(p.set17, 99), e50 = best(p.set50, 99), e1000 = best(p.set1000, 99);
  EXPECT_GT(e17, e50);
  EXPECT_GT(e50, e1000);
  EXPECT_LE(e50, best(p.set50, 40));
  EXPECT_LE(e1000, best(p.set1000, 40));
}

TEST(FacefitExperiments, NoiseMovesTheOptimumToTheNoiseVariance) {
  // T5: training faces, f = 50, Gaussian noise σ_N per coordinate: the MAP estimate with
  // η = σ_N² is the Bayes-optimal trade-off, so the grid optimum is within a factor 3.
  const auto& p = population();
  const std::vector<double> grid = {1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1, 3, 10, 30};
  for (double sigma : {0.1, 1.0}) {
    const auto rows = sweep(p.model, first(p.train, 30), p.set50, grid, {{99, sigma, 0}}, p.model.eval_mask, 5);
    const double eta_best = grid[argmin(mean_curve(rows, grid.size(), &SweepRow::E_full))];
    EXPECT_NEAR(std::log(eta_best / (sigma * sigma)), 0.0, std::log(3.0) + 1e-9) << "sigma " << sigma;
  }
}

TEST(FacefitExperiments, EvidenceFindsTheNoiseVariance) {
  // --eta auto=evidence on the same problem: within a factor 3 of σ_N² on ≥ 90 % of faces.
  const auto& p = population();
  Rng rng(77);
  for (double sigma : {0.1, 1.0}) {
    int hits = 0;
    const int faces = 30;
    for (int i = 0; i < faces; ++i) {
      const Eigen::VectorXd& face = p.train[static_cast<std::size_t>(i)];
      FitOptions o;
      o.camera = CameraKind::fixed;
      o.eta_mode = EtaMode::evidence;
      Landmarks lm;
      lm.vertex = p.set50;
      lm.uv.resize(2, 50);
      for (Eigen::Index a = 0; a < 50; ++a) {
        const Eigen::Vector3d x = face.segment<3>(3 * p.set50[static_cast<std::size_t>(a)]);
        lm.uv.col(a) = o.fixed_camera.leftCols<3>() * x + o.fixed_camera.col(3) + sigma * Eigen::Vector2d(rng.normal(), rng.normal());
      }
      const double eta = fit_landmarks(p.model, lm, o).eta_px;
      if (std::abs(std::log(eta / (sigma * sigma))) <= std::log(3.0)) ++hits;
    }
    EXPECT_GE(hits, 27) << "sigma " << sigma;
  }
}

TEST(FacefitExperiments, WrongCameraIsHelpedByRegularisation) {
  // T6: data from the frontal view, solver's L rotated by 4°: η = 0 fits the wrong
  // projection exactly; a suitable η > 0 reduces E_full by at least 30 %.
  const auto& p = population();
  const auto rows = sweep(p.model, first(p.train, 20), p.set50, kGrid, {{99, 0, 4.0}}, p.model.eval_mask, 1);
  const auto curve = mean_curve(rows, kGrid.size(), &SweepRow::E_full);
  EXPECT_LE(*std::min_element(curve.begin(), curve.end()), 0.7 * curve[0]);
}
