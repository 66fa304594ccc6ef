#pragma once
// Exact vertical L-infinity distance between one triangle of a coarse mesh (vertices on
// DEM samples) and the reference surface (docs/terrainlod.md §1: computed exactly on the
// overlay of the two triangulations). The difference of two piecewise-linear functions is
// linear on every cell of their overlay, so its maximum is at an overlay vertex: a DEM
// sample inside or on the triangle, or a crossing of a triangle edge with a grid line
// (x = k, y = k) or a cell diagonal (x + y = k, x - y = k). All of these are visited.

#include "terrainlod/reference_surface.hpp"

namespace fest::terrainlod {

struct GridPoint {
  double x = 0, y = 0, z = 0;  // grid units (integers for DEM samples), height
};

// Twice the signed xy area (positive when a, b, c run counter-clockwise seen from above).
inline double twice_area(const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

// The maximum of |triangle(x, y) - reference(x, y)| over the triangle, or a value above
// `stop_above` as soon as one is found (callers that only need "within the bound?" save
// the rest of the scan). The triangle must have positive xy area.
double triangle_error(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b, const GridPoint& c,
                      double stop_above);

// The two halves of triangle_error, for callers that remember edges shared by several
// triangles: the samples inside or on the triangle, and the crossings of one edge with
// the reference's edges (the segment's end points excluded).
double triangle_samples_error(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b,
                              const GridPoint& c, double stop_above);
double edge_error(const ReferenceSurface& ref, const GridPoint& p, const GridPoint& q, double stop_above);

}  // namespace fest::terrainlod
