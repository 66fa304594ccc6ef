// patnet dot: load without running; draw the net classes for Graphviz.

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "patnet/dot.hpp"
#include "patnet/machine.hpp"

namespace fest::patnet_tool {

int cmd_dot(const DotArgs& a) {
  patnet::Machine m;
  for (const std::string& f : a.files) m.load(read_input(f), f, false);
  m.finish_checks();
  for (const auto& d : m.diagnostics())
    if (d.error) throw bad_input("{}", d.text());
  write_output(a.output, patnet::to_dot(m, a.class_name));
  return 0;
}

}  // namespace fest::patnet_tool
