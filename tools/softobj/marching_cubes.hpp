#pragma once
// The baseline polygoniser (docs/softobj.md §3.6): f sampled on a regular grid over the
// skeleton's bounding box grown by rho + 2h, extracted with VTK's flying edges, every
// vertex then Newton-projected onto f = V*. Any topology; uniform resolution.

#include "core/mesh.hpp"
#include "softobj/field.hpp"

namespace fest::softobj_tool {

TriMesh marching_cubes(const softobj::Field& field, double iso, double rho, double h, std::size_t max_vertices);

}  // namespace fest::softobj_tool
