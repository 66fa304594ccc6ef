#pragma once
// Turning the model flags (--grid, --qs, --center, --quat) into a fest::feshape::Model,
// with usage errors that name the flag.

#include "commands.hpp"
#include "feshape/model.hpp"

namespace fest::feshape_tool {

// "MxN" -> rings, meridians, each in 3..1000 (the seed's smallest grid is 5x5).
void parse_grid(const std::string& grid, int& rings, int& meridians);
// The model the flags describe; `qs` empty gives the unit sphere (1,1,1,1,1,1,0,0,0,0,0).
feshape::Model model_from_args(const ModelArgs& a);

}  // namespace fest::feshape_tool
