// segbrain kb-check: lint rule files (syntax, undefined predicates, singletons).
#include <cstdio>

#include "commands.hpp"
#include "core/error.hpp"
#include "knowledge_base.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;

int run_kb_check(const KbCheckArgs& a) {
  OperatorEngine ops;
  Engine& engine = ops.engine;
  std::vector<Program> progs = load_kb(a.files);
  std::size_t problems = 0;
  for (const auto& p : progs) {
    engine.consult(p);
    for (const auto& c : p.clauses)
      for (const auto& s : c.singletons) std::printf("%s:%d: warning: singleton variable %s\n", c.file.c_str(), c.line, s.c_str());
  }
  for (const auto& [pred, where] : engine.undefined_calls()) {
    std::printf("%s: error: unknown predicate %s\n", where.c_str(), pred.c_str());
    ++problems;
  }
  if (problems) throw bad_input("{} unknown predicate call(s) in the knowledge base", problems);
  return 0;
}

}  // namespace fest::segbrain_tool
