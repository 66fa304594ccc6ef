#pragma once
// Exact (unoccluded) form factors of planar polygons (docs/radiosity.md §3):
// the point-to-polygon contour integral of Lambert/Nusselt,
//
//   F_{dy->P} = (1/2pi) sum_k gamma_k n_y . (R_k x R_k+1) / |R_k x R_k+1|,
//
// after clipping P to the half-space in front of y, and the area-to-area form factor
// F_{A->B} = (1/A) int_A F_{dA->B} dA by Gauss-Legendre quadrature over A.

#include <Eigen/Core>

#include "radiosity/model.hpp"

namespace fest::radiosity {

double point_polygon_ff(const Eigen::Vector3d& y, const Eigen::Vector3d& normal, const Polygon& poly);

// `cells` x `cells` sub-cells of A, each with 4 x 4 Gauss points (the integrand has a
// logarithmic edge singularity where A and B touch; the cells localise it).
double polygon_polygon_ff(const Polygon& a, const Polygon& b, int cells = 24);

}  // namespace fest::radiosity
