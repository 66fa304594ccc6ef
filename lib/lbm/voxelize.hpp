#pragma once
// Triangle meshes to solid flags (docs/lbmsim.md 2.8): ray parity along z through the
// node centres (inside iff an odd number of crossings lies below the centre), after an
// optional uniform fit of the mesh into a region of the lattice.

#include <array>
#include <cstdint>
#include <vector>

#include "lbm/geometry.hpp"

namespace fest::lbm {

struct TriangleSoup {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Edges used by exactly one triangle, and edges used by more than two.
struct EdgeCount {
  std::size_t boundary = 0, nonmanifold = 0;
};
EdgeCount count_open_edges(const TriangleSoup& mesh);

struct VoxelizeOptions {
  bool fit_box = true;
  double margin = 2.0;                        // cells
  std::array<double, 6> region{0, 0, 0, 0, 0, 0};  // lo, hi in lattice coordinates; all 0: the whole lattice
  std::uint8_t flag = 1;
};

// Marks the nodes inside the mesh with options.flag (nodes already solid keep their id).
// Returns the number of nodes marked. Throws Status::bad_input for an empty mesh.
std::size_t voxelize(const TriangleSoup& mesh, const VoxelizeOptions& options, Flags& flags);

}  // namespace fest::lbm
