#pragma once
// The frame around every tool's main(): runs the body, turns fest::Error and any other
// exception into "tool: error: message" on standard error and the design's exit status.

#include <functional>
#include <string>

namespace fest {

// Returns the exit status to hand back from main().
int run_tool(const std::string& tool, const std::function<int()>& body);

// "tool: warning: message" on standard error.
void warn(const std::string& tool, const std::string& message);

}  // namespace fest
