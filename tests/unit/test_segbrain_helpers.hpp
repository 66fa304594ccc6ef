#pragma once
// Shared helpers of the segbrain unit tests.

#include <cstddef>

#include "segbrain/grid.hpp"

namespace fest::segbrain::test_support {

// A grid of nx x ny x nz voxels with the given spacing in mm (identity orientation).
inline Grid grid(std::size_t nx, std::size_t ny, std::size_t nz, double sx = 1, double sy = 1, double sz = 1) {
  Grid g;
  g.n = {nx, ny, nz};
  g.spacing = {sx, sy, sz};
  return g;
}

}  // namespace fest::segbrain::test_support
