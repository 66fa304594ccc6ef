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

int run_jacobian(const JacobianOptions& o) {
  const Lattice lattice = load_lattice(o.lattice);
  const ffd::Outside outside = o.outside;
  const ffd::Deformer d(lattice);
  const Mesh m = load_mesh(o.input);
  std::string out = "vertex\tdetJ\n";
  for (const Eigen::Vector3d& p : points_of(m)) {
    if (!p.allFinite()) throw bad_input("the mesh has a non-finite coordinate ({})", o.input);
  }
  std::size_t i = 0;
  for (const Eigen::Vector3d& p : points_of(m)) out += fmt::format("{}\t{}\n", i++, d.jacobian(p, outside).determinant());
  write_output(o.output, out);
  return 0;
}

}  // namespace fest::ffd_tool
