#pragma once
// Reading a mesh whole, as both of fconv's jobs need it.

#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::fconv_tool {

// A mesh as read, with the faces OpenMesh's halfedge structure refused set to be written
// in their place; what the reader read leniently is said as a warning.
Mesh read_whole_mesh(const formats::Input& in);

}  // namespace fest::fconv_tool
