#pragma once
// Inputs of `patnet run` from files: JSON Lines events and a TSV table (docs/patnet.md
// "Inputs from the outside world").

#include <string>
#include <vector>

#include "patnet/machine.hpp"

namespace fest::patnet_tool {

std::vector<patnet::InputEvent> parse_events(const std::string& bytes, const std::string& name, patnet::Machine& m);
patnet::TableInput parse_table(const std::string& bytes, const std::string& name, const std::string& var);

}  // namespace fest::patnet_tool
