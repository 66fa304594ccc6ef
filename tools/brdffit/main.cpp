// brdffit: spatially varying BRDFs from a few registered HDR photographs of a scanned
// object (specs/brdffit.md; Lensch et al., chapter 8 of the Festschrift). One executable,
// one subcommand per stage. The geometry stages (geometry_commands.cpp) and the
// materials stages (materials_commands.cpp, when built) add themselves to the app; every
// subcommand runs from its callback, inside run_tool, so errors become one line and the
// exit status of DESIGN.md.

#include <cstdio>
#include <string>

#include "cli/cli.hpp"
#include "geometry_commands.hpp"
#ifdef FEST_BRDFFIT_MATERIALS
#include "materials_commands.hpp"
#endif

int main(int argc, char** argv) {
  CLI::App app{"Spatially varying BRDFs from registered HDR photographs of a scanned object\n"
               "(Lensch et al.: lumitexels, Lafortune fits, material clustering, projection).",
               "brdffit"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);
  fest::brdffit_tool::add_geometry_commands(app);
#ifdef FEST_BRDFFIT_MATERIALS
  add_materials_commands(app);
#endif
  app.footer("Exit status: 0 success, 1 run-time failure, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See brdffit(1), ltx(5).");
  // Parsing runs the subcommand's callback, so it happens inside run_tool.
  return fest::run_tool("brdffit", [&]() -> int {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
      std::fprintf(stderr, "brdffit: error: %s (see brdffit --help)\n", e.what());
      return static_cast<int>(fest::Status::usage);
    }
    return 0;
  });
}
