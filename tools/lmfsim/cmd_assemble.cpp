// lmfsim assemble: the initial state projected onto the constraints, as scene JSON.
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/table/table_io.hpp"
#include "lmfsim/scene_json.hpp"
#include "lmfsim/system.hpp"

namespace fest::lmfsim_tool {

using namespace fest::lmfsim;

int cmd_assemble() {
  // The scene JSON comes on standard input.
  const std::string scene_bytes = fest::read_input("-");
  nlohmann::json doc = fest::formats::read_json(scene_bytes);
  Scene scene = load_scene(scene_bytes);
  scene.sim.stab = Stabilization::project;
  System sys(std::move(scene));
  Eigen::VectorXd s = sys.initial_state();
  sys.project(0, s);
  const double res = sys.max_violation(0, s);
  if (!(res <= 1e-9 * sys.length_scale()))
    throw fest::runtime_failure("cannot assemble: |C| = {:.3g} after projection (conflicting constraints?)", res);
  const auto& bodies = sys.scene().bodies;
  std::vector<Vec3> pos, vel, omega;
  std::vector<Quat> quat;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyKin k = sys.kinematics(static_cast<int>(b), s);
    pos.push_back(k.p);
    vel.push_back(k.v);
    omega.push_back(k.w);
    quat.push_back(sys.orientation(static_cast<int>(b), s));
  }
  write_state(doc, sys.scene(), pos, quat, vel, omega);
  fest::write_output("-", fest::formats::write_json(doc));
  return 0;
}

}  // namespace fest::lmfsim_tool
