// brdffit: spatially varying BRDFs from a few calibrated HDR photographs of a scanned
// object (seed 000 chapter 8, Lensch et al.; specs/brdffit.md). Subcommands in the manner
// of git. MINIMAL VERSION of the materials branch: only fit, cluster, project, normals;
// the lead merges it with the geometry side's main.cpp.

#include "cli/cli.hpp"
#include "materials_commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Spatially varying BRDFs (Lafortune lobes, material clusters, basis weights, normal maps)\n"
               "from lumitexels of registered HDR photographs (Lensch et al.).",
               "brdffit"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  app.footer("Exit status: 0 success, 1 numerical failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See brdffit(1), ltw(5).");
  brdffit_tool::add_materials_commands(app);
  return fest::cli::run(app, argc, argv, [&] { return brdffit_tool::run_materials_command(app); });
}
