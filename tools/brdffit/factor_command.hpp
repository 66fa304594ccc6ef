#pragma once
// brdffit factor (specs/brdffit.md §2.10, §4): separable display textures of one BRDF.

#include <CLI/CLI.hpp>

namespace fest::brdffit_tool {

// Registers `factor`; it runs from its CLI11 callback.
void add_factor_command(CLI::App& app);

}  // namespace fest::brdffit_tool
