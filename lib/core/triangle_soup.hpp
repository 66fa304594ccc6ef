#pragma once
// An indexed triangle soup with optional per-vertex attributes: the plain form in which a
// mesh travels between formats/ (which reads and writes files) and the domain libraries
// that code triangles (lib/edgebreaker). No connectivity rules: faces may be
// non-manifold, repeat vertices or leave vertices unused.

#include <array>
#include <cstdint>
#include <vector>

namespace fest {

struct TriangleSoup {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<int, 3>> triangles;  // indices into positions
  // Per-vertex attributes: each empty, or one entry per position.
  std::vector<std::array<double, 3>> normals;
  std::vector<std::array<std::uint8_t, 3>> colors;
  std::vector<std::array<double, 2>> texcoords;
};

}  // namespace fest
