#pragma once
// Writing a model level as a mesh: binary PLY with the vertex properties u, v (material
// coordinates, double) and the face property level (bisections, uchar); ascii PLY, OBJ
// and OFF without them (docs/feshape.md §4).

#include <string>

#include "feshape/model.hpp"

namespace fest::feshape_tool {

struct MeshTarget {
  std::string path;
  std::string format;  // ply, plya, obj, off
};

// From -o and --to; standard output defaults to binary PLY. Usage error for other formats.
MeshTarget mesh_target(const std::string& output, const std::string& to);
// The bytes of the model's mesh in the target's format.
std::string encode_model(const feshape::Model& m, const MeshTarget& target);

}  // namespace fest::feshape_tool
