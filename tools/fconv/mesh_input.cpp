#include "mesh_input.hpp"

#include <string>

#include "core/tool_main.hpp"

namespace fest::fconv_tool {

using namespace fest::formats;

Mesh read_whole_mesh(const Input& in) {
  Mesh mesh = parse(in, read_mesh);
  for (const std::string& w : read_warnings(mesh)) warn("fconv", w + " (" + in.name + ")");
  carry_skipped_faces(mesh);
  return mesh;
}

}  // namespace fest::fconv_tool
