// patnet check: load without running; report the diagnostics.

#include <cstdio>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "patnet/machine.hpp"

namespace fest::patnet_tool {

int cmd_check(const CheckArgs& a) {
  patnet::Machine m;
  for (const std::string& f : a.files) m.load(read_input(f), f, false);
  m.finish_checks();
  int errors = 0, warnings = 0;
  for (const auto& d : m.diagnostics()) {
    if (d.error) ++errors;
    else ++warnings;
    if (d.error || !a.quiet) std::fprintf(stderr, "patnet: %s: %s\n", d.error ? "error" : "warning", d.text().c_str());
  }
  return errors > 0 ? static_cast<int>(Status::bad_input) : 0;
}

}  // namespace fest::patnet_tool
