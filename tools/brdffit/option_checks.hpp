#pragma once
// The materials stages' options checked in the flags' names before lib/brdffit sees them
// (lib/brdffit states the same limits in its own terms).

#include "brdffit/cluster.hpp"
#include "brdffit/lafortune_fit.hpp"
#include "brdffit/normals.hpp"
#include "commands.hpp"
#include "core/threads.hpp"

namespace fest::brdffit_tool {

// FitFlags -> FitOptions: --max-lobe-albedo, --lobes, --starts checked; threads resolved.
brdffit::FitOptions fit_options(const FitFlags& f);

// --clusters, --split-scale, --split-iters, --global-iters, --stable, --min-cluster, --min-gain.
void check_cluster_options(const brdffit::ClusterOptions& o);

// --normal-min-samples, --max-tilt, --alternate.
void check_normal_options(const brdffit::NormalOptions& o);

// --basis.
void check_basis(int basis);

// Options of a lib/brdffit stage with --threads resolved (0 = all cores).
template <typename Options>
Options with_threads(Options o, int threads) {
  o.threads = resolve_threads(threads);
  return o;
}

}  // namespace fest::brdffit_tool
