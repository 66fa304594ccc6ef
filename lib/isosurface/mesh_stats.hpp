#pragma once
// Topology and measures of any indexed triangle mesh (docs/isosurf.md "Stats"): what CI
// gates on. Edges are undirected vertex pairs; an edge used by one triangle is a boundary
// edge, by more than two a non-manifold edge; an edge used twice in the same direction is
// an orientation conflict. Closed (watertight) = no boundary, no non-manifold edge, no
// conflict. Area and the signed enclosed volume (divergence theorem, sum of det/6 over the
// triangles; meaningful when closed) in double precision, in triangle order.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "isosurface/surface.hpp"

namespace fest::isosurface {

struct MeshStats {
  std::size_t vertices = 0;          // referenced by a triangle
  std::size_t unreferenced_vertices = 0;
  std::size_t triangles = 0;
  std::size_t degenerate_triangles = 0;  // a vertex repeated
  std::size_t edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t nonmanifold_edges = 0;
  std::size_t orientation_conflicts = 0;
  std::size_t nonmanifold_vertices = 0;  // more than one fan of triangles around the vertex
  std::size_t components = 0;        // connected by shared edges
  long long euler = 0;               // V - E + F
  long long genus = -1;              // sum over components of (2 - chi_c)/2 when closed; -1 otherwise
  bool closed = false;
  double area = 0;
  double volume = 0;
};

MeshStats mesh_stats(const Surface& surface, int threads = 1);

// Connected components (by shared edges) of the triangles: a label per triangle, labels
// numbered by first triangle, and the size of each component.
std::vector<std::uint32_t> triangle_components(const Surface& surface, std::vector<std::size_t>& sizes);

}  // namespace fest::isosurface
