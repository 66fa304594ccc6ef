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

int run_init(const InitOptions& o) {
  if (o.dims.size() != 3) throw usage_error("--dims takes L,M,N");
  for (const int d : o.dims)
    if (d < 2 || d > ffd::max_axis_points) throw usage_error("--dims: {} is outside 2..{}", d, ffd::max_axis_points);
  if (!(o.pad >= 0) || o.pad > 10) throw usage_error("--pad {} is outside 0..10", o.pad);
  const ffd::Basis basis = o.basis;
  const Mesh m = load_mesh(o.input);
  if (m.n_vertices() == 0) throw bad_input("the mesh has no vertices ({})", o.input);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Eigen::Vector3d& p : points_of(m)) {
    if (!p.allFinite()) throw bad_input("the mesh has a non-finite coordinate ({})", o.input);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Eigen::Vector3d ext = hi - lo;
  const double scale = std::max(ext.maxCoeff(), 1e-12);
  for (int a = 0; a < 3; ++a) ext[a] = std::max(ext[a], 1e-6 * scale);  // a flat mesh still gets a box
  Lattice l;
  l.origin = lo - o.pad * ext;
  for (int a = 0; a < 3; ++a) l.axes[static_cast<std::size_t>(a)] = Eigen::Vector3d::Unit(a) * ext[a] * (1 + 2 * o.pad);
  for (int a = 0; a < 3; ++a) l.dims[static_cast<std::size_t>(a)] = o.dims[static_cast<std::size_t>(a)];
  l.basis.fill(basis);
  write_output(o.output, ffd::encode_lattice_json(l));
  return 0;
}

}  // namespace fest::ffd_tool
