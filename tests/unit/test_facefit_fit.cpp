// Fitting through cameras (docs/facefit.md §3): exact recovery with
// a known camera, similarity invariance, affine pose recovery, posterior uncertainty,
// landmark checks.

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "facefit/fit.hpp"
#include "facefit/landmark_set.hpp"
#include "facefit_fixtures.hpp"

using namespace facefit_test;

namespace {

Landmarks project(const Eigen::VectorXd& face, const std::vector<std::uint32_t>& vertices, const CameraMatrix& P) {
  Landmarks lm;
  lm.vertex = vertices;
  lm.uv.resize(2, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t a = 0; a < vertices.size(); ++a)
    lm.uv.col(static_cast<Eigen::Index>(a)) = P.leftCols<3>() * face.segment<3>(3 * vertices[a]) + P.col(3);
  return lm;
}

std::vector<std::uint32_t> every_nth_vertex(std::uint32_t step, std::uint32_t count) {
  std::vector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < count; ++i) v.push_back(i * step % 400);
  return v;
}

}  // namespace

TEST(FacefitFit, KnownCameraRecoversModelFacesExactly) {
  // T4 analogue on G1: the face lies in the span, l = 40 ≥ k = 30, η = 0 → exact.
  const Model m = g1_model();
  Rng rng(10);
  const Eigen::VectorXd c = random_coefficients(rng, 30);
  const Eigen::VectorXd face = reconstruct(m, c);
  FitOptions o;
  o.camera = CameraKind::fixed;
  o.eta = 0;
  const FitResult r = fit_landmarks(m, project(face, every_nth_vertex(19, 20), o.fixed_camera), o);
  EXPECT_LT((r.c - c).norm(), 1e-8 * c.norm());
  EXPECT_LT((r.shape - face).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(r.E_r, 1e-8);
}

TEST(FacefitFit, SimilarityCameraIsInvariantToImageTranslationAndScale) {
  const Model m = g1_model();
  Rng rng(11);
  const Eigen::VectorXd face = reconstruct(m, random_coefficients(rng, 30));
  const auto base = project(face, every_nth_vertex(7, 25), orthographic_camera(1.0, {150, 150}));
  FitOptions o;  // similarity camera, η = 2 mm²
  const FitResult ref = fit_landmarks(m, base, o);
  for (double alpha : {0.5, 2.0}) {
    Landmarks moved = base;
    for (Eigen::Index a = 0; a < moved.uv.cols(); ++a)
      moved.uv.col(a) = alpha * (base.uv.col(a) - Eigen::Vector2d(150, 150)) + Eigen::Vector2d(150 + 13.5, 150 - 7.25);
    const FitResult r = fit_landmarks(m, moved, o);
    EXPECT_LT((r.shape - ref.shape).cwiseAbs().maxCoeff(), 1e-4) << alpha;
    EXPECT_NEAR(r.E_r, alpha * ref.E_r, 1e-6 * alpha * ref.E_r + 1e-9) << alpha;
  }
}

TEST(FacefitFit, AffineCameraRecoversPose) {
  // Test plan item 10 on G1: yaw 30°, pitch 10°, s = 2.3 px/mm.
  const Model m = g1_model();
  Rng rng(12);
  const Eigen::VectorXd face = reconstruct(m, random_coefficients(rng, 30));
  const auto vertices = every_nth_vertex(13, 60);
  const CameraMatrix P = orthographic_camera(2.3, {200, 180}, 30, 10);
  FitOptions o;
  o.camera = CameraKind::affine;
  o.eta = 0.01;
  o.iterations = 20;
  const FitResult r = fit_landmarks(m, project(face, vertices, P), o);
  const CameraPose pose = decompose_camera(r.camera);
  EXPECT_NEAR(pose.yaw_deg, 30, 0.5);
  EXPECT_NEAR(pose.pitch_deg, 10, 0.5);
  EXPECT_NEAR(pose.scale / 2.3, 1, 0.005);
  FitOptions frontal;
  frontal.camera = CameraKind::fixed;
  frontal.eta = 0.01;
  const FitResult rf = fit_landmarks(m, project(face, vertices, frontal.fixed_camera), frontal);
  const double e_affine = (r.shape - face).norm(), e_frontal = (rf.shape - face).norm();
  EXPECT_LE(e_affine, 1.1 * e_frontal + 1e-3);
}

TEST(FacefitFit, UncertaintyMatchesTheExplicitPosteriorCovariance) {
  const Model m = g1_model();
  Rng rng(13);
  const Eigen::VectorXd face = reconstruct(m, random_coefficients(rng, 30));
  FitOptions o;
  o.camera = CameraKind::fixed;
  o.eta = 3.0;
  o.eta_in_model_units = false;
  const FitResult r = fit_landmarks(m, project(face, every_nth_vertex(17, 10), o.fixed_camera), o);  // l = 20 < k
  const auto sigma = vertex_uncertainty(m, r, 2);
  // Σ_c = (Q^TQ/η + I)^−1 in standardised coefficients, built independently.
  Eigen::MatrixXd Q;
  Eigen::VectorXd rr;
  build_measurement(m, project(face, every_nth_vertex(17, 10), o.fixed_camera), o.fixed_camera, Eigen::VectorXd(), Q, rr);
  const Eigen::MatrixXd cov = (Q.transpose() * Q / 3.0 + Eigen::MatrixXd::Identity(30, 30)).inverse();
  const Eigen::MatrixXd S = basis_matrix(m);
  Eigen::MatrixXd B = S;
  for (Eigen::Index i = 0; i < 30; ++i) B.col(i) *= m.sigma[static_cast<std::size_t>(i)];
  for (std::uint32_t j : {0u, 17u, 123u, 399u}) {
    const Eigen::MatrixXd Bj = B.middleRows(3 * j, 3);
    EXPECT_NEAR(sigma[j], std::sqrt((Bj * cov * Bj.transpose()).trace()), 1e-9 * sigma[j]) << j;
  }
}

TEST(FacefitFit, BadLandmarksAreRejected) {
  const Model m = g1_model();
  FitOptions o;
  Landmarks two;
  two.vertex = {1, 2};
  two.uv = Eigen::Matrix2Xd::Constant(2, 2, 150);
  EXPECT_THROW(fit_landmarks(m, two, o), fest::Error);
  Landmarks out_of_range;
  out_of_range.vertex = {1, 2, 400};
  out_of_range.uv = Eigen::Matrix2Xd::Random(2, 3);
  EXPECT_THROW(fit_landmarks(m, out_of_range, o), fest::Error);
  Landmarks nan = out_of_range;
  nan.vertex = {1, 2, 3};
  nan.uv(1, 2) = std::nan("");
  EXPECT_THROW(fit_landmarks(m, nan, o), fest::Error);
  // All landmarks on one image point: nothing to fit, a run-time failure (exit 1).
  Landmarks same;
  same.vertex = {1, 50, 99, 250, 300};
  same.uv = Eigen::Matrix2Xd::Constant(2, 5, 150);
  try {
    o.camera = CameraKind::affine;
    fit_landmarks(m, same, o);
    ADD_FAILURE() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::failure);
  }
}

