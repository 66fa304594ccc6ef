// Building the corner table and rejecting every mesh outside the chapter's setting, so
// that the traversal may assume a closed, oriented genus-0 manifold and never check again.
#include "edgebreaker/corner_table.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/error.hpp"

namespace fest::edgebreaker {
namespace {

// Corner ids are ints; keep 3t (and the decoder's provisional ids) well inside int.
constexpr std::size_t max_triangles = static_cast<std::size_t>(std::numeric_limits<int>::max() / 8);

void check_indices(const std::vector<Triangle>& triangles, int vertex_count) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& f = triangles[t];
    for (int v : f)
      if (v < 0 || v >= vertex_count)
        throw bad_input("triangle {} refers to vertex {}, outside 0..{}", t, v, vertex_count - 1);
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
      throw bad_input("triangle {} ({} {} {}) is degenerate: it repeats a vertex", t, f[0], f[1], f[2]);
  }
}

// Pairs each directed edge with its reverse. On a closed oriented manifold every directed
// edge occurs exactly once and so does its reverse; anything else is named precisely.
void link_opposites(CornerTable& table) {
  const int n = table.corners();
  const auto key = [&](int from, int to) {
    return static_cast<std::uint64_t>(from) * static_cast<std::uint64_t>(table.vertex_count) +
           static_cast<std::uint64_t>(to);
  };
  // Corner c is opposite the edge V[next(c)] -> V[prev(c)].
  std::vector<std::pair<std::uint64_t, int>> edges(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) edges[static_cast<std::size_t>(c)] = {key(table.V[next(c)], table.V[prev(c)]), c};
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (edges[i].first == edges[i - 1].first) {
      const int c = edges[i].second;
      throw bad_input(
          "edge {}->{} occurs in triangles {} and {} in the same direction: a non-manifold edge or "
          "inconsistently oriented triangles",
          table.V[next(c)], table.V[prev(c)], edges[i - 1].second / 3, c / 3);
    }
  for (int c = 0; c < n; ++c) {
    const std::uint64_t reverse = key(table.V[prev(c)], table.V[next(c)]);
    const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(reverse, -1));
    if (it == edges.end() || it->first != reverse)
      throw bad_input("edge {}-{} of triangle {} has no triangle on its other side: the mesh is open",
                      table.V[next(c)], table.V[prev(c)], c / 3);
    table.O[c] = it->second;
  }
}

// Edge-manifold is not enough: two spheres touching at one vertex pass the edge test.
// Around a manifold vertex, next(O[next(c)]) visits all its corners in one cycle.
void check_vertex_fans(const CornerTable& table) {
  const int n = table.corners();
  std::vector<int> fans(static_cast<std::size_t>(table.vertex_count), 0);
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (int c = 0; c < n; ++c) {
    if (seen[c]) continue;
    ++fans[table.V[c]];
    int k = c;
    do {  // O is an involution on a closed mesh, so this permutation returns to c
      seen[k] = 1;
      k = next(table.O[next(k)]);
    } while (k != c);
  }
  for (int v = 0; v < table.vertex_count; ++v) {
    if (fans[v] == 0) throw bad_input("vertex {} is used by no triangle", v);
    if (fans[v] > 1)
      throw bad_input("vertex {} is non-manifold: its triangles form {} separate fans", v, fans[v]);
  }
}

void check_opposites(const CornerTable& table) {
  const int n = table.corners();
  for (int c = 0; c < n; ++c) {
    const int d = table.O[static_cast<std::size_t>(c)];
    if (d < 0 || d >= n || d / 3 == c / 3 || table.O[static_cast<std::size_t>(d)] != c)
      throw bad_input("corner {} has no proper opposite corner", c);
    if (table.V[static_cast<std::size_t>(next(c))] != table.V[static_cast<std::size_t>(prev(d))] ||
        table.V[static_cast<std::size_t>(prev(c))] != table.V[static_cast<std::size_t>(next(d))])
      throw bad_input("corners {} and {} are opposite across different edges", c, d);
  }
}

void check_connected(const CornerTable& table) {
  const int t = table.triangles();
  std::vector<char> reached(static_cast<std::size_t>(t), 0);
  std::vector<int> todo{0};
  reached[0] = 1;
  int count = 1;
  while (!todo.empty()) {
    const int f = todo.back();
    todo.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int g = table.O[3 * f + k] / 3;
      if (!reached[g]) {
        reached[g] = 1;
        ++count;
        todo.push_back(g);
      }
    }
  }
  if (count != t) {
    const auto first = std::find(reached.begin(), reached.end(), 0) - reached.begin();
    throw bad_input("the mesh has more than one connected component (triangle {} is not connected to triangle 0); "
                    "only one closed surface is supported",
                    first);
  }
}

}  // namespace

void check_closed_manifold(const CornerTable& table) {
  for (int v : table.V)
    if (v < 0 || v >= table.vertex_count) throw bad_input("a corner refers to vertex {}, outside 0..{}", v, table.vertex_count - 1);
  for (int c = 0; c < table.corners(); c += 3)
    if (table.V[static_cast<std::size_t>(c)] == table.V[static_cast<std::size_t>(c + 1)] ||
        table.V[static_cast<std::size_t>(c + 1)] == table.V[static_cast<std::size_t>(c + 2)] ||
        table.V[static_cast<std::size_t>(c + 2)] == table.V[static_cast<std::size_t>(c)])
      throw bad_input("triangle {} repeats a vertex", c / 3);
  check_opposites(table);
  check_vertex_fans(table);
}

CornerTable build_closed_corner_table(const std::vector<Triangle>& triangles, int vertex_count) {
  if (vertex_count < 0) throw bad_input("vertex count {} is negative", vertex_count);
  if (triangles.empty()) throw bad_input("the mesh has no triangles");
  if (triangles.size() > max_triangles)
    throw bad_input("the mesh has {} triangles, more than the {} supported", triangles.size(), max_triangles);
  check_indices(triangles, vertex_count);

  CornerTable table;
  table.vertex_count = vertex_count;
  table.V.reserve(3 * triangles.size());
  for (const Triangle& f : triangles) table.V.insert(table.V.end(), f.begin(), f.end());
  table.O.assign(table.V.size(), -1);

  link_opposites(table);
  check_vertex_fans(table);
  return table;
}

CornerTable build_corner_table(const std::vector<Triangle>& triangles, int vertex_count) {
  CornerTable table = build_closed_corner_table(triangles, vertex_count);
  check_connected(table);

  // Closed, connected and oriented: Euler's formula gives the genus. e = 3t/2 because every
  // edge has two sides, so chi = v - t/2.
  const long long chi = static_cast<long long>(vertex_count) - static_cast<long long>(table.triangles()) / 2;
  if (chi != 2)
    throw bad_input("the surface has genus {} (Euler characteristic {}); only genus 0 is supported", (2 - chi) / 2,
                    chi);
  return table;
}

}  // namespace fest::edgebreaker
