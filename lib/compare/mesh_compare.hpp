#pragma once
// Mesh comparison: symmetric surface distance by sampling, and the topology that a
// golden-file test should see unchanged (counts, genus, boundaries, manifoldness).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"

namespace fest::compare {

struct SurfaceDistance {
  double hausdorff = 0;  // max of the two one-sided maxima
  double rms = 0;        // root mean square over the samples of both sides
  double mean = 0;
  double max_a_to_b = 0;
  double max_b_to_a = 0;
  std::size_t samples_a = 0;
  std::size_t samples_b = 0;
  // Distances below this are floating-point noise of projecting a point onto its own
  // triangle and are reported as 0 (1e-12 of the larger bounding-box diagonal).
  double resolution = 0;
};

// Samples every vertex and `extra_samples` area-weighted random points (fixed seed) on
// each mesh, and measures each sample's distance to the other surface (exact
// point-triangle distance through an AABB tree; polygons are cut into triangles by
// core/polygon_triangulation.hpp: fans, ears where concave).
// The samples are split into fixed chunks whose partial sums are added in order, so
// the figures are identical for every thread count.
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, std::size_t extra_samples = 100000,
                                 std::uint64_t seed = 1, int threads = 1);

// Faces a mesh holds beside its halfedge structure (polygons OpenMesh refused: repeated
// vertices, complex edges, fewer than three vertices), as vertex indices. A file's
// meshes are compared with them: what the files hold, not what OpenMesh accepted.
using FaceList = std::vector<std::vector<int>>;

// As above, with each mesh's faces beside its halfedges taking part like its own faces
// (fans; faces of fewer than three vertices add their vertices as samples only).
SurfaceDistance surface_distance(const Mesh& a, const FaceList& beside_a, const Mesh& b, const FaceList& beside_b,
                                 std::size_t extra_samples = 100000, std::uint64_t seed = 1, int threads = 1);

struct MeshTopology {
  std::size_t vertices = 0;
  std::size_t faces = 0;              // halfedge faces plus faces beside them
  std::size_t faces_beside = 0;       // faces held beside the halfedge structure (not in the figures below)
  std::size_t edges = 0;
  std::size_t isolated_vertices = 0;
  std::size_t boundary_edges = 0;
  std::size_t boundary_loops = 0;
  std::size_t components = 0;         // connected components of faces
  std::size_t nonmanifold_vertices = 0;
  long euler = 0;                     // V - E + F over the vertices used by faces
  long genus = 0;                     // from euler = sum over components (2 - 2g - b)
  bool manifold() const noexcept { return nonmanifold_vertices == 0; }
  bool closed() const noexcept { return boundary_edges == 0; }
};

MeshTopology mesh_topology(const Mesh& mesh);
// Counts `beside` in faces and faces_beside; edges, boundaries, components, manifoldness
// and genus are those of the halfedge mesh.
MeshTopology mesh_topology(const Mesh& mesh, const FaceList& beside);

}  // namespace fest::compare
