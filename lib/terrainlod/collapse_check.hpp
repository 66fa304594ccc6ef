#pragma once
// Whether a half-edge collapse keeps a triangle mesh a manifold disc: OpenMesh's
// TriConnectivity::is_collapse_ok (the same four conditions), with the one-ring marks kept
// here between calls. The library's version looks its status property up by name on
// every call (string compares and a temporary string): in the collapse engine, which asks
// once per measured candidate, that was a third of all instructions.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"

namespace fest::terrainlod {

class CollapseCheck {
 public:
  explicit CollapseCheck(std::size_t vertices) : mark_(vertices, 0) {}

  // True when collapsing v0 -> v1 (the half-edge's from- onto its to-vertex) is allowed:
  // neither side's triangle has both its other edges on the boundary, the two opposite
  // corners differ, v0 and v1 share no neighbour but those corners (link condition), and
  // an inner edge does not join two boundary vertices. The half-edge must be live (not
  // deleted): OpenMesh's deleted checks are left out, as its status() accessor looks the
  // property up by name too.
  bool collapse_ok(const TriMesh& m, TriMesh::HalfedgeHandle v0v1);

 private:
  std::vector<std::uint32_t> mark_;  // == epoch_: a neighbour of v1 in the current check
  std::uint32_t epoch_ = 0;
};

}  // namespace fest::terrainlod
