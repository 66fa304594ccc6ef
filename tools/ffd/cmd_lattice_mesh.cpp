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

int run_lattice_mesh(const LatticeMeshOptions& o) {
  const Lattice l = load_lattice(o.input);
  const ffd::Deformer d(l);
  const Lattice& full = d.lattice();
  std::string out = fmt::format("# ffd control net {}x{}x{} ({})\n", l.dims[0], l.dims[1], l.dims[2], ffd::basis_name(l.basis[0]));
  for (int k = 0; k < l.dims[2]; ++k)
    for (int j = 0; j < l.dims[1]; ++j)
      for (int i = 0; i < l.dims[0]; ++i) {
        const Eigen::Vector3d p = full.rest_point(i, j, k) + full.displacement[full.index(i, j, k)];
        out += fmt::format("v {} {} {}\n", p[0], p[1], p[2]);
      }
  for (int k = 0; k < l.dims[2]; ++k)
    for (int j = 0; j < l.dims[1]; ++j)
      for (int i = 0; i < l.dims[0]; ++i) {
        const std::size_t n = full.index(i, j, k) + 1;
        if (i + 1 < l.dims[0]) out += fmt::format("l {} {}\n", n, full.index(i + 1, j, k) + 1);
        if (j + 1 < l.dims[1]) out += fmt::format("l {} {}\n", n, full.index(i, j + 1, k) + 1);
        if (k + 1 < l.dims[2]) out += fmt::format("l {} {}\n", n, full.index(i, j, k + 1) + 1);
      }
  write_output(o.output, out);
  return 0;
}

}  // namespace fest::ffd_tool
