#pragma once
// Spatially varying weights: every lumitexel's BRDF as a weighted sum of its cluster's
// basis BRDFs, f_L = sum_j t_j f_j (docs/brdffit.md §5; chapter 8 §8.4.3). The basis
// of cluster C (reconstructed; the paper gives only its size): f_C, the two children of
// one trial split of C, then the BRDFs of the other clusters nearest to C's members
// (mean D) until `basis` functions. Weights by linear least squares "computed using
// singular value decomposition", or NNLS when non-negative weights are asked for.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "brdffit/cluster.hpp"
#include "brdffit/fit_sample.hpp"
#include "brdffit/lumitexel.hpp"

namespace fest::brdffit {

enum class WeightMode { scalar, rgb };  // one weight per basis BRDF, or one per channel

struct ProjectOptions {
  int basis = 4;
  WeightMode weights = WeightMode::scalar;
  bool nonneg = false;
  double svd_threshold = 1e-6;  // relative to the largest singular value
  ClusterOptions split;         // the trial split's settings (fit options, threads)
  ProgressFn progress;          // project_lumitexels: thousandths of nearest clusters, bases, weights
};

struct Basis {
  ModelSpec model;
  std::vector<Eigen::VectorXd> brdfs;             // global list of basis BRDFs
  std::vector<std::vector<int>> cluster_basis;    // per cluster: indices into brdfs, f_C first
};

struct Projection {
  Basis basis;
  int basis_size = 0;  // weights per lumitexel (per channel in rgb mode): the longest list
  WeightMode mode = WeightMode::scalar;
  std::vector<std::uint16_t> cluster;  // per lumitexel
  std::vector<float> weights;          // per lumitexel: basis_size (scalar) or 3 x basis_size
                                       // (rgb, channel-major); weight j goes with
                                       // cluster_basis[cluster][j]; unused trailing ones are 0
  int values_per_lumitexel() const { return mode == WeightMode::rgb ? 3 * basis_size : basis_size; }
};

// The bases of every cluster (trial splits and nearest clusters) for the given assignment.
Basis build_basis(const LumitexelSet& set, const std::vector<FitSample>& local, const ModelSpec& model,
                  const std::vector<MaterialCluster>& clusters, const std::vector<std::uint16_t>& assignment,
                  const ProjectOptions& options);

// The basis functions of one lumitexel, in weight order.
using BasisFunctions = std::vector<const ModelEvaluator*>;

// Weights of one lumitexel (samples in its local frame) for the given basis functions;
// writes values_per_lumitexel() floats. Fewer samples than functions: (1, 0, ...).
void solve_weights(const FitSample* samples, std::size_t count, const BasisFunctions& functions,
                   const ProjectOptions& options, int basis_size, float* out);

// f_L per channel for a lumitexel with the given weights.
Eigen::Vector3d blended_value(const BasisFunctions& functions, const float* weights, WeightMode mode, int basis_size,
                              double xy, double z);

// Assigns every lumitexel to its nearest cluster, builds the bases and solves all weights.
Projection project_lumitexels(const LumitexelSet& set, const std::vector<FitSample>& local, const ModelSpec& model,
                              const std::vector<MaterialCluster>& clusters, const ProjectOptions& options);

// Evaluators of every basis BRDF (index as in basis.brdfs), and the functions of
// lumitexel i's cluster taken from them.
std::vector<ModelEvaluator> evaluators_of(const Basis& basis);
BasisFunctions functions_of(const Projection& p, const std::vector<ModelEvaluator>& evaluators, std::size_t i);

// Sum over lumitexels of |L| D(L, f_L) (the projected model's error) and, for comparison,
// of |L| D(L, f_C) (the per-cluster model's error).
struct ProjectionError {
  double projected = 0, per_cluster = 0;
};
ProjectionError projection_error(const LumitexelSet& set, const std::vector<FitSample>& local, const Projection& p,
                                 int threads, const ProgressFn& progress = {});

}  // namespace fest::brdffit
