#pragma once
// The canonical voxel grid the operators work on: axes point to anatomical Right,
// Anterior, Superior (docs/segbrain.md), so "axial slice" means constant z. Images are float,
// masks uint8 0/1, both x fastest.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fest::segbrain {

struct Grid {
  std::array<std::size_t, 3> n{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};  // mm
  std::size_t size() const noexcept { return n[0] * n[1] * n[2]; }
  std::size_t index(std::size_t x, std::size_t y, std::size_t z) const noexcept { return x + n[0] * (y + n[1] * z); }
  double voxel_ml() const noexcept { return spacing[0] * spacing[1] * spacing[2] / 1000.0; }
};

using Image = std::vector<float>;
using Mask = std::vector<std::uint8_t>;

}  // namespace fest::segbrain
