#include "facefit/fit.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <unordered_set>

#include "core/parallel_for.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "facefit/ridge.hpp"

namespace fest::facefit {

namespace {

Eigen::Vector3d mean_point(const Model& model, std::uint32_t j) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int e = 0; e < model.dims; ++e) x(e) = model.mean[static_cast<std::size_t>(model.dims) * j + e];
  return x;
}

// 3-D positions of the landmark vertices of v̄ + S diag(σ) c (only their rows of S).
Eigen::Matrix3Xd landmark_points(const Model& model, const Landmarks& lm, const Eigen::VectorXd& c) {
  Eigen::Matrix3Xd X(3, static_cast<Eigen::Index>(lm.size()));
  for (std::size_t a = 0; a < lm.size(); ++a) {
    const std::uint32_t j = lm.vertex[a];
    Eigen::Vector3d x = mean_point(model, j);
    for (int e = 0; e < model.dims; ++e) {
      const std::size_t row = static_cast<std::size_t>(model.dims) * j + e;
      double s = 0;
      for (Eigen::Index i = 0; i < c.size(); ++i) s += model.basis_at(row, static_cast<std::size_t>(i)) * model.sigma[static_cast<std::size_t>(i)] * c(i);
      x(e) += s;
    }
    X.col(static_cast<Eigen::Index>(a)) = x;
  }
  return X;
}

double camera_scale(const CameraMatrix& P) {
  return (P.block<1, 3>(0, 0).norm() + P.block<1, 3>(1, 0).norm()) / 2;
}

struct Solve {
  Eigen::VectorXd c, t;
  double eta_px = 0, E_r = 0, dof = 0;
  Eigen::VectorXd w;
  Eigen::MatrixXd V;
  Eigen::VectorXd residual;  // Qc + Tt − r (weighted rows)
  double ms_build = 0, ms_svd = 0;
};

Solve solve_once(const Model& model, const Landmarks& lm, const CameraMatrix& P, const Eigen::VectorXd& weight,
                 bool with_nuisance, const FitOptions& opt) {
  Solve s;
  auto t0 = SteadyClock::now();
  Eigen::MatrixXd Q;
  Eigen::VectorXd r;
  build_measurement(model, lm, P, weight, Q, r);
  const Eigen::Index f = static_cast<Eigen::Index>(lm.size());
  const Eigen::Index k = Q.cols();
  Eigen::MatrixXd T;
  if (with_nuisance) {
    // Translation in u, in v, and the scale column L v̄ (eq. 49-50; L s_tz = 0 is dropped
    // because the camera has no depth row).
    T.setZero(2 * f, 3);
    for (Eigen::Index a = 0; a < f; ++a) {
      const Eigen::Vector2d pm = P.leftCols<3>() * mean_point(model, lm.vertex[static_cast<std::size_t>(a)]);
      for (int d = 0; d < 2; ++d) {
        T(2 * a + d, d) = weight(a);
        T(2 * a + d, 2) = weight(a) * pm(d);
      }
    }
  }
  const bool penalized = with_nuisance && opt.nuisance == NuisanceKind::penalized;
  Eigen::VectorXd column_scale;
  if (penalized) {
    // Paper-literal variant: the nuisance vectors join the basis with prior std S.
    column_scale = T.colwise().norm().transpose();
    Eigen::MatrixXd Qa(Q.rows(), k + 3);
    Qa.leftCols(k) = Q;
    for (int j = 0; j < 3; ++j) {
      column_scale(j) = column_scale(j) > 0 ? opt.nuisance_sigma / column_scale(j) : 0.0;
      Qa.col(k + j) = T.col(j) * column_scale(j);
    }
    Q = Qa;
  }
  s.ms_build = ms_since(t0);
  t0 = SteadyClock::now();
  const RidgeSolver solver(Q, r, with_nuisance && !penalized ? T : Eigen::MatrixXd(), opt.eps_rank);
  const double scale = camera_scale(P);
  switch (opt.eta_mode) {
    case EtaMode::given: s.eta_px = opt.eta_in_model_units ? opt.eta * scale * scale : opt.eta; break;
    case EtaMode::gcv: s.eta_px = solver.eta_by_gcv(); break;
    case EtaMode::evidence: s.eta_px = solver.eta_by_evidence(); break;
  }
  const Eigen::VectorXd call = solver.coefficients(s.eta_px);
  s.c = call.head(k);
  s.residual = Q * call - r;
  if (with_nuisance && !penalized) {
    s.t = solver.nuisance(call);
    s.residual += T * s.t;
  } else if (penalized) {
    s.t = call.tail(3).cwiseProduct(column_scale);
  }
  s.E_r = s.residual.norm();
  s.dof = solver.effective_dof(s.eta_px);
  s.w = solver.singular_values();
  s.V = solver.V().topRows(k);
  s.ms_svd = ms_since(t0);
  return s;
}

}  // namespace

