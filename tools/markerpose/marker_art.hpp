#pragma once
// The dictionary marker that --dict and --id name (gen, draw).

#include <string>

#include "markers/synth.hpp"

namespace fest::markerpose_tool {

// Its cells as art for the synthesiser; a usage error naming both flags when the
// dictionary is unknown or the id outside it.
markers::MarkerArt art_from_flags(const std::string& dict, int id);

}  // namespace fest::markerpose_tool
