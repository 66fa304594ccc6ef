// brdffit cluster (docs/brdffit.md §5): .ltx -> lib/brdffit's split-and-refit clustering
// -> clusters.json.

#include <string>
#include <vector>

#include "brdffit/brdf_json.hpp"
#include "brdffit/cluster.hpp"
#include "brdffit/fit_sample.hpp"
#include "commands.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "fitted_inputs.hpp"
#include "formats/table/table_io.hpp"
#include "option_checks.hpp"

namespace fest::brdffit_tool {

int run_cluster(const ClusterArgs& a) {
  const Stopwatch clock;
  brdffit::ClusterOptions o = a.c;
  o.fit = fit_options(a.fit);
  o.clusters = a.clusters;
  nlohmann::json header;
  brdffit::LumitexelSet set = load_lumitexels(a.input, &header);
  const std::size_t kept = drop_sparse(set, a.min_samples);
  const double seconds_read = clock.seconds();
  const std::vector<brdffit::FitSample> local = brdffit::local_samples(set, o.fit.threads);
  check_cluster_options(o);
  Progress bar("brdffit cluster", 0, progress_wanted(a.progress));
  o.progress = bar.callback();
  const brdffit::ClusterResult r = brdffit::cluster_lumitexels(set, local, o);
  bar.finish();
  nlohmann::json out = brdffit::clusters_to_json(r);
  out["lumitexels"] = set.lumitexels.size();
  out["lumitexels_clustered"] = kept;
  out["mesh_sha256"] = set.mesh_sha256;
  out["options"] = {{"clusters", a.clusters == 0 ? std::string("auto") : std::to_string(a.clusters)},
                    {"split_scale", o.split_scale}, {"split_iters", o.split_iters},
                    {"stable", o.stable}, {"global_iters", o.global_iters}, {"min_cluster", o.min_cluster},
                    {"min_gain", o.min_gain}, {"fit_subsample", o.fit.subsample}, {"seed", o.fit.seed},
                    {"min_samples", a.min_samples}};
  write_output(a.output, formats::write_json(out));
  write_report(a.fit.report, {{"command", "cluster"}, {"lumitexels", set.lumitexels.size()}, {"clustered", kept},
                              {"samples", set.samples.size()}, {"clusters", r.clusters.size()},
                              {"total_error", r.total_error}, {"seconds_read", seconds_read},
                              {"seconds", clock.seconds()}});
  return 0;
}

}  // namespace fest::brdffit_tool
