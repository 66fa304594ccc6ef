#pragma once
// A random connected skeleton for softobj's property tests: a strip of 1-20 triangles
// from a random walk (fixed seed), each new vertex 4 units from the last edge's midpoint.
#include <random>

#include "softobj/field.hpp"

namespace fest::softobj::testing {

inline Skeleton random_strip(unsigned seed, int* triangle_count = nullptr) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> count(1, 20);
  const int n = count(rng);
  Skeleton s;
  s.vertices = {{0, 0, 0}, {4, 0, 0}};
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d a = s.vertices[s.vertices.size() - 2], b = s.vertices.back();
    Eigen::Vector3d step(u(rng), u(rng), 0.4 * u(rng));
    s.vertices.push_back(0.5 * (a + b) + 4 * step.normalized());
    s.triangles.push_back({static_cast<int>(s.vertices.size()) - 3, static_cast<int>(s.vertices.size()) - 2,
                           static_cast<int>(s.vertices.size()) - 1});
  }
  if (triangle_count) *triangle_count = n;
  return s;
}

}  // namespace fest::softobj::testing
