#pragma once
// Greedy half-edge-collapse simplification of a DEM with a guaranteed vertical error
// (docs/terrainlod.md §2, the engine of `simplify` and of the tiles): start from a mesh
// within the bound (the finest triangulation, every sample a vertex and every cell split
// by one diagonal, or a coarse RTIN within the bound: rtin_start.hpp), repeatedly
// remove the vertex whose cheapest collapse onto a neighbour changes the surface least,
// where "least" is the exact vertical L-infinity distance of the new triangles from the
// reference surface (triangle_error.hpp), and stop when no collapse stays within the bound.
// Vertices never move (half-edge collapses), so every height stays a DEM sample, and
// every triangle of the result was measured against the reference when it was made: the
// bound holds for the whole mesh by construction, not by an estimate.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/progress_callback.hpp"
#include "terrainlod/height_grid.hpp"
#include "terrainlod/reference_surface.hpp"
#include "terrainlod/tin_reference.hpp"
#include "terrainlod/transition.hpp"
#include "terrainlod/triangle_error.hpp"

namespace fest::terrainlod {

// A triangulated irregular network in grid units: vertices are DEM samples (integer x, y),
// triangles counter-clockwise seen from above (north = +y).
struct Tin {
  std::vector<GridPoint> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// What the engine decimates from: the full lattice (every sample a vertex), or the
// coarse RTIN whose every triangle already meets the bound (rtin_start.hpp), which
// costs the engine a fraction of the work; the lattice is the fallback where the RTIN
// does not apply (a grid that is not square 2^k + 1) and the reference for validation.
enum class StartRule { lattice, rtin };

struct SimplifyOptions {
  double max_error = 0;  // vertical bound in height units (>= 0)
  DiagonalRule diagonal = DiagonalRule::shortest;
  StartRule start = StartRule::rtin;
  // Thousandths: the collapses are taken cheapest first, so the cost of the one taken
  // rises from 0 to the bound; the bar follows it (never going back).
  ProgressFn progress;
};

struct SimplifyResult {
  Tin mesh;
  std::size_t collapses = 0;
  double tolerance = 0;      // round-off allowance added to max_error (1e-9 x height range)
  double max_error = 0;      // largest error of a collapse that was taken
};

// The finest triangulation of the grid (what simplification starts from).
Tin finest_triangulation(const HeightGrid& grid, DiagonalRule diagonal);

// Simplifies the whole grid as one free tile: the four corners stay, border vertices only
// move along their border (the outline stays the DEM's rectangle), no xy rounding.
// Throws usage_error for a negative or non-finite bound.
SimplifyResult simplify_grid(const HeightGrid& grid, const SimplifyOptions& options);

// A tile as the engine sees it (docs/terrainlod.md §3): its square in grid units and the
// lattice step of the finer neighbour tiles. A triangle with an edge on a border that can
// face a finer neighbour is measured in all its transition variants (that edge split at
// the neighbour's lattice points, heights = DEM samples), so every one of the tile's 16
// triangulations stays within the bound, not only the base one.
struct TileFrame {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int fine_step = 0;      // grid units between the finer neighbours' border vertices; 0 = none
  unsigned refinable = 0; // bit per Side: a finer neighbour can exist across that border
};

// The points a finer neighbour inserts on the edges of triangle (a, b, c): for each edge
// on a refinable border, the fine lattice points strictly inside it (appended to `points`
// with ids from 3 on; ids 0..2 are a, b, c).
std::array<EdgeInsert, 3> border_inserts(const ReferenceSurface& ref, const TileFrame& frame, const GridPoint& a,
                                         const GridPoint& b, const GridPoint& c, std::vector<GridPoint>& points);

// Largest error of triangle (a, b, c) over all its transition variants in `frame`
// (stops early above `stop_above` like triangle_error).
double transition_error(const ReferenceSurface& ref, const TileFrame& frame, const GridPoint& a,
                        const GridPoint& b, const GridPoint& c, double stop_above);
// The same against a coarser mesh `ref`; `dem` gives the inserted border points' heights.
double transition_error(const TinReference& ref, const ReferenceSurface& dem, const TileFrame& frame,
                        const GridPoint& a, const GridPoint& b, const GridPoint& c, double stop_above);

// The engine on any start mesh (counter-clockwise triangles, a disc): `locked` vertices
// stay; other boundary vertices slide along the boundary; every new triangle (with its
// transition variants when `frame` is given) must stay within `limit` of `ref`.
SimplifyResult simplify_tin(const ReferenceSurface& ref, const Tin& start, const std::vector<std::uint8_t>& locked,
                            double limit, const TileFrame* frame);

// The same against a coarser mesh `ref` (the level-(l+2) reference); `dem` gives the
// heights of the finer neighbours' border points of the transition variants.
SimplifyResult simplify_tin(const TinReference& ref, const ReferenceSurface& dem, const Tin& start,
                            const std::vector<std::uint8_t>& locked, double limit, const TileFrame* frame);

// Largest vertical distance of a TIN from the reference surface, triangle by triangle.
double tin_error(const ReferenceSurface& reference, const Tin& tin);

}  // namespace fest::terrainlod