TEST(FacefitFit, UnknownLandmarkIdsAreReportedOrSkipped) {
  LandmarkMap map{{"nose", 5}, {"chin", 9}};
  std::vector<LandmarkEntry> entries(3);
  entries[0].id = "nose";
  entries[1].id = "chin";
  entries[2].id = "ear";
  entries[2].line = 4;
  EXPECT_THROW(resolve_landmarks(entries, map, false, nullptr, "lm.tsv"), fest::Error);
  std::size_t skipped = 0;
  const Landmarks lm = resolve_landmarks(entries, map, true, &skipped, "lm.tsv");
  EXPECT_EQ(skipped, 1u);
  ASSERT_EQ(lm.size(), 2u);
  EXPECT_EQ(lm.vertex[1], 9u);
}

TEST(FacefitFit, FreeNuisanceIsTheLimitOfAVeryWidePrior) {
  // The one-SVD similarity path (free translation and scale) against the paper-literal
  // variant that appends the nuisance vectors to the basis with prior std S: as S grows
  // the penalty on them vanishes and both minimise the same objective.
  const Model m = g1_model();
  Rng rng(14);
  const Eigen::VectorXd face = reconstruct(m, random_coefficients(rng, 30));
  Landmarks lm = project(face, every_nth_vertex(7, 25), orthographic_camera(1.7, {160, 140}));
  for (Eigen::Index a = 0; a < lm.uv.cols(); ++a) lm.uv.col(a) += 0.3 * Eigen::Vector2d(rng.normal(), rng.normal());
  FitOptions free_opt;
  FitOptions wide = free_opt;
  wide.nuisance = NuisanceKind::penalized;
  wide.nuisance_sigma = 1e6;
  const FitResult a = fit_landmarks(m, lm, free_opt), b = fit_landmarks(m, lm, wide);
  EXPECT_LT((a.shape - b.shape).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_NEAR(a.E_r, b.E_r, 1e-6 * a.E_r);
  EXPECT_NEAR(decompose_camera(a.camera).scale, decompose_camera(b.camera).scale, 1e-6);
}

TEST(FacefitFit, CachedSimilarityPlanGivesTheSameFits) {
  // A batch reuses Q₀, T₀ and the SVD while the landmark vertices and weights stay the
  // same; the result must not depend on what was fitted before (bit for bit: the same
  // arithmetic on the same matrices), and a new vertex set or weights must rebuild it.
  const Model m = g1_model();
  Rng rng(21);
  FitCache cache;
  const FitOptions o;
  std::vector<Landmarks> runs;
  for (int i = 0; i < 3; ++i) {
    const Eigen::VectorXd face = reconstruct(m, random_coefficients(rng, 30));
    runs.push_back(project(face, every_nth_vertex(7, 25), orthographic_camera(1.2 + 0.3 * i, {150.0 + 5 * i, 140})));
  }
  runs.push_back(project(reconstruct(m, random_coefficients(rng, 30)), every_nth_vertex(11, 30), orthographic_camera(1.5, {150, 150})));
  runs.push_back(runs[0]);
  runs.back().sigma = Eigen::VectorXd::LinSpaced(25, 0.5, 2.0);
  for (const Landmarks& lm : runs) {
    const FitResult cached = fit_landmarks(m, lm, o, &cache), fresh = fit_landmarks(m, lm, o);
    EXPECT_EQ(cached.c, fresh.c);
    EXPECT_EQ(cached.shape, fresh.shape);
    EXPECT_EQ(cached.camera, fresh.camera);
    EXPECT_EQ(cached.singular_values, fresh.singular_values);
  }
}

TEST(FacefitFit, Float32ReconstructionIsTheRoundedDoubleOne) {
  const Model m = g1_model();
  Rng rng(22);
  const Eigen::VectorXd c = random_coefficients(rng, 30);
  std::vector<float> out(m.n());
  reconstruct_f32(m, c, out.data());
  const Eigen::VectorXf expected = reconstruct(m, c).cast<float>();
  EXPECT_EQ(Eigen::Map<const Eigen::VectorXf>(out.data(), static_cast<Eigen::Index>(out.size())), expected);
}
