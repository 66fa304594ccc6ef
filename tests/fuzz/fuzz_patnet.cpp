// Feeds raw bytes to the PaT-Lisp reader, compiler and static checker (patnet check),
// and, when the checks pass, runs the nets briefly under tight limits (patnet run): any
// input must end in diagnostics, trace events or a clean fest::Error -- never a crash,
// an escaping exception or a hang.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "patnet/dot.hpp"
#include "patnet/machine.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    fest::patnet::Machine m;
    m.load(text, "fuzz.pat", false);
    m.finish_checks();
    if (m.has_errors()) return 0;
    if (!m.classes().empty()) (void)fest::patnet::to_dot(m, "");
    fest::patnet::RunOptions o;
    o.cycles = 50;
    o.max_steps = 20000;
    o.max_nets = 200;
    o.max_depth = 200;
    fest::patnet::Machine r(o, nullptr);
    try {
      r.load(text, "fuzz.pat", true);
      r.run();
    } catch (const fest::patnet::LimitError&) {
    }
  } catch (const fest::Error&) {
  }
  return 0;
}
