#pragma once
// An indexed triangle surface: the output of the extractors and the input of the stats.

#include <array>
#include <cstdint>
#include <vector>

namespace fest::isosurface {

struct Surface {
  std::vector<float> xyz;                                 // 3 per vertex, world units
  std::vector<std::array<std::uint32_t, 3>> triangles;    // oriented: normal = outside
  std::vector<float> normals;                             // 3 per vertex when asked for (--normals), else empty
  std::size_t vertices() const noexcept { return xyz.size() / 3; }
};

}  // namespace fest::isosurface
