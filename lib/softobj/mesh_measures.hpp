#pragma once
// Integrals and checks of a closed triangle mesh (docs/softobj.md §5): enclosed volume by
// the divergence theorem, area, Euler characteristic, edge-manifold closure, chord stats.

#include "core/mesh.hpp"
#include "softobj/field.hpp"

namespace fest::softobj {

struct MeshMeasures {
  std::size_t vertices = 0, triangles = 0;
  double volume = 0, area = 0;
  int euler_characteristic = 0;
  bool closed = false;        // no boundary halfedges
  double max_edge = 0, min_angle_deg = 180, max_normal_angle_deg = 0;
};

// Uses the vertex normals stored in the mesh for the chord normal angles.
MeshMeasures measure(const TriMesh& mesh);

// max |f(v) - iso| / iso over the vertices.
double max_iso_error(const Field& field, const TriMesh& mesh, double iso);

// Largest distance from a triangle centroid to the iso-surface (Newton projection of the
// centroid along grad f): the deviation measure of the adaptivity comparison.
double max_centroid_deviation(const Field& field, const TriMesh& mesh, double iso);

// Largest distance to the iso-surface over a barycentric lattice of every triangle: the
// points (i, j, k) / order, i + j + k = order, the vertices excluded (order 4: 12 points
// per triangle, among them the centroid's neighbours and the edge midpoints). A denser
// measure than the centroid alone, so that a polygoniser refined by its centroids and
// edge midpoints is not judged on those points only (docs/softobj.md §6).
double max_sampled_deviation(const Field& field, const TriMesh& mesh, double iso, int order = 4);

}  // namespace fest::softobj
