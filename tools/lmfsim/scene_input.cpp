// The scene on standard input: JSON -> Scene (meshes read from files relative to the
// working folder), and the command-line overrides of its `sim` block.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/table/table_io.hpp"
#include "lmfsim/scene_json.hpp"

namespace fest::lmfsim_tool {

using namespace fest::lmfsim;

void SimOverrides::apply(SimSettings& sim) const {
  if (dt) sim.dt = *dt;
  if (t_end) sim.t_end = *t_end;
  if (every) sim.every = *every;
  if (alpha) sim.alpha = *alpha;
  if (beta) sim.beta = *beta;
  if (kappa) sim.kappa = *kappa;
  if (omega0) sim.omega0 = *omega0;
  if (zeta) sim.zeta = *zeta;
  if (svd_tol) sim.svd_tol = *svd_tol;
  if (max_violation) sim.max_violation = *max_violation;
  if (rtol) sim.rtol = *rtol;
  if (atol) sim.atol = *atol;
  if (integrator) sim.integrator = *integrator;
  if (solver) sim.solver = *solver;
  if (formulation) sim.formulation = *formulation;
  if (stab) sim.stab = *stab;
  if (!(sim.dt > 0) || !std::isfinite(sim.dt)) throw fest::usage_error("--dt must be positive (got {})", sim.dt);
  if (!(sim.t_end >= 0)) throw fest::usage_error("--t-end must be >= 0 (got {})", sim.t_end);
  if (sim.every < 1) throw fest::usage_error("--every must be >= 1 (got {})", sim.every);
  step_count(sim.t_end, sim.dt, dt || t_end);
}

long step_count(double t_end, double dt, bool from_flags) {
  // In double: t_end / dt of an absurd --t-end is no long (lround would wrap, and the
  // run would write frame 0 only).
  const double steps = t_end / dt;
  if (!(steps <= kMaxSteps)) {
    const std::string count = std::isfinite(steps) ? fmt::format("{:.3g}", steps) : "more than 1e308";
    if (from_flags)
      throw fest::usage_error("--t-end {} / --dt {} is {} steps; a run takes at most {:.0f}", t_end, dt, count, kMaxSteps);
    throw fest::bad_input("the scene's sim.t_end {} / sim.dt {} is {} steps; a run takes at most {:.0f}", t_end, dt, count,
                          kMaxSteps);
  }
  return std::lround(steps);
}

Scene load_scene(const std::string& bytes) {
  if (bytes.find_first_not_of(" \t\r\n") == std::string::npos) throw fest::bad_input("empty scene on standard input");
  const nlohmann::json doc = fest::formats::read_json(bytes);
  auto loader = [](const std::string& path, std::vector<Vec3>& v, std::vector<std::array<int, 3>>& t) {
    const fest::formats::Input in = fest::formats::load_input(path);
    const fest::Mesh mesh = fest::formats::parse(in, fest::formats::read_mesh);
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      v.emplace_back(p[0], p[1], p[2]);
    }
    for (auto fh : mesh.faces()) {
      std::vector<int> idx;
      for (auto fv : mesh.fv_range(fh)) idx.push_back(fv.idx());
      if (idx.size() < 3) continue;
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) t.push_back({idx[0], idx[k], idx[k + 1]});  // fan
    }
    if (mesh.n_vertices() == 0) throw fest::bad_input("mesh has no vertices ({})", path);
    for (auto eh : mesh.edges())
      if (mesh.is_boundary(eh)) throw fest::bad_input("mesh is not closed ({})", path);
  };
  return scene_from_json(doc, loader);
}

}  // namespace fest::lmfsim_tool
