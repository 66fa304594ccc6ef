// fcompare: kind-aware numeric comparison of two files -- the check behind every
// golden-file test of fest. Exit 0 when within tolerance, 1 when not.
//
// Flags only: the comparison lives in the fest_fcompare_app library (cmd_compare.cpp).

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace fest::fcompare_tool;
  CLI::App app{"Compare two files of the same kind numerically: meshes (surface distance, counts,\n"
               "topology), images (RMSE, PSNR, max abs), volumes (max abs, Dice per label), tables\n"
               "(max abs per column), VTK datasets (cells, points, arrays), JSON (numbers and structure).\n"
               "Exit 0 when within tolerance, 1 when not.",
               "fcompare"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  CompareOptions opt;
  std::vector<std::string> thresholds;
  app.add_option("a", opt.a, "First file (- for standard input)")->required();
  app.add_option("b", opt.b, "Second file")->required();
  CLI::Option* tol = app.add_option("--tol", opt.tol,
                 "Tolerance of the main metric: mesh Hausdorff distance, else max absolute difference")
      ->default_val(0.0)
      ->check(fest::cli::non_negative);
  app.add_option("-t,--threshold", thresholds,
                 "Extra check METRIC<=VALUE or METRIC>=VALUE, e.g. 'psnr>=40', 'rms<=1e-4', 'dice>=0.9'; "
                 "replaces the default check of that metric and of the metrics that measure the same error "
                 "(image max_abs/rmse/psnr; mesh hausdorff/rms/mean; volume max_abs/rmse/dice; table max_abs/max_rel)")
      ->allow_extra_args(false);
  app.add_option("--samples", opt.samples, "Meshes: random surface samples per mesh besides the vertices")
      ->check(fest::cli::range(0LL, 100000000LL))
      ->default_val(100000);
  fest::cli::add_threads(app, opt.threads);
  app.add_flag("--ignore-counts", opt.ignore_counts, "Meshes: allow different vertex, face, line and point counts");
  app.add_flag("--ignore-topology", opt.ignore_topology, "Meshes: allow different genus, boundaries, components");
  app.add_flag("--ordered", opt.ordered,
               "Meshes: also compare vertices by index (vertex_max_abs), for conversions that keep vertex "
               "order; by default only order-independent distances are measured");
  app.add_option("--report", opt.report, "Write every metric and check as JSON to this file");
  app.footer("Exit status: 0 within tolerance, 1 not (failing checks on standard error), 2 usage error,\n"
             "3 bad input, 4 I/O error. See fcompare(1).");
  return fest::cli::run(app, argc, argv, [&] {
    opt.quiet = common.quiet;
    opt.tol_given = tol->count() > 0;
    for (const std::string& t : thresholds) opt.thresholds.push_back(fest::compare::parse_threshold(t));
    return compare_command(opt);
  });
}
