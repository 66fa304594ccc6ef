#pragma once
// Material clustering by split and refit (docs/brdffit.md §5; chapter 8 §8.4.3):
// start with one cluster of all lumitexels and its fitted BRDF; repeatedly take the
// cluster with the largest total error, move its parameters by +-kappa sigma_max along the
// principal eigenvector of their covariance, let the members choose the nearer of the two
// BRDFs and refit both until few change side, then reassign every lumitexel to its
// nearest cluster. Distances are D(L, f) of docs/brdffit.md §5.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "brdffit/fit_sample.hpp"
#include "brdffit/lafortune_fit.hpp"
#include "brdffit/lumitexel.hpp"
#include "core/progress_callback.hpp"

namespace fest::brdffit {

struct ClusterOptions {
  int clusters = 5;            // K_target; 0 = auto (split until min_gain stops it)
  int max_auto_clusters = 64;  // upper limit of auto mode
  double split_scale = 1.0;    // kappa (reconstructed)
  int split_iters = 10;
  double stable = 0.005;       // fraction of members changing side that ends a split
  int global_iters = 3;
  double min_cluster = 0.001;  // fraction of lumitexels below which a cluster is dissolved
  double min_gain = 0.02;      // auto mode: stop when a split lowers the total error by less
                               // than this fraction of the one-cluster error
  int refit_iterations = 30;   // LM iterations of warm-started refits
  double refit_tolerance = 1e-6;  // their stopping rule (relative decrease of E)
  std::size_t split_subsample = 25000;  // samples of the refits inside a split's loop (the
                                        // children are refitted on fit.subsample after it)
  FitOptions fit;              // model, starts, subsample, seed, threads of every fit
  ProgressFn progress;         // clusters made of the target (auto: of max_auto_clusters)
};

struct MaterialCluster {
  Eigen::VectorXd params;      // layout of lafortune_model.hpp
  Eigen::MatrixXd covariance;
  std::size_t members = 0;     // lumitexels
  std::size_t samples = 0;
  double error = 0;            // sum over members of |L| D(L, f)
};

struct SplitRecord {
  int split = 0;               // the cluster that was split
  int created = 0;             // index of the new cluster (the other half keeps `split`)
  int clusters = 0;            // count after the split and the reassignment
  int split_iterations = 0;
  double error_before = 0, error_after = 0;  // total error
};

struct ClusterResult {
  ModelSpec model;
  std::vector<MaterialCluster> clusters;
  std::vector<std::uint16_t> assignment;  // per lumitexel of the input set
  std::vector<SplitRecord> history;
  double total_error = 0;
};

// Lumitexels with no samples take part in nothing and are assigned to cluster 0.
// Throws bad_input when no lumitexel has a sample, usage_error for absurd options,
// runtime_failure (naming the cluster) when a fit produces NaN.
ClusterResult cluster_lumitexels(const LumitexelSet& set, const std::vector<FitSample>& local,
                                 const ClusterOptions& options);

// D(L, f) for lumitexel i.
double lumitexel_distance(const LumitexelSet& set, const std::vector<FitSample>& local, std::size_t i,
                          const ModelSpec& model, const Eigen::VectorXd& p);

// Every lumitexel to the cluster of smallest D (ties to the lower index).
std::vector<std::uint16_t> nearest_clusters(const LumitexelSet& set, const std::vector<FitSample>& local,
                                            const ModelSpec& model, const std::vector<Eigen::VectorXd>& params,
                                            int threads, const ProgressFn& progress = {});

// One split of a cluster as in docs/brdffit.md §5 without replacing it (the projection's basis uses the
// two children): returns the children's parameters, or nothing when the cluster cannot be
// split (fewer than two members with samples).
std::vector<Eigen::VectorXd> trial_split(const LumitexelSet& set, const std::vector<FitSample>& local,
                                         const std::vector<std::size_t>& members, const MaterialCluster& cluster,
                                         const ClusterOptions& options);

}  // namespace fest::brdffit
