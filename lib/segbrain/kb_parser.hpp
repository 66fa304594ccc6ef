#pragma once
// Reader of knowledge-base text (docs/segbrain.md §2): clauses, facts and directives, with the
// position of each clause so errors and traces can say "file:line". The parser only
// reads text it is given; following `:- include(F)` is the caller's job (no I/O in lib/).

#include <string>
#include <vector>

#include "segbrain/term.hpp"

namespace fest::segbrain {

struct Clause {
  Term head;
  Term body;          // the atom `true` for facts
  std::string file;
  int line = 0;
  int col = 0;
  std::vector<std::string> singletons;  // named variables used once (for kb-check)
};

struct Directive {
  Term goal;          // include(F), dynamic(N/A), ...
  std::string file;
  int line = 0;
};

struct Program {
  std::vector<Clause> clauses;
  std::vector<Directive> directives;
};

// Parses a whole file's text. Throws fest::Error (bad_input) with
// "file:line:col: syntax error: what" at the first error.
Program parse_program(const std::string& text, const std::string& file);

// Parses one term (for --set values and --goal): "[1.5, 2.0]", "find_brain".
Term parse_term(const std::string& text, const std::string& where);

}  // namespace fest::segbrain
