#pragma once
// Writing softobj's triangle meshes through formats/mesh, with vertex normals.

#include <string>

#include "core/mesh.hpp"
#include "formats/detect.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::softobj_tool {

struct MeshTarget {
  std::string path;
  formats::OutputFormat format;
  formats::MeshWriteOptions options;
};

// From -o and --to (ply, plya, obj, off, stl); standard output defaults to binary PLY.
MeshTarget mesh_target(const std::string& output, const std::string& to);
void write_trimesh(const TriMesh& mesh, const MeshTarget& target);

}  // namespace fest::softobj_tool
