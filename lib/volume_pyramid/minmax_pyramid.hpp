#pragma once
// The min-max pyramid shared by isosurf (active cells) and volrender (empty-space
// skipping): docs/isosurf.md "Min-max octree". A pointerless octree over the cells of a
// grid: a node of level l covers 2^l x 2^l x 2^l cells starting at a multiple of 2^l and
// stores min and max of every sample of its CLOSED region (its corner samples included),
// so a node with min >= iso or max < iso holds no crossing of iso (Wilhelms & Van Gelder
// 1992). Levels below `finest_level` (default 3: blocks of 8^3 cells, ~0.4 % of the volume
// in extra floats) are not stored; their cells are read from the grid.

#include <array>
#include <cstddef>
#include <vector>

#include "volume_pyramid/scalar_grid.hpp"

namespace fest::volume_pyramid {

class MinMaxPyramid {
 public:
  MinMaxPyramid() = default;
  // Throws nothing; a grid with fewer than 2 samples along an axis gives an empty pyramid.
  MinMaxPyramid(const ScalarGrid& grid, int threads, int finest_level = 3);

  int finest_level() const noexcept { return finest_; }
  int root_level() const noexcept { return finest_ + static_cast<int>(levels_.size()) - 1; }
  // Nodes per axis of a stored level: ceil((n-1) / 2^l).
  std::array<std::size_t, 3> nodes(int level) const { return at(level).n; }
  float min(int level, std::size_t i, std::size_t j, std::size_t k) const { const auto& L = at(level); return L.lo[L.index(i, j, k)]; }
  float max(int level, std::size_t i, std::size_t j, std::size_t k) const { const auto& L = at(level); return L.hi[L.index(i, j, k)]; }
  // True when the node's closed region contains samples on both sides of iso
  // (min < iso <= max, the inside class being f >= iso).
  bool active(int level, std::size_t i, std::size_t j, std::size_t k, float iso) const {
    const auto& L = at(level);
    const std::size_t n = L.index(i, j, k);
    return L.lo[n] < iso && iso <= L.hi[n];
  }
  // Extra bytes held.
  std::size_t bytes() const noexcept;

 private:
  struct Level {
    std::array<std::size_t, 3> n{0, 0, 0};
    std::vector<float> lo, hi;
    std::size_t index(std::size_t i, std::size_t j, std::size_t k) const noexcept { return i + n[0] * (j + n[1] * k); }
  };
  const Level& at(int level) const { return levels_.at(static_cast<std::size_t>(level - finest_)); }
  int finest_ = 3;
  std::vector<Level> levels_;
};

}  // namespace fest::volume_pyramid
