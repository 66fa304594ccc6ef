#pragma once
// Closed genus-0 meshes built from their definitions, and checks written independently of
// lib/edgebreaker (std::map instead of sorted corner tables), for the edgebreaker tests.

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "edgebreaker/clers.hpp"

namespace fest::test::eb {

using fest::edgebreaker::Triangle;

struct Faces {
  std::vector<Triangle> triangles;
  int vertex_count = 0;
};

// The tetrahedron: vertices (0,0,0), (1,0,0), (0,1,0), (0,0,1), outward faces.
inline Faces tetrahedron() { return {{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}, 4}; }

// The face lists of CGAL's octahedron.off, icosahedron.off and cube.off (Debian
// libcgal-demo, the project's test data), whose strings an independent prototype recorded.
inline Faces cgal_octahedron() {
  return {{{1, 0, 4}, {4, 0, 3}, {3, 0, 2}, {2, 0, 1}, {1, 5, 2}, {2, 5, 3}, {3, 5, 4}, {4, 5, 1}}, 6};
}
inline Faces cgal_icosahedron() {
  return {{{1, 9, 0},  {10, 1, 0}, {5, 10, 0}, {4, 5, 0},  {9, 4, 0},  {8, 2, 3},  {4, 8, 3},
           {5, 4, 3},  {11, 5, 3}, {2, 11, 3}, {11, 2, 6}, {10, 11, 6}, {1, 10, 6}, {7, 1, 6},
           {2, 7, 6},  {11, 10, 5}, {9, 8, 4}, {7, 2, 8},  {9, 7, 8},  {1, 7, 9}},
          12};
}
inline Faces cgal_cube() {
  return {{{0, 1, 3}, {3, 1, 2}, {0, 4, 1}, {1, 4, 5}, {3, 2, 7}, {7, 2, 6},
           {4, 0, 3}, {7, 4, 3}, {6, 4, 7}, {6, 5, 4}, {1, 5, 6}, {2, 1, 6}},
          8};
}

// Two triangles glued along all three edges: the smallest closed genus-0 triangulation
// (n = 0 interior vertices, string "E").
inline Faces double_triangle() { return {{{0, 1, 2}, {0, 2, 1}}, 3}; }

// Icosahedron refined `levels` times by 1->4 midpoint subdivision: v = 10*4^k + 2, t = 20*4^k.
inline Faces subdivided_icosahedron(int levels) {
  Faces m = cgal_icosahedron();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      midpoint[key] = m.vertex_count;
      return m.vertex_count++;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : m.triangles) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

// The same surface with vertices renumbered, faces shuffled and each face's corners
// rotated (orientation kept), from a fixed seed.
inline Faces scrambled(const Faces& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<int> relabel(static_cast<std::size_t>(m.vertex_count));
  std::iota(relabel.begin(), relabel.end(), 0);
  std::shuffle(relabel.begin(), relabel.end(), rng);
  Faces out{{}, m.vertex_count};
  for (const Triangle& f : m.triangles) {
    const auto r = static_cast<int>(rng() % 3);
    out.triangles.push_back({relabel[f[r]], relabel[f[(r + 1) % 3]], relabel[f[(r + 2) % 3]]});
  }
  std::shuffle(out.triangles.begin(), out.triangles.end(), rng);
  return out;
}

// Oriented triangles as a sorted list, each rotated to start at its smallest vertex, so
// two lists compare equal iff they hold the same oriented faces.
inline std::vector<Triangle> canonical(std::vector<Triangle> triangles) {
  for (Triangle& f : triangles)
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

// An empty string if the triangles form one simple, closed, oriented, connected surface
// with Euler characteristic 2 on vertices 0..v-1; otherwise what is wrong.
inline std::string sphere_defect(const std::vector<Triangle>& triangles, int v) {
  std::map<std::pair<int, int>, int> directed;  // directed edge -> count
  std::vector<std::vector<int>> star(static_cast<std::size_t>(v));
  for (const Triangle& f : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      if (a < 0 || a >= v || a == b) return "bad index or degenerate face";
      ++directed[{a, b}];
      star[a].push_back(b);  // one outgoing edge per corner at a
    }
  for (const auto& [edge, count] : directed)
    if (count != 1 || directed.count({edge.second, edge.first}) != 1) return "edge not used once each way";
  // One fan per vertex: following "outgoing edge a->b, then the face across b->a" around a
  // must visit all of a's corners in one cycle.
  std::map<std::pair<int, int>, int> third;  // directed edge (a,b) -> third vertex of its face
  for (const Triangle& f : triangles)
    for (int k = 0; k < 3; ++k) third[{f[k], f[(k + 1) % 3]}] = f[(k + 2) % 3];
  for (int a = 0; a < v; ++a) {
    if (star[a].empty()) return "unused vertex";
    int b = star[a][0];
    std::size_t steps = 0;
    do {
      b = third[{a, b}];  // face (a, b, c): the next outgoing edge around a is a->c
      ++steps;
    } while (b != star[a][0] && steps <= star[a].size());
    if (steps != star[a].size()) return "non-manifold vertex";
  }
  // Connected through shared vertices (edge-connected follows for a manifold).
  std::vector<int> root(static_cast<std::size_t>(v));
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&](int x) {
    while (root[x] != x) x = root[x];
    return x;
  };
  for (const Triangle& f : triangles) {
    root[find(f[1])] = find(f[0]);
    root[find(f[2])] = find(f[0]);
  }
  for (int a = 0; a < v; ++a)
    if (find(a) != find(0)) return "more than one component";
  const long long e = static_cast<long long>(directed.size()) / 2;
  if (v - e + static_cast<long long>(triangles.size()) != 2) return "Euler characteristic is not 2";
  return "";
}

// Maps decoded vertex ids back to the input's through the encoder's visit order.
inline std::vector<Triangle> mapped(const std::vector<Triangle>& decoded, const std::vector<int>& order) {
  std::vector<Triangle> out;
  for (const Triangle& f : decoded) out.push_back({order.at(f[0]), order.at(f[1]), order.at(f[2])});
  return out;
}

}  // namespace fest::test::eb
