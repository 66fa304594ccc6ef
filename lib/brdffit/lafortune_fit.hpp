#pragma once
// Fitting one Lafortune BRDF to radiance samples by Levenberg–Marquardt with the analytic
// Jacobian (docs/brdffit.md §3): E(p) = sum_i w_i sum_c rho(r_i,c - f_c(p; u_i, v_i) u_i,z)
// with rho the square (default) or Huber's function, log-N parameterisation, projection
// onto the bounds after every step, the initialisation and multi-start of docs/brdffit.md §3, and the
// parameter covariance sigma^2 (J^T J)^-1 that the clustering's split step uses.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "brdffit/fit_sample.hpp"
#include "brdffit/lafortune_model.hpp"
#include "core/progress_callback.hpp"
#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

struct FitOptions {
  ModelSpec model;
  int starts = 4;                // multi-start over N in {5, 20, 80, 300} (first `starts`)
  double huber_delta = 0;        // > 0: Huber loss with this threshold
  int max_iterations = 200;
  double tolerance = 1e-8;       // stop when the relative decrease of E is below this
  std::size_t subsample = 200000;  // fit on at most this many samples (0 = all)
  std::uint64_t seed = 1;        // of the subsample
  int threads = 1;
  ProgressFn progress;           // fit_brdf only: LM iterations of every start planned (a
                                 // start that converges early counts all of its iterations)
};

struct FitResult {
  Eigen::VectorXd params;  // in the layout of lafortune_model.hpp (log N)
  reflectance::LafortuneBrdf brdf;
  Eigen::MatrixXd covariance;  // sigma^2 (J^T J)^+ in the parameter layout
  double energy = 0;           // E on the samples fitted
  double sigma2 = 0;           // E / (m - P)
  double mean_squared = 0;     // D over all given samples (docs/brdffit.md §5), after the fit
  std::size_t samples_used = 0;
  int iterations = 0;          // LM iterations of the winning start
};

// Full fit: initialisation and multi-start (and, for K > 1 lobes, lobes added one at a
// time, each from several starts). Throws bad_input when there are no samples or a
// sample is not finite, runtime_failure when the fit produces a non-finite value.
FitResult fit_brdf(const std::vector<FitSample>& samples, const FitOptions& options);

// One LM run from the given parameters (the clustering's refits start from the parent).
FitResult refine_brdf(const std::vector<FitSample>& samples, const Eigen::VectorXd& start, const FitOptions& options);

// D(L, f) of docs/brdffit.md §5 for samples [begin, end): weighted mean of the squared residual per
// channel. Returns 0 for an empty range.
double mean_squared_residual(const ModelSpec& spec, const Eigen::VectorXd& p, const FitSample* begin,
                             const FitSample* end);
double mean_squared_residual(const ModelEvaluator& f, const FitSample* begin, const FitSample* end);

// The albedo bound in the data's units: spec.max_lobe_albedo times the median apparent
// albedo pi r / u_z of the samples when that exceeds 1. Radiance calibrated against a
// white target (docs/brdffit.md §1) has a median apparent albedo below 1 and keeps the physical bound;
// uncalibrated radiance (light intensity in camera units, as hdrmerge's rigs have it)
// scales the bound with the unknown intensity instead of crushing every lobe.
double albedo_bound_in_data_units(double max_lobe_albedo, const std::vector<FitSample>& samples);

// Deterministic subsample of at most `count` indices of [0, n) (sorted), from a seed.
std::vector<std::size_t> subsample_indices(std::size_t n, std::size_t count, std::uint64_t seed);

}  // namespace fest::brdffit