// Q₀, T₀ and the solver of the unit similarity camera for one set of landmark vertices
// and weights (FitCache in fit.hpp says why this is worth keeping).
struct FitCache::SimilarityPlan {
  const void* basis = nullptr;
  std::size_t components = 0;
  double eps_rank = 0;
  std::vector<std::uint32_t> vertex;
  Eigen::VectorXd weight;
  Eigen::MatrixXd Q0, T0;
  std::optional<RidgeSolver> solver;
  double ms_build = 0;

  bool matches(const Model& model, const Landmarks& lm, const Eigen::VectorXd& w, double eps) const {
    return basis == model.basis && components == model.components && eps_rank == eps && vertex == lm.vertex &&
           weight.size() == w.size() && weight == w;
  }
};

FitCache::FitCache() = default;
FitCache::~FitCache() = default;

namespace {

std::unique_ptr<FitCache::SimilarityPlan> similarity_plan(const Model& model, const Landmarks& lm, const Eigen::VectorXd& weight,
                                                          double eps_rank) {
  const auto t0 = SteadyClock::now();
  auto plan = std::make_unique<FitCache::SimilarityPlan>();
  plan->basis = model.basis;
  plan->components = model.components;
  plan->eps_rank = eps_rank;
  plan->vertex = lm.vertex;
  plan->weight = weight;
  const Eigen::Index f = static_cast<Eigen::Index>(lm.size());
  CameraMatrix unit = CameraMatrix::Zero();
  unit(0, 0) = 1;
  unit(1, 1) = -1;
  Eigen::VectorXd ignored;
  build_measurement(model, lm, unit, weight, plan->Q0, ignored);
  plan->T0 = Eigen::MatrixXd::Zero(2 * f, 3);
  for (Eigen::Index a = 0; a < f; ++a) {
    const Eigen::Vector3d vm = mean_point(model, lm.vertex[static_cast<std::size_t>(a)]);
    plan->T0(2 * a, 0) = weight(a);
    plan->T0(2 * a + 1, 1) = weight(a);
    plan->T0(2 * a, 2) = weight(a) * vm.x();
    plan->T0(2 * a + 1, 2) = -weight(a) * vm.y();
  }
  plan->ms_build = ms_since(t0);
  plan->solver.emplace(plan->Q0, Eigen::VectorXd::Zero(2 * f), plan->T0, eps_rank);
  return plan;
}

// The default camera (similarity, free nuisance) in one SVD. For P = s·[[1,0,0],[0,−1,0]]
// + t, Q = s·Q₀ and the nuisance columns span the same space for every s, so
// min ‖sQ₀c + Tt − r‖² + η‖c‖² is min ‖Q₀c + T₀t₀ − r/s‖² + (η/s²)‖c‖²: the refinement
// passes only change r/s, and the solver keeps its SVD.
Solve solve_similarity(const Model& model, const Landmarks& lm, const Eigen::VectorXd& weight, const FitOptions& opt,
                       CameraMatrix& P, int passes, int& iterations, FitCache* cache) {
  const auto t1 = SteadyClock::now();
  const Eigen::Index f = static_cast<Eigen::Index>(lm.size());
  std::unique_ptr<FitCache::SimilarityPlan> local;
  FitCache::SimilarityPlan* plan = nullptr;
  const bool reuse = cache && cache->similarity && cache->similarity->matches(model, lm, weight, opt.eps_rank);
  if (reuse) {
    plan = cache->similarity.get();
  } else {
    local = similarity_plan(model, lm, weight, opt.eps_rank);
    plan = local.get();
    if (cache) cache->similarity = std::move(local);
  }
  const Eigen::MatrixXd& Q0 = plan->Q0;
  const Eigen::MatrixXd& T0 = plan->T0;
  RidgeSolver& solver = *plan->solver;
  const double ms_build = reuse ? 0.0 : plan->ms_build;  // a reused plan cost nothing this time
  Solve s;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.components));
  P = fit_similarity(landmark_points(model, lm, zero), lm.uv, weight);
  for (int pass = 0; pass <= passes; ++pass) {
    const double scale = P(0, 0);
    if (!(std::abs(scale) > 0)) throw runtime_failure("all singular values of Q are zero: the landmarks see no model variation");
    Eigen::VectorXd r(2 * f);
    for (Eigen::Index a = 0; a < f; ++a) {
      const Eigen::Vector3d vm = mean_point(model, lm.vertex[static_cast<std::size_t>(a)]);
      for (int d = 0; d < 2; ++d) r(2 * a + d) = weight(a) * (lm.uv(d, a) - P.row(d).head<3>().dot(vm) - P(d, 3));
    }
    solver.set_measurement(r / scale);
    const double s2 = scale * scale;
    switch (opt.eta_mode) {
      case EtaMode::given: s.eta_px = opt.eta_in_model_units ? opt.eta * s2 : opt.eta; break;
      case EtaMode::gcv: s.eta_px = solver.eta_by_gcv() * s2; break;
      case EtaMode::evidence: s.eta_px = solver.eta_by_evidence() * s2; break;
    }
    s.c = solver.coefficients(s.eta_px / s2);
    const Eigen::VectorXd t = solver.nuisance(s.c);
    s.t = Eigen::Vector3d(scale * t(0), scale * t(1), t(2));
    s.residual = scale * (Q0 * s.c + T0 * t) - r;
    iterations = pass + 1;
    if (pass < passes) P = fit_similarity(landmark_points(model, lm, s.c), lm.uv, weight);
  }
  const double scale = P(0, 0);
  s.E_r = s.residual.norm();
  s.dof = solver.effective_dof(s.eta_px / (scale * scale));
  s.w = solver.singular_values() * std::abs(scale);
  s.V = solver.V().topRows(static_cast<Eigen::Index>(model.components));
  s.ms_build = ms_build;
  s.ms_svd = std::max(0.0, ms_since(t1) - ms_build);
  return s;
}

}  // namespace

