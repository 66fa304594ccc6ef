#include "commands.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "ffd/joints.hpp"
#include "ffd/lattice.hpp"
#include "ffd/lattice_codec.hpp"
#include "ffd/rigid.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

#include "mesh_lattice_io.hpp"

namespace fest::ffd_tool {

int run_convert(const ConvertOptions& o) {
  const Lattice l = load_lattice(o.input);
  if (o.to == LatticeFormat::json) write_output(o.output, ffd::encode_lattice_json(l));
  else write_output(o.output, ffd::encode_pygem_prm(l));
  return 0;
}

}  // namespace fest::ffd_tool
