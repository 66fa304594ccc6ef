#pragma once
// The baseline polygoniser (`--method mc`, docs/softobj.md §3): f sampled on a regular grid over the
// skeleton's bounding box grown by rho + 2h, extracted with fest's exact marching cubes
// (lib/isosurface), every vertex then Newton-projected onto f = V*. Any topology; uniform
// resolution.

#include "core/mesh.hpp"
#include "softobj/field.hpp"

namespace fest::softobj_tool {

// Triangles OpenMesh's halfedge structure cannot hold (non-manifold configurations of the
// case table) are not added; their number goes to *dropped.
TriMesh marching_cubes(const softobj::Field& field, double iso, double rho, double h, std::size_t max_vertices,
                       std::size_t* dropped = nullptr);

}  // namespace fest::softobj_tool
