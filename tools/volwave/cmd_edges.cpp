#include "commands.hpp"
#include "core/error.hpp"
namespace fest::volwave_tool {
int edges_command(const EdgesOptions&) { throw runtime_failure("edges: not built yet"); }
}  // namespace fest::volwave_tool
