#pragma once
// Point location: a uniform bin grid over the cells' bounding boxes for the first cell of
// a path (the only global search the LEM needs, docs/lemtrace.md §4), and a walk through face
// neighbours towards the most negative barycentric coordinate for the Runge-Kutta
// methods (docs/lemtrace.md §4), whose every evaluation of v needs the cell again.

#include <cstdint>
#include <vector>

#include "lemtrace/tet_mesh.hpp"

namespace fest::lemtrace {

Eigen::Vector4d barycentric(const TetMesh& mesh, int32_t cell, const Vec3& x);

class CellLocator {
 public:
  explicit CellLocator(const TetMesh& mesh);
  // A cell containing x (barycentric coordinates >= -1e-12), or -1.
  int32_t locate(const Vec3& x) const;
  // From `start`, walk at most 64 steps; falls back to locate(). `calls` counts the
  // cells tested; `beta`, when given, receives x's barycentric coordinates in the cell
  // found (the walk's own inside test computed them: interpolation needs no more).
  int32_t walk(int32_t start, const Vec3& x, int64_t* calls, Eigen::Vector4d* beta = nullptr) const;
  std::size_t bytes() const noexcept { return (start_.size() + cells_.size()) * sizeof(int32_t); }

 private:
  const TetMesh& mesh_;
  Vec3 lo_, inv_size_;
  int n_[3] = {1, 1, 1};
  std::vector<uint32_t> start_;
  std::vector<int32_t> cells_;
  std::size_t bin(int i, int j, int k) const { return (static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i; }
};

}  // namespace fest::lemtrace
