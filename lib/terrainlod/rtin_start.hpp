#pragma once
// An adaptive start mesh for the collapse engine (simplify.hpp): a coarse right-
// triangulated irregular network (RTIN: recursive longest-edge bisection of the square's
// two half-squares, the hierarchy @mapbox/martini uses) on a square lattice whose every
// triangle already meets the engine's bound, so that the engine decimates from a mesh
// near its final size instead of from the full lattice (greedy decimation costs about
// area x ln(start / final vertices)).
//
// Top-down: a triangle of the current mesh is measured exactly with the caller's measure
// (the engine's own, transition variants included); one over the limit is split, together
// with the triangle across its hypotenuse and, so that those exist, their ancestors (the
// closure that keeps an RTIN conforming: no T-junctions); passes repeat until nothing
// changes. Locked points lie on the lattice's border: a triangle with border edges is
// measured and kept as the fan that joins its opposite corner to every locked point on
// them (the transition refinement of transition.hpp), so the border keeps all of them
// without forcing a band of small triangles along it. No triangle is accepted by an
// estimate: every triangle of the result was measured within the limit.
//
// The smallest RTIN triangles halve a lattice cell along a fixed diagonal; where that
// half is over the limit, the cell takes the other diagonal (measured too; the other
// half's parent is split so both halves exist). Where neither fits, there is no RTIN
// start mesh.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "terrainlod/reference_surface.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod/triangle_error.hpp"

namespace fest::terrainlod {

// The square lattice of (n + 1)^2 DEM samples `step` grid units apart from (x0, y0);
// n a power of two (>= 1).
struct SquareLattice {
  int x0 = 0, y0 = 0;
  int n = 1;
  int step = 1;
};

// The error of a counter-clockwise triangle as the engine measures it; may stop early
// with any value above `stop_above`.
using TriangleMeasure = std::function<double(const GridPoint&, const GridPoint&, const GridPoint&, double stop_above)>;

// The measure's reference surface at a point (grid units): the lower bound that rejects
// most over-limit triangles before their exact measurement (empty: measure everything).
using PointHeight = std::function<double(double x, double y)>;

struct RtinStart {
  Tin tin;                            // counter-clockwise triangles, heights = DEM samples
  std::vector<std::uint8_t> locked;   // per vertex of `tin`: a locked lattice point
  std::size_t measured = 0;           // triangles measured exactly (statistics)
  std::size_t rejected = 0;           // triangles rejected by the lower bound alone
  std::size_t flipped_cells = 0;      // lattice cells that took the other diagonal
};

// `locked_points`: (n + 1)^2 flags, row-major from the south-west lattice point, set on
// border points only; every flagged point is a vertex of the result (and flagged in
// RtinStart::locked). Heights are `dem.sample` at the lattice points. Returns nullopt
// where some lattice cell fits the limit with neither diagonal (the lattice mesh would not
// fit either). `reference_height`, where given, must be the surface `measure` measures
// against: a triangle (or a piece of its border fan) whose plane misses it by more than
// the limit at its centroid or an edge midpoint is over without the exact measurement (a
// lower bound: it only rejects, so the result is the same with or without it). Throws usage_error for a lattice that is not a
// power of two or not inside the DEM, or a locked point off the border.
std::optional<RtinStart> rtin_start_mesh(const ReferenceSurface& dem, const SquareLattice& lattice,
                                         const std::vector<std::uint8_t>& locked_points, double limit,
                                         const TriangleMeasure& measure, const PointHeight& reference_height = {});

}  // namespace fest::terrainlod
