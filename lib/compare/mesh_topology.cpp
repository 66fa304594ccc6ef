#include <numeric>
#include <vector>

#include "compare/mesh_compare.hpp"

namespace fest::compare {

namespace {

struct DisjointSets {
  std::vector<std::size_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

}  // namespace

MeshTopology mesh_topology(const Mesh& mesh) {
  MeshTopology t;
  t.vertices = mesh.n_vertices();
  t.faces = mesh.n_faces();
  t.edges = mesh.n_edges();
  for (auto v : mesh.vertices()) {
    if (mesh.is_isolated(v))
      ++t.isolated_vertices;
    else if (!mesh.is_manifold(v))
      ++t.nonmanifold_vertices;
  }
  for (auto e : mesh.edges())
    if (mesh.is_boundary(e)) ++t.boundary_edges;

  // Boundary loops: walk each unvisited boundary halfedge around its hole.
  std::vector<char> seen(mesh.n_halfedges(), 0);
  for (auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h) || seen[h.idx()]) continue;
    ++t.boundary_loops;
    auto cur = h;
    std::size_t guard = 0;
    do {
      seen[cur.idx()] = 1;
      cur = mesh.next_halfedge_handle(cur);
    } while (cur != h && ++guard <= mesh.n_halfedges());
  }

  DisjointSets sets(mesh.n_vertices());
  for (auto e : mesh.edges()) {
    auto h = mesh.halfedge_handle(e, 0);
    sets.unite(static_cast<std::size_t>(mesh.from_vertex_handle(h).idx()),
               static_cast<std::size_t>(mesh.to_vertex_handle(h).idx()));
  }
  for (auto v : mesh.vertices())
    if (!mesh.is_isolated(v) && sets.find(static_cast<std::size_t>(v.idx())) == static_cast<std::size_t>(v.idx()))
      ++t.components;

  const long used_vertices = static_cast<long>(t.vertices - t.isolated_vertices);
  t.euler = used_vertices - static_cast<long>(t.edges) + static_cast<long>(t.faces);
  // Each component contributes 2 - 2g - b to the Euler characteristic.
  t.genus = (2 * static_cast<long>(t.components) - static_cast<long>(t.boundary_loops) - t.euler) / 2;
  return t;
}

MeshTopology mesh_topology(const Mesh& mesh, const FaceList& beside) {
  MeshTopology t = mesh_topology(mesh);
  t.faces += beside.size();
  t.faces_beside = beside.size();
  return t;
}

}  // namespace fest::compare
