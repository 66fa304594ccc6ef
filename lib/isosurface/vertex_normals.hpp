#pragma once
// Per-vertex normals of an extracted surface from the data (docs/isosurf.md "Vertex
// normals", `--normals`): n = -grad f / |grad f| at the vertex, grad f by central
// differences at the 8 samples around it, trilinearly interpolated (the same gradient as
// volrender's shading), mapped to world space by A^-T. Where the gradient vanishes the
// area-weighted mean of the adjacent triangles' normals is used instead.

#include "isosurface/surface.hpp"
#include "volume_pyramid/scalar_grid.hpp"

namespace fest::isosurface {

// Fills s.normals (3 floats per vertex, unit length; zero for a vertex of no triangle
// with a vanishing gradient). `grid` is the grid the surface was extracted from.
void add_gradient_normals(const volume_pyramid::ScalarGrid& grid, Surface& s, int threads);

}  // namespace fest::isosurface
