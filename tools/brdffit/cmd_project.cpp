// brdffit project (docs/brdffit.md §5): .ltx and clusters.json -> lib/brdffit's per-cluster
// bases and per-lumitexel weights -> .ltw.

#include <string>
#include <vector>

#include "brdffit/brdf_json.hpp"
#include "brdffit/fit_sample.hpp"
#include "brdffit/ltw_format.hpp"
#include "brdffit/project.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "fitted_inputs.hpp"
#include "formats/table/table_io.hpp"
#include "option_checks.hpp"

namespace fest::brdffit_tool {

int run_project(const ProjectArgs& a) {
  const Stopwatch clock;
  refuse_binary_terminal(a.output, "use -o or a pipe");
  brdffit::ProjectOptions o;
  o.basis = a.basis;
  o.weights = a.weights;
  o.nonneg = a.nonneg;
  o.split.split_scale = a.split_scale;
  o.split.split_iters = a.split_iters;
  o.split.fit.threads = resolve_threads(a.threads);
  if (!(a.split_scale > 0) || a.split_iters < 1) throw usage_error("--split-scale must be positive and --split-iters >= 1");
  const brdffit::ClusterResult clusters = decoded_from(a.clusters_file, [&] {
    return brdffit::clusters_from_json(formats::read_json(read_input(a.clusters_file)));
  });
  o.split.fit.model = clusters.model;
  nlohmann::json header;
  brdffit::LumitexelSet set = load_lumitexels(a.input, &header);
  drop_sparse(set, a.min_samples);
  const std::vector<brdffit::FitSample> local = brdffit::local_samples(set, o.split.fit.threads);
  check_basis(a.basis);
  // One bar: the projection, then its error (about 7 % of the time).
  Progress bar("brdffit project", 0, progress_wanted(a.progress));
  o.progress = progress_part(bar.callback(), 0.0, 0.93);
  const brdffit::Projection p = brdffit::project_lumitexels(set, local, clusters.model, clusters.clusters, o);
  const brdffit::ProjectionError err =
      brdffit::projection_error(set, local, p, o.split.fit.threads, progress_part(bar.callback(), 0.93, 1.0));
  bar.finish();
  const std::string bytes = brdffit::encode_ltw(p, {{"mesh_sha256", set.mesh_sha256},
                                                     {"error", {{"projected", err.projected}, {"per_cluster", err.per_cluster}}}});
  write_output(a.output, bytes);
  write_report(a.report, {{"command", "project"}, {"lumitexels", set.lumitexels.size()}, {"basis_size", p.basis_size},
                          {"basis_brdfs", p.basis.brdfs.size()}, {"error_projected", err.projected},
                          {"error_per_cluster", err.per_cluster}, {"seconds", clock.seconds()}});
  return 0;
}

}  // namespace fest::brdffit_tool
