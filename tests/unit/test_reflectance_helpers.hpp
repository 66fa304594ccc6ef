#pragma once
// Shared by the reflectance and brdffit geometry tests: meshes whose geometry is known exactly.

#include <array>
#include <cstdint>
#include <vector>

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

// A unit sphere: an octahedron subdivided `level` times, midpoints pushed out to radius 1
// (8 * 4^level triangles, no normals). Its silhouette from any side is a disc to within
// the chord error of the level.
inline reflectance::TriangleMesh octahedron_sphere(int level) {
  reflectance::TriangleMesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < level; ++l) {
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : m.triangles) {
      std::uint32_t mid[3];
      for (int k = 0; k < 3; ++k) {
        m.vertices.push_back((m.vertices[t[k]] + m.vertices[t[(k + 1) % 3]]).normalized());
        mid[k] = static_cast<std::uint32_t>(m.vertices.size() - 1);
      }
      next.push_back({t[0], mid[0], mid[2]});
      next.push_back({t[1], mid[1], mid[0]});
      next.push_back({t[2], mid[2], mid[1]});
      next.push_back({mid[0], mid[1], mid[2]});
    }
    m.triangles.swap(next);
  }
  return m;
}

}  // namespace fest::test
