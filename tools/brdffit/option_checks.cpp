#include "option_checks.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"

namespace fest::brdffit_tool {

brdffit::FitOptions fit_options(const FitFlags& f) {
  brdffit::FitOptions o;
  o.model.lobes = f.lobes;
  o.model.shared = f.shared;
  if (!(f.max_lobe_albedo >= 0)) throw usage_error("--max-lobe-albedo must be >= 0, not {}", f.max_lobe_albedo);
  o.model.max_lobe_albedo = f.max_lobe_albedo;
  if (f.lobes < 1 || f.lobes > 3) throw usage_error("--lobes must be 1, 2 or 3, not {}", f.lobes);
  o.starts = f.starts;
  if (f.starts < 1 || f.starts > 4) throw usage_error("--starts must be 1..4, not {}", f.starts);
  o.huber_delta = f.huber_delta;
  o.subsample = f.subsample;
  o.seed = f.seed;
  o.threads = resolve_threads(f.threads);
  return o;
}

void check_cluster_options(const brdffit::ClusterOptions& o) {
  if (o.clusters < 0 || o.clusters > 65535) throw usage_error("--clusters must be 1..65535 or auto, not {}", o.clusters);
  if (!(o.split_scale > 0)) throw usage_error("--split-scale must be positive");
  if (o.split_iters < 1 || o.global_iters < 0) throw usage_error("--split-iters must be >= 1 and --global-iters >= 0");
  if (!(o.stable >= 0 && o.stable < 1) || !(o.min_cluster >= 0 && o.min_cluster < 1) || !(o.min_gain >= 0))
    throw usage_error("--stable and --min-cluster must lie in [0, 1), --min-gain must be >= 0");
}

void check_normal_options(const brdffit::NormalOptions& o) {
  if (o.min_samples < 3) throw usage_error("--normal-min-samples must be at least 3 (two unknowns), not {}", o.min_samples);
  if (!(o.max_tilt_deg > 0 && o.max_tilt_deg < 90)) throw usage_error("--max-tilt must lie in (0, 90) degrees");
  if (o.alternate < 1) throw usage_error("--alternate must be at least 1");
}

void check_basis(int basis) {
  if (basis < 1 || basis > 64) throw usage_error("--basis must be 1..64, not {}", basis);
}

}  // namespace fest::brdffit_tool
