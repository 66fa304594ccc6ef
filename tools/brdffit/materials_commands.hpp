#pragma once
// The materials side of brdffit (docs/brdffit.md §3-5): the subcommands
// fit, cluster, project and normals. Include only from tools/brdffit/main.cpp.

#include <CLI/CLI.hpp>

namespace brdffit_tool {

// Declares the four subcommands and their flags on `app`.
void add_materials_commands(CLI::App& app);

// After parsing: runs the materials subcommand that was given and returns its exit
// status; returns -1 when none of them was given.
int run_materials_command(const CLI::App& app);

}  // namespace brdffit_tool
