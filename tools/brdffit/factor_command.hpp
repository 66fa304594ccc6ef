#pragma once
// brdffit factor (docs/brdffit.md §6): separable display textures of one BRDF.

#include <CLI/CLI.hpp>

namespace fest::brdffit_tool {

// Registers `factor`; it runs from its CLI11 callback.
void add_factor_command(CLI::App& app);

}  // namespace fest::brdffit_tool
