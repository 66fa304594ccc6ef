#pragma once
// The geometry side of brdffit: synth, lumitexels, register, render, eval.

#include <CLI/CLI.hpp>

namespace fest::brdffit_tool {

void add_geometry_commands(CLI::App& app);

}  // namespace fest::brdffit_tool
