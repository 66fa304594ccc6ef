#pragma once
// Normal refinement (docs/brdffit.md §6; chapter 8 §8.4.4): for every lumitexel with
// enough samples, the normal n' = normalize(n + a t + b b) that best explains its samples
// under its projected BRDF f_L, found by Levenberg–Marquardt over the tangent offset (a, b)
// from (0, 0) with the tilt bounded. Only u.n', v.n' and u.v enter an isotropic BRDF, so
// no frame is needed for n'. Optionally alternates with re-projection of the weights.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "brdffit/lumitexel.hpp"
#include "brdffit/project.hpp"

namespace fest::brdffit {

struct NormalOptions {
  int min_samples = 5;
  double max_tilt_deg = 30;
  int max_iterations = 50;
  int alternate = 1;       // rounds of (projection, normals); 1 = normals only
  ProjectOptions project;  // for re-projection when alternating (nonneg, threshold)
  int threads = 1;
  ProgressFn progress;     // chunks of lumitexels refined
};

struct NormalResult {
  std::vector<Eigen::Vector3f> normals;  // per lumitexel (the input normal where not refined)
  std::vector<std::uint8_t> refined;     // 1 where refined
  std::size_t refined_count = 0;
  double residual_before = 0, residual_after = 0;  // sum of squared residuals, refined ones
};

// The blended BRDF of one lumitexel: basis functions and weights.
struct BlendedBrdf {
  BasisFunctions functions;
  const float* weights = nullptr;
  WeightMode mode = WeightMode::scalar;
  int basis_size = 0;
};

// Sum of squared residuals of world-frame samples for the normal n (unit).
double normal_residual(const Sample* samples, std::size_t count, const Eigen::Vector3d& n, const BlendedBrdf& f);

// Refines one normal; returns the refined unit normal, and the residual before/after.
Eigen::Vector3d refine_normal(const Sample* samples, std::size_t count, const Eigen::Vector3d& n0,
                              const BlendedBrdf& f, const NormalOptions& options, double* before, double* after);

NormalResult refine_normals(const LumitexelSet& set, const Projection& projection, const NormalOptions& options);

}  // namespace fest::brdffit
