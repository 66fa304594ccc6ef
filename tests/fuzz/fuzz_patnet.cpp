// Feeds raw bytes to the PaT-Lisp reader, compiler and static checker (patnet check):
// any input must end in diagnostics or a clean fest::Error, never a crash or a hang.
// Nothing is executed (top-level forms run only in `patnet run`).
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
    if (!m.has_errors() && !m.classes().empty()) (void)fest::patnet::to_dot(m, "");
  } catch (const fest::Error&) {
  }
  return 0;
}
