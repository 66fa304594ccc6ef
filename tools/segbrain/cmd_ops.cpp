// segbrain ops: the operator predicates the workspace gives the engine, and their modes.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "knowledge_base.hpp"
#include "segbrain/engine.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;
using nlohmann::json;

int run_ops(const OpsArgs& a) {
  OperatorEngine ops;
  Engine& engine = ops.engine;
  json j = json::array();
  std::string text;
  for (const auto& [name, info] : engine.foreigns()) {
    j.push_back({{"predicate", name}, {"modes", info.modes}, {"doc", info.doc}});
    text += fmt::format("{:<28} {:<40} {}\n", name, "(" + info.modes + ")", info.doc);
  }
  write_output("-", a.json ? j.dump(2) + "\n" : text);
  return 0;
}

}  // namespace fest::segbrain_tool
