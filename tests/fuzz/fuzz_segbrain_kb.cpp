// Feeds raw bytes to segbrain's knowledge-base reader (lib/segbrain/kb_parser: clauses,
// directives, operators, lists, strings, comments) as a rule file and as a single term
// (--goal, --set values), and consults what it reads into an engine with the workspace's
// operators, as segbrain kb-check does: any input must end in a program or a clean
// fest::Error -- never a crash, an escaping exception or a hang. Nothing is proved.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "segbrain/engine.hpp"
#include "segbrain/kb_parser.hpp"
#include "segbrain/workspace.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  using namespace fest::segbrain;
  try {
    (void)to_string(parse_term(text, "fuzz"));
  } catch (const fest::Error&) {
  }
  try {
    const Program p = parse_program(text, "fuzz.pl");
    for (const auto& c : p.clauses) (void)(to_string(c.head).size() + to_string(c.body).size());
    Engine engine;
    Grid g;
    g.n = {3, 3, 3};
    Workspace ws(g);
    ws.register_operators(engine);
    engine.consult(p);
    (void)engine.undefined_calls();
  } catch (const fest::Error&) {
  }
  return 0;
}
