#include "isosurface/mesh_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fest::isosurface {
namespace {

struct HalfEdge {
  std::uint64_t key;      // min << 32 | max
  std::uint32_t tri;
  bool forward;           // stored from min to max in the triangle's order
  bool operator<(const HalfEdge& o) const { return key != o.key ? key < o.key : tri < o.tri; }
};

std::vector<HalfEdge> half_edges(const Surface& s) {
  std::vector<HalfEdge> h;
  h.reserve(s.triangles.size() * 3);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& T = s.triangles[t];
    if (T[0] == T[1] || T[1] == T[2] || T[0] == T[2]) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = T[c], b = T[(c + 1) % 3];
      h.push_back({std::uint64_t{std::min(a, b)} << 32 | std::max(a, b), static_cast<std::uint32_t>(t), a < b});
    }
  }
  std::sort(h.begin(), h.end());
  return h;
}

struct UnionFind {
  std::vector<std::uint32_t> p;
  explicit UnionFind(std::size_t n) : p(n) { std::iota(p.begin(), p.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) p[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

std::vector<std::uint32_t> triangle_components(const Surface& s, std::vector<std::size_t>& sizes) {
  const auto h = half_edges(s);
  UnionFind uf(s.triangles.size());
  for (std::size_t a = 0, b; a < h.size(); a = b) {
    for (b = a + 1; b < h.size() && h[b].key == h[a].key; ++b) uf.unite(h[a].tri, h[b].tri);
  }
  std::vector<std::uint32_t> label(s.triangles.size());
  std::vector<std::uint32_t> root_label(s.triangles.size(), UINT32_MAX);
  sizes.clear();
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const std::uint32_t r = uf.find(static_cast<std::uint32_t>(t));
    if (root_label[r] == UINT32_MAX) {
      root_label[r] = static_cast<std::uint32_t>(sizes.size());
      sizes.push_back(0);
    }
    label[t] = root_label[r];
    ++sizes[label[t]];
  }
  return label;
}

MeshStats mesh_stats(const Surface& s, int) {
  MeshStats m;
  const std::size_t nv = s.vertices();
  m.triangles = s.triangles.size();
  std::vector<char> used(nv, 0);
  for (const auto& T : s.triangles) {
    for (auto v : T) used[v] = 1;
    if (T[0] == T[1] || T[1] == T[2] || T[0] == T[2]) ++m.degenerate_triangles;
    const float* a = &s.xyz[3 * std::size_t{T[0]}];
    const float* b = &s.xyz[3 * std::size_t{T[1]}];
    const float* c = &s.xyz[3 * std::size_t{T[2]}];
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    m.area += 0.5 * std::sqrt(x * x + y * y + z * z);
    // det[a b c] / 6
    m.volume += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
                 double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
                 double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) / 6.0;
  }
  m.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  m.unreferenced_vertices = nv - m.vertices;

  const auto h = half_edges(s);
  UnionFind uf(s.triangles.size());
  for (std::size_t a = 0, b; a < h.size(); a = b) {
    std::size_t fwd = 0;
    for (b = a; b < h.size() && h[b].key == h[a].key; ++b) {
      fwd += h[b].forward;
      if (b > a) uf.unite(h[a].tri, h[b].tri);
    }
    const std::size_t uses = b - a;
    ++m.edges;
    if (uses == 1) ++m.boundary_edges;
    else if (uses > 2) ++m.nonmanifold_edges;
    else if (fwd != 1) ++m.orientation_conflicts;
  }
  // Non-manifold vertices: the triangles around a vertex must form one fan (connected
  // through edges at that vertex). Count fans by a union-find over each vertex's corners.
  {
    std::vector<std::uint32_t> first(nv + 1, 0);
    for (const auto& T : s.triangles)
      for (auto v : T) ++first[v + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<std::uint32_t> tri_of(first.back()), fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      for (auto v : s.triangles[t]) tri_of[fill[v]++] = static_cast<std::uint32_t>(t);
    std::vector<std::uint32_t> parent;
    for (std::size_t v = 0; v < nv; ++v) {
      const std::uint32_t b = first[v], e = first[v + 1];
      if (e - b < 2) continue;
      parent.resize(e - b);
      std::iota(parent.begin(), parent.end(), 0u);
      auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
      };
      // two triangles at v sharing another vertex share an edge at v
      for (std::uint32_t p = b; p < e; ++p)
        for (std::uint32_t q = p + 1; q < e; ++q) {
          const auto& A = s.triangles[tri_of[p]];
          const auto& B = s.triangles[tri_of[q]];
          bool share = false;
          for (auto x : A)
            if (x != v)
              for (auto y : B) share |= x == y;
          if (share) {
            const auto ra = find(p - b), rb = find(q - b);
            if (ra != rb) parent[ra] = rb;
          }
        }
      std::size_t fans = 0;
      for (std::uint32_t p = 0; p < e - b; ++p) fans += find(p) == p;
      if (fans > 1) ++m.nonmanifold_vertices;
    }
  }
  std::vector<long long> comp_v, comp_e, comp_f;
  std::vector<std::uint32_t> root_label(s.triangles.size(), UINT32_MAX);
  std::vector<std::uint32_t> label(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto r = uf.find(static_cast<std::uint32_t>(t));
    if (root_label[r] == UINT32_MAX) {
      root_label[r] = static_cast<std::uint32_t>(comp_f.size());
      comp_v.push_back(0), comp_e.push_back(0), comp_f.push_back(0);
    }
    label[t] = root_label[r];
    ++comp_f[label[t]];
  }
  m.components = comp_f.size();
  m.euler = static_cast<long long>(m.vertices) - static_cast<long long>(m.edges) + static_cast<long long>(m.triangles);
  m.closed = m.triangles > 0 && m.boundary_edges == 0 && m.nonmanifold_edges == 0 && m.orientation_conflicts == 0 &&
             m.degenerate_triangles == 0;
  if (m.closed && m.nonmanifold_vertices == 0) {
    // chi = sum of chi_c; genus = sum of (2 - chi_c)/2 = C - chi/2 for closed orientable surfaces
    m.genus = static_cast<long long>(m.components) - m.euler / 2;
  }
  return m;
}

}  // namespace fest::isosurface
