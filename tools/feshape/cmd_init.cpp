// feshape init: the initial model (lat-long mesh on the global shape) as a mesh.
#include "commands.hpp"
#include "core/file_io.hpp"
#include "model_args.hpp"
#include "model_output.hpp"

namespace fest::feshape_tool {

int run_init(const InitArgs& a) {
  const MeshTarget target = mesh_target(a.output, a.to);
  const feshape::Model m = model_from_args(a.model);
  write_output(target.path, encode_model(m, target));
  return 0;
}

}  // namespace fest::feshape_tool
