#pragma once
// A float32 scalar grid with its index -> world affine: what isosurf and volrender compute
// on (docs/isosurf.md "Conventions"). Samples x fastest: index = i + nx*(j + ny*k).

#include <array>
#include <cstddef>
#include <vector>

#include "core/volume.hpp"

namespace fest::volume_pyramid {

struct ScalarGrid {
  std::array<std::size_t, 3> dims{0, 0, 0};
  std::vector<float> values;
  // world = origin + axes * (i, j, k); axes is row-major 3x3, column c = world step of
  // index axis c (direction times spacing).
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 9> axes{1, 0, 0, 0, 1, 0, 0, 0, 1};

  std::size_t size() const noexcept { return dims[0] * dims[1] * dims[2]; }
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const noexcept { return i + dims[0] * (j + dims[1] * k); }
  float at(std::size_t i, std::size_t j, std::size_t k) const noexcept { return values[index(i, j, k)]; }

  std::array<double, 3> world(double i, double j, double k) const noexcept {
    return {origin[0] + axes[0] * i + axes[1] * j + axes[2] * k, origin[1] + axes[3] * i + axes[4] * j + axes[5] * k,
            origin[2] + axes[6] * i + axes[7] * j + axes[8] * k};
  }
  double determinant() const noexcept {
    const auto& a = axes;
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
  }
};

// float32 samples and axes = direction * diag(spacing) of an in-memory volume; the number
// of NaN samples found is returned in `nans` (they are copied as NaN).
ScalarGrid to_grid(const Volume& volume, std::size_t& nans);

// A copy surrounded by one layer of `value` on every side (isosurf --cap): the origin
// moves by one step back along each axis so world positions of the old samples stay.
ScalarGrid padded(const ScalarGrid& grid, float value);

}  // namespace fest::volume_pyramid