void check_landmarks(const Model& model, const Landmarks& lm) {
  if (static_cast<Eigen::Index>(lm.size()) != lm.uv.cols()) throw bad_input("landmarks: {} vertices but {} positions", lm.size(), lm.uv.cols());
  if (lm.size() < 3) throw bad_input("only {} mapped landmark(s); at least 3 are needed", lm.size());
  std::unordered_set<std::uint32_t> seen;
  for (std::size_t a = 0; a < lm.size(); ++a) {
    const std::string name = a < lm.id.size() ? lm.id[a] : std::to_string(a + 1);
    if (lm.vertex[a] >= model.points) throw bad_input("landmark '{}': vertex {} is out of range (the model has {} vertices)", name, lm.vertex[a], model.points);
    if (!seen.insert(lm.vertex[a]).second) throw bad_input("landmark '{}': vertex {} is given twice", name, lm.vertex[a]);
    if (!std::isfinite(lm.uv(0, static_cast<Eigen::Index>(a))) || !std::isfinite(lm.uv(1, static_cast<Eigen::Index>(a))))
      throw bad_input("landmark '{}': coordinate is not a finite number", name);
    if (lm.sigma.size() > 0 && !(lm.sigma(static_cast<Eigen::Index>(a)) > 0 && std::isfinite(lm.sigma(static_cast<Eigen::Index>(a)))))
      throw bad_input("landmark '{}': sigma must be a positive number", name);
  }
}

