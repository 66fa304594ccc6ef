#pragma once
// An adaptive start mesh for the collapse engine (simplify.hpp): the coarsest right-
// triangulated irregular network (RTIN: recursive longest-edge bisection of the square's
// two half-squares, the hierarchy of Evans, Kirkpatrick & Townsend's right-triangulated
// networks as @mapbox/martini builds it) on a square lattice whose every triangle already
// meets the engine's bound, so that the engine decimates from a mesh about twice its final
// size instead of from the full lattice (greedy decimation costs about
// area x ln(start / final vertices)).
//
// Every triangle of the hierarchy is measured exactly with the caller's measure (the one
// the engine uses, transition variants included), bottom-up; a triangle is "over" when it
// or any descendant is over the limit, where the flag lives on the midpoint of the
// hypotenuse, so the two triangles sharing a hypotenuse split together (Martini's trick)
// and the top-down selection yields a conforming mesh. Locked lattice points are forced in
// as vertices the same way (their flag is set). No triangle is accepted by an estimate:
// every triangle of the result was measured within the limit.
//
// The smallest RTIN triangles halve a lattice cell along a fixed diagonal; where that
// diagonal is over the limit, both halves' parents are split and the cell takes the other
// diagonal (measured too). Where neither diagonal fits, there is no RTIN start mesh.

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

struct RtinStart {
  Tin tin;                            // counter-clockwise triangles, heights = DEM samples
  std::vector<std::uint8_t> locked;   // per vertex of `tin`: a locked lattice point
  std::size_t measured = 0;           // triangles measured exactly (statistics)
  std::size_t flipped_cells = 0;      // lattice cells that took the other diagonal
};

// `locked_points`: (n + 1)^2 flags, row-major from the south-west lattice point; every
// flagged point is a vertex of the result (and flagged in RtinStart::locked). Heights are
// `dem.sample` at the lattice points. Returns nullopt where some lattice cell fits the
// limit with neither diagonal (the lattice mesh would not fit either). Throws usage_error
// for a lattice that is not a power of two or not inside the DEM.
std::optional<RtinStart> rtin_start_mesh(const ReferenceSurface& dem, const SquareLattice& lattice,
                                         const std::vector<std::uint8_t>& locked_points, double limit,
                                         const TriangleMeasure& measure);

}  // namespace fest::terrainlod
