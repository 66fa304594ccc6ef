#pragma once
// Taubin's lambda|mu smoothing (Taubin, "A signal processing approach to fair surface
// design", SIGGRAPH 1995; docs/isosurf.md "Smoothing", `--smooth K`): each iteration moves
// every free vertex by lambda times the umbrella Laplacian (mean of its neighbours minus
// itself), then by mu < -lambda times the new Laplacian, a low-pass filter that does not
// shrink the surface the way plain Laplacian smoothing does. Vertices on boundary or
// non-manifold edges stay fixed.

#include "isosurface/surface.hpp"

namespace fest::isosurface {

void taubin_smooth(Surface& s, int iterations, double lambda = 0.5, double mu = -0.53);

}  // namespace fest::isosurface
