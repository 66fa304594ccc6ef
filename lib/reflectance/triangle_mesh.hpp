#pragma once
// The triangle mesh the renderer draws: flat arrays, no halfedge structure (the renderer
// only walks triangles). Tools convert fest::Mesh into it.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::reflectance {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3d> normals;  // unit, one per vertex (shading normals)
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Angle-weighted vertex normals (Thürmer & Wüthrich): each triangle adds its unit face
// normal times its interior angle at the vertex. Isolated vertices get +z.
void compute_vertex_normals(TriangleMesh& mesh);

// Centre and radius of a bounding sphere (the box centre and the farthest vertex).
void bounding_sphere(const TriangleMesh& mesh, Eigen::Vector3d& centre, double& radius);

// Length of the bounding-box diagonal (the scale of depth tolerances).
double bbox_diagonal(const TriangleMesh& mesh);

}  // namespace fest::reflectance
