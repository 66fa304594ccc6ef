#pragma once
// The knowledge base of a segbrain command: the rule files (or the built-in head_t1.pl)
// parsed with their includes, and the output labels it declares.

#include <array>
#include <string>
#include <vector>

#include "segbrain/engine.hpp"
#include "segbrain/kb_parser.hpp"
#include "segbrain/workspace.hpp"

namespace fest::segbrain_tool {

// share/segbrain/head_t1.pl, compiled in (default_kb.cpp.in).
extern const char* const kDefaultKbName;
extern const char* const kDefaultKb;

// The given rule files, each after the files it includes (`:- include(F)`, relative to
// its folder), each once; none: the built-in knowledge base.
std::vector<segbrain::Program> load_kb(const std::vector<std::string>& files);

// An output label of the knowledge base: label(Index, Name, Parent, [R, G, B]).
struct LabelEntry {
  int index = 0;
  std::string name, parent;
  std::array<int, 3> rgb{0, 0, 0};
};
// The label/4 facts the engine holds, in file order.
std::vector<LabelEntry> label_entries(segbrain::Engine& engine);
// The label/4 facts of the given rule files (none: the built-in knowledge base).
std::vector<LabelEntry> kb_labels(const std::vector<std::string>& kb);

// An engine that knows the workspace's operator predicates (on a 3x3x3 grid, none of them
// called): what kb-check checks rule files against and ops lists.
struct OperatorEngine {
  segbrain::Engine engine;
  segbrain::Workspace workspace{tiny_grid()};
  OperatorEngine() { workspace.register_operators(engine); }

 private:
  static segbrain::Grid tiny_grid() {
    segbrain::Grid g;
    g.n = {3, 3, 3};
    return g;
  }
};

}  // namespace fest::segbrain_tool
