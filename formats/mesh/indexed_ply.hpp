#pragma once
// Binary little-endian PLY written straight from arrays (float32 positions, triangles),
// without building a mesh first: the fast path for tools that emit large meshes many
// times (facefit writes a 76 000-vertex face in a few milliseconds this way; building the
// OpenMesh structure alone takes ~100 ms). The file is an ordinary PLY that read_mesh
// and every other reader accept.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fest::formats {

// xyz: 3 floats per vertex. Throws bad_input when a triangle names a vertex >= vertices.
std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace fest::formats
