#pragma once
// The reference surface: the piecewise-linear interpolant of the DEM on its finest
// triangulation, every grid cell split by one diagonal (docs/terrainlod.md §1). Coordinates
// here are grid units (i east, j north); the vertical error is invariant under the affine
// map to world x, y, so all error measurement happens in these units.

#include <cstdint>
#include <vector>

#include "terrainlod/height_grid.hpp"

namespace fest::terrainlod {

enum class DiagonalRule {
  shortest,   // the diagonal whose 3-D length is shorter (smaller height difference)
  alternate,  // checkerboard of the two directions
  ne,         // always south-west -> north-east
};

class ReferenceSurface {
 public:
  ReferenceSurface(const HeightGrid& grid, DiagonalRule rule);

  int width() const { return grid_->width; }
  int height() const { return grid_->height; }
  double sample(int i, int j) const { return grid_->at(i, j); }
  const HeightGrid& grid() const { return *grid_; }
  // True when cell (i, j) (south-west corner (i, j)) is split by the SW-NE diagonal.
  bool ne_diagonal(int i, int j) const { return ne_[static_cast<std::size_t>(j) * (width() - 1) + i] != 0; }
  // Height of the interpolant at (x, y) inside [0, W-1] x [0, H-1].
  double height_at(double x, double y) const;

 private:
  const HeightGrid* grid_;
  std::vector<std::uint8_t> ne_;
};

}  // namespace fest::terrainlod
