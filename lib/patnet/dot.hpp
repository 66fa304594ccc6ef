#pragma once
// Graphviz export of loaded net classes (docs/patnet.md "dot"): the graphical view the
// seed's §5.1 planned. Boxes are nodes, diamonds probabilistic/weighted/random nodes,
// edges carry the condition or probability, dashed edges point from a class to its
// parents, notes list monitors.

#include <string>

#include "patnet/machine.hpp"

namespace fest::patnet {

// All classes, or only `only_class` (by name, any case; empty = all). Throws
// fest::Error(bad_input) when `only_class` names no class.
std::string to_dot(const Machine& m, const std::string& only_class);

}  // namespace fest::patnet