void build_measurement(const Model& model, const Landmarks& lm, const CameraMatrix& P, const Eigen::VectorXd& weight,
                       Eigen::MatrixXd& Q, Eigen::VectorXd& r) {
  const auto f = static_cast<Eigen::Index>(lm.size());
  const auto k = static_cast<Eigen::Index>(model.components);
  Q.setZero(2 * f, k);
  r.resize(2 * f);
  for (Eigen::Index a = 0; a < f; ++a) {
    const std::uint32_t j = lm.vertex[static_cast<std::size_t>(a)];
    const double wa = weight.size() ? weight(a) : 1.0;
    const Eigen::Vector3d vm = mean_point(model, j);
    for (int d = 0; d < 2; ++d) {
      r(2 * a + d) = wa * (lm.uv(d, a) - P.row(d).head<3>().dot(vm) - P(d, 3));
      for (Eigen::Index i = 0; i < k; ++i) {
        double s = 0;
        for (int e = 0; e < model.dims; ++e)
          s += P(d, e) * model.basis_at(static_cast<std::size_t>(model.dims) * j + e, static_cast<std::size_t>(i));
        Q(2 * a + d, i) = wa * model.sigma[static_cast<std::size_t>(i)] * s;
      }
    }
  }
}

FitResult fit_landmarks(const Model& model, const Landmarks& lm, const FitOptions& opt, FitCache* cache) {
  check_landmarks(model, lm);
  const auto f = static_cast<Eigen::Index>(lm.size());
  Eigen::VectorXd weight = Eigen::VectorXd::Ones(f);
  if (lm.sigma.size() == f) weight = lm.sigma.cwiseInverse() * opt.sigma_ref;

  FitResult out;
  Solve s;
  CameraMatrix P;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.components));
  switch (opt.camera) {
    case CameraKind::fixed:
      P = opt.fixed_camera;
      s = solve_once(model, lm, P, weight, false, opt);
      out.iterations = 1;
      break;
    case CameraKind::similarity: {
      const bool nuisance = opt.nuisance != NuisanceKind::none;
      if (opt.nuisance == NuisanceKind::free) {
        s = solve_similarity(model, lm, weight, opt, P, opt.similarity_passes, out.iterations, cache);
      } else {
        P = fit_similarity(landmark_points(model, lm, zero), lm.uv, weight);
      }
      for (int pass = 0; opt.nuisance != NuisanceKind::free && pass <= opt.similarity_passes; ++pass) {
        s = solve_once(model, lm, P, weight, nuisance, opt);
        out.iterations = pass + 1;
        if (pass < opt.similarity_passes) P = fit_similarity(landmark_points(model, lm, s.c), lm.uv, weight);
      }
      if (nuisance && s.t.size() == 3) {
        // Fold the nuisance parameters into the reported camera: the scale column was
        // L v̄, so it scales the projection; the translation adds.
        P.leftCols<3>() *= 1 + s.t(2);
        P(0, 3) += s.t(0);
        P(1, 3) += s.t(1);
      }
      break;
    }
    case CameraKind::affine: {
      Eigen::Matrix3Xd X = landmark_points(model, lm, zero);
      double previous = -1;
      for (int it = 0; it < std::max(1, opt.iterations); ++it) {
        P = fit_scaled_orthographic(X, lm.uv, weight);
        s = solve_once(model, lm, P, weight, false, opt);
        out.iterations = it + 1;
        X = landmark_points(model, lm, s.c);
        if (previous >= 0 && std::abs(s.E_r - previous) <= 1e-6 * std::max(previous, 1e-300)) break;
        previous = s.E_r;
      }
      break;
    }
  }
  out.c = s.c;
  out.camera = P;
  out.eta_px = s.eta_px;
  out.eta_source = opt.eta_mode == EtaMode::given ? "given" : opt.eta_mode == EtaMode::gcv ? "gcv" : "evidence";
  out.residuals.resize(2, f);
  for (Eigen::Index a = 0; a < f; ++a)
    for (int d = 0; d < 2; ++d) out.residuals(d, a) = s.residual(2 * a + d) / weight(a);
  out.E_r = s.E_r;
  out.E_r_rms = s.E_r / std::sqrt(static_cast<double>(f));
  out.norm_c = s.c.norm();
  out.effective_dof = s.dof;
  out.singular_values = s.w;
  out.V = s.V;
  out.nuisance = s.t;
  out.ms_build_q = s.ms_build;
  out.ms_svd = s.ms_svd;
  const auto t0 = SteadyClock::now();
  if (opt.reconstruct) {
    out.shape = reconstruct(model, out.c);
    if (!out.shape.allFinite()) throw runtime_failure("the fit produced non-finite coordinates");
  } else if (!out.c.allFinite()) {
    throw runtime_failure("the fit produced non-finite coefficients");
  }
  out.ms_reconstruct = ms_since(t0);
  return out;
}

