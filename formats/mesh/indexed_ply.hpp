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
#include <string_view>
#include <vector>

namespace fest::formats {

// xyz: 3 floats per vertex. Throws bad_input when a triangle names a vertex >= vertices.
std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles);

// The same with per-vertex float properties after x, y, z (one named array per scalar,
// each as long as the vertex count): what ParaView and fest's renderers colour by.
std::string write_indexed_ply(const std::vector<float>& xyz, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                              const std::vector<std::string>& scalar_names, const std::vector<std::vector<float>>& scalars);

// The same file for many vertex sets over one triangle list (facefit fit --batch): the
// header and the face block are encoded once, into a buffer kept between calls; each
// encode() only copies the positions in. Throws bad_input like write_indexed_ply.
class IndexedPlyEncoder {
 public:
  IndexedPlyEncoder(std::size_t vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles);
  // xyz: 3 floats per vertex. The view stays valid until the next encode().
  std::string_view encode(const float* xyz);
  std::size_t vertices() const noexcept { return vertices_; }

 private:
  std::string buffer_;  // header, vertex block, face block
  std::size_t header_ = 0, vertices_ = 0;
};

}  // namespace fest::formats
