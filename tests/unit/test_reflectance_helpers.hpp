#pragma once
// Shared by the reflectance and brdffit geometry tests: meshes whose geometry is known exactly.

#include <cstdint>

#include "reflectance/triangle_mesh.hpp"

namespace fest::test {

// A square [-s, s]^2 in the plane z = h, split into 2 n^2 triangles, normals +z.
inline reflectance::TriangleMesh plane(double s, double h, int n) {
  reflectance::TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.vertices.emplace_back(-s + 2 * s * i / n, -s + 2 * s * j / n, h);
      m.normals.emplace_back(0, 0, 1);
    }
  auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

}  // namespace fest::test
