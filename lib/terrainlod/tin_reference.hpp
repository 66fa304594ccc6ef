#pragma once
// A coarser mesh as the reference surface (docs/terrainlod.md §1, seed 7.2.1): level l is
// measured against the finished level-(l+2) base triangulations over its square, not the
// DEM, so the work per tile does not grow with the DEM's resolution, and the error against
// the DEM stays below (4/3) eps_l (eps_l + eps_(l+2) + eps_(l+4) + ...).
//
// The error of a triangle is the same exact vertical L-infinity distance as against the
// grid (triangle_error.hpp), evaluated on the overlay of the triangle with this mesh: its
// corners, the reference vertices inside it and the crossings of its edges with reference
// edges. A uniform grid of buckets over the region finds the vertices, edges and (for point
// location) triangles near a query.

#include <array>
#include <vector>

#include "terrainlod/triangle_error.hpp"

namespace fest::terrainlod {

class TinReference {
 public:
  // Triangles counter-clockwise seen from above with positive xy area, covering the
  // rectangle [x0, x1] x [y0, y1] (grid units) without overlaps; `bucket` = bucket side
  // (grid units, > 0).
  TinReference(std::vector<GridPoint> vertices, std::vector<std::array<int, 3>> triangles, int x0, int y0, int x1,
               int y1, int bucket);

  // Height at a point of the rectangle (the first triangle that contains it).
  double height_at(double x, double y) const;

  // The triangle's corners and the reference vertices inside or on it (the "samples" part).
  double samples_error(const GridPoint& a, const GridPoint& b, const GridPoint& c, double stop_above) const;
  // Crossings of segment p -> q with the reference's edges (end points excluded).
  double edge_error(const GridPoint& p, const GridPoint& q, double stop_above) const;
  double triangle_error(const GridPoint& a, const GridPoint& b, const GridPoint& c, double stop_above) const;

  std::size_t vertices() const { return vertices_.size(); }
  std::size_t triangles() const { return triangles_.size(); }

 private:
  int bucket_of(double x, double y) const;
  void bucket_range(double lo_x, double lo_y, double hi_x, double hi_y, int& bx0, int& by0, int& bx1, int& by1) const;

  std::vector<GridPoint> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 2>> edges_;
  int x0_, y0_, bucket_, nx_, ny_;
  // Per bucket, ids into vertices_ / triangles_ / edges_ (CSR: start offsets + items).
  std::vector<int> vertex_start_, vertex_items_, triangle_start_, triangle_items_, edge_start_, edge_items_;
};

}  // namespace fest::terrainlod
