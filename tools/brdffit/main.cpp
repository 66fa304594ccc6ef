// brdffit: spatially varying BRDFs from a few registered HDR photographs of a scanned
// object (docs/brdffit.md; Lensch et al., chapter 8 of the Festschrift). One executable,
// one subcommand per stage. The geometry stages (geometry_commands.cpp) run from their
// CLI11 callbacks; the materials stages (materials_commands.cpp) run after parsing. Both
// happen inside run_tool, so errors become one line and the exit status of README's "Conventions".

#include <cstdio>
#include <string>

#include "cli/cli.hpp"
#include "factor_command.hpp"
#include "geometry_commands.hpp"
#include "materials_commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Spatially varying BRDFs from registered HDR photographs of a scanned object\n"
               "(Lensch et al.: lumitexels, Lafortune fits, material clustering, projection).",
               "brdffit"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  fest::brdffit_tool::add_geometry_commands(app);
  brdffit_tool::add_materials_commands(app);
  fest::brdffit_tool::add_factor_command(app);
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See brdffit(1), ltx(5), ltw(5).");
  return fest::run_tool("brdffit", [&]() -> int {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
      std::fprintf(stderr, "brdffit: error: %s (see brdffit --help)\n", e.what());
      return static_cast<int>(fest::Status::usage);
    }
    const int materials_status = brdffit_tool::run_materials_command(app);
    return materials_status >= 0 ? materials_status : 0;
  });
}
