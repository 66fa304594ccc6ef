// lemtrace gen: a synthetic grid with an analytic field.

#include "commands.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "dataset_bridge.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"

namespace fest::lemtrace_tool {

int run_gen(const GenArgs& a) {
  GridFormat to = a.to;
  if (to == GridFormat::unset) {
    if (is_stdio(a.output)) to = GridFormat::vtu;
    else {
      const formats::OutputFormat of = formats::output_format_from_path(a.output);
      if (of.format == formats::Format::vtu) to = GridFormat::vtu;
      else if (of.format == formats::Format::vtk) to = GridFormat::vtk;
      else throw usage_error("gen writes .vtu or .vtk, not '{}'", a.output);
    }
  }
  const auto& kinds = gen_kinds();
  if (std::find(kinds.begin(), kinds.end(), a.kind) == kinds.end())
    throw usage_error("unknown grid kind '{}' (see lemtrace gen --help)", a.kind);
  GenOptions o;
  o.kind = a.kind;
  o.n = a.n;
  o.jitter = a.jitter;
  o.seed = a.seed;
  o.hex = a.hex;
  const GeneratedGrid g = generate(o);
  const Dataset ug = dataset_from_generated(g, a.kind);
  write_output(a.output, formats::write_dataset(ug, to == GridFormat::vtu ? formats::Format::vtu : formats::Format::vtk));
  return 0;
}

}  // namespace fest::lemtrace_tool