Eigen::VectorXd fit_full_shape(const Model& model, const Eigen::VectorXd& shape, double eta, Eigen::VectorXd* coeffs) {
  if (static_cast<std::size_t>(shape.size()) != model.n())
    throw bad_input("the shape has {} vertices, the model {}", shape.size() / model.dims, model.points);
  if (!shape.allFinite()) throw bad_input("the shape has non-finite coordinates");
  // c_i = ⟨s_i, r⟩/σ_i shrunk by 1/(1 + η/σ_i²) (eq. 46 in standardised coefficients).
  Eigen::VectorXd c = coefficients_of(model, shape);
  for (Eigen::Index i = 0; i < c.size(); ++i) {
    const double s2 = model.sigma[static_cast<std::size_t>(i)] * model.sigma[static_cast<std::size_t>(i)];
    c(i) /= 1 + eta / s2;
  }
  if (coeffs) *coeffs = c;
  return reconstruct(model, c);
}

std::vector<double> vertex_uncertainty(const Model& model, const FitResult& fit, int threads) {
  // Σ_c = I − V D V^T with D = diag(w²/(w²+η)), so trace(B_j Σ_c B_j^T) = ‖B_j‖² − ‖B_j V D^½‖².
  const auto k = static_cast<Eigen::Index>(model.components);
  const Eigen::Index r = fit.V.cols();
  Eigen::MatrixXd M(k, r);  // diag(σ) V D^½
  for (Eigen::Index i = 0; i < r; ++i) {
    const double w = fit.singular_values(i);
    const double d = w > 0 ? std::sqrt(w * w / (w * w + fit.eta_px)) : 0.0;
    for (Eigen::Index row = 0; row < k; ++row) M(row, i) = model.sigma[static_cast<std::size_t>(row)] * fit.V(row, i) * d;
  }
  const std::size_t p = model.points;
  const int dims = model.dims;
  const auto n = static_cast<Eigen::Index>(model.n());
  std::vector<double> out(p);
  const Eigen::MatrixXd basis_d = model.basis_type == Dtype::f64 ? basis_matrix(model) : Eigen::MatrixXd();
  auto work = [&](std::size_t begin, std::size_t end) {
    const auto rows = static_cast<Eigen::Index>((end - begin) * static_cast<std::size_t>(dims));
    const auto row0 = static_cast<Eigen::Index>(begin * static_cast<std::size_t>(dims));
    Eigen::MatrixXd B(rows, k);  // S diag(σ) rows of this chunk
    if (model.basis_type == Dtype::f32) {
      Eigen::Map<const Eigen::MatrixXf> S(static_cast<const float*>(model.basis), n, k);
      B = S.middleRows(row0, rows).cast<double>();
    } else {
      B = basis_d.middleRows(row0, rows);
    }
    const Eigen::MatrixXd BV = B * M;
    for (Eigen::Index i = 0; i < k; ++i) B.col(i) *= model.sigma[static_cast<std::size_t>(i)];
    for (std::size_t j = begin; j < end; ++j) {
      const auto rr = static_cast<Eigen::Index>((j - begin) * static_cast<std::size_t>(dims));
      const double v = B.middleRows(rr, dims).squaredNorm() - BV.middleRows(rr, dims).squaredNorm();
      out[j] = std::sqrt(std::max(0.0, v));
    }
  };
  const std::size_t chunk = 4096;
  const std::size_t chunks = (p + chunk - 1) / chunk;
  parallel_for(chunks, threads, [&](std::size_t c) { work(c * chunk, std::min(p, (c + 1) * chunk)); });
  return out;
}

}  // namespace fest::facefit
