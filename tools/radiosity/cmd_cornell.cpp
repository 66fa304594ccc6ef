// radiosity cornell: the built-in Cornell box as a scene JSON.

#include "commands.hpp"
#include "core/file_io.hpp"
#include "radiosity/cornell.hpp"
#include "radiosity/scene_json.hpp"

namespace fest::radiosity_tool {

int run_cornell(const CornellArgs& args) {
  write_output(args.output, radiosity::encode_scene_json(radiosity::cornell_box(!args.no_blocks)));
  return 0;
}

}  // namespace fest::radiosity_tool
