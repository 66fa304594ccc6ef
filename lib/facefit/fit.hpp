#pragma once
// Fitting the model to 2-D feature points (docs/facefit.md §3): build Q = L S diag(σ) from the
// rows of S at the feature vertices, subtract the projected mean (r = r_obs − L v̄),
// solve the regularised problem (ridge.hpp), add v̄ back (eq. 42). Cameras: fixed
// (known L, the paper's experiments), similarity (translation + scale adapted, eq. 49),
// affine (unknown pose, alternating camera and shape; an extension, not in the chapter).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "facefit/camera.hpp"
#include "facefit/model.hpp"

namespace fest::facefit {

struct Landmarks {
  std::vector<std::uint32_t> vertex;   // model vertex of each feature point
  Eigen::Matrix2Xd uv;                 // image position (px), one column per point
  Eigen::VectorXd sigma;               // per-point reliability (px); empty = all equal
  std::vector<std::string> id;         // names for the report (may be empty)
  std::size_t size() const { return vertex.size(); }
};

enum class CameraKind { fixed, similarity, affine };
enum class NuisanceKind { free, penalized, none };
enum class EtaMode { given, gcv, evidence };

struct FitOptions {
  CameraKind camera = CameraKind::similarity;
  CameraMatrix fixed_camera = orthographic_camera(1.0, Eigen::Vector2d(150, 150));  // for CameraKind::fixed
  EtaMode eta_mode = EtaMode::given;
  double eta = 2.0;            // value for EtaMode::given
  bool eta_in_model_units = true;  // η given in mm² (scaled by s² to px²) rather than px²
  NuisanceKind nuisance = NuisanceKind::free;
  double nuisance_sigma = 100;  // penalized nuisance: prior std of each nuisance column
  double sigma_ref = 1.0;       // px; rows are whitened by sigma_ref / sigma_a
  int iterations = 5;           // affine camera: alternations
  int similarity_passes = 2;    // similarity camera: refinement passes after the first solve
  double eps_rank = 1e-10;
  bool reconstruct = true;      // false: coefficients only (batch runs that write no mesh)
};

struct FitResult {
  Eigen::VectorXd c;           // standardised coefficients
  Eigen::VectorXd shape;       // v = v̄ + S diag(σ) c, n values
  CameraMatrix camera;         // the camera of the final solve
  double eta_px = 0;           // η used, px²
  std::string eta_source;      // "given", "gcv", "evidence"
  double E_r = 0;              // ‖Qc + Tt − r‖ (px; unweighted rows when all σ_a equal)
  double E_r_rms = 0;          // E_r / √f
  double norm_c = 0;
  double effective_dof = 0;
  Eigen::VectorXd singular_values;
  Eigen::MatrixXd V;           // right singular vectors (k × min(l,k)) for the uncertainty
  Eigen::VectorXd nuisance;    // (t_u, t_v, s) of the last solve when nuisance columns were used
  Eigen::Matrix2Xd residuals;  // fitted − observed image positions, per landmark (px)
  int iterations = 0;
  double ms_build_q = 0, ms_svd = 0, ms_reconstruct = 0;
};

// Q (2f×k) and r (2f) for camera P: rows 2a+d; r = r_obs − P [v̄_j; 1]. Each landmark's two
// rows are multiplied by weight(a) (empty = 1).
void build_measurement(const Model& model, const Landmarks& lm, const CameraMatrix& P, const Eigen::VectorXd& weight,
                       Eigen::MatrixXd& Q, Eigen::VectorXd& r);

// What a run of fits can share. For the similarity camera with free nuisance (the
// default), Q₀, T₀ and the SVD of P⊥Q₀ depend only on the landmark vertices and their
// weights, not on the image positions; a batch over one landmark map therefore needs one
// SVD, and each further fit costs O(l·k). The cache keeps the last such plan and is
// rebuilt when the vertices, weights, model or eps_rank change. Not thread-safe.
class FitCache {
 public:
  FitCache();
  ~FitCache();
  FitCache(const FitCache&) = delete;
  FitCache& operator=(const FitCache&) = delete;
  struct SimilarityPlan;
  std::unique_ptr<SimilarityPlan> similarity;
};

FitResult fit_landmarks(const Model& model, const Landmarks& lm, const FitOptions& options, FitCache* cache = nullptr);

// The L = id special case (eq. 44-46): shrink a complete shape towards the model,
// x = Σ ⟨s_i, r⟩ s_i / (1 + η/σ_i²); η = 0 projects orthogonally into the span.
Eigen::VectorXd fit_full_shape(const Model& model, const Eigen::VectorXd& shape, double eta, Eigen::VectorXd* coeffs = nullptr);

// Posterior per-vertex standard deviation (model units): σ_j = √trace(B_j Σ_c B_j^T),
// Σ_c = I − V diag(w²/(w²+η)) V^T, B_j the rows of S diag(σ) of vertex j. O(n·k²).
std::vector<double> vertex_uncertainty(const Model& model, const FitResult& fit, int threads);

// Checks landmarks against the model: vertex indices < p, finite coordinates, ≥ 3 points,
// no vertex given twice. Throws bad_input.
void check_landmarks(const Model& model, const Landmarks& lm);

}  // namespace fest::facefit
