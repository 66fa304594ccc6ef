#pragma once
// Transition refinement of one triangle towards finer neighbour tiles (docs/terrainlod.md §3
// step B, seed Figs. 7.6-7.9): points inserted on an edge of the triangle turn it into a
// fan from the opposite vertex; a triangle with two refined edges (a tile-corner triangle)
// is split in the fixed border order W, S, E, N, the second split fanning the one
// sub-triangle that still holds the whole second edge. Encoder, decoder and the error
// check all call this one function, so the 16 triangulations of a tile are the same
// everywhere by construction.

#include <array>
#include <vector>

namespace fest::terrainlod {

enum Side { kWest = 0, kSouth = 1, kEast = 2, kNorth = 3 };

struct EdgeInsert {
  int side = -1;               // tile border the edge lies on (-1: none)
  std::vector<int> points;     // vertex ids strictly inside the edge, ordered from t[k] to t[k+1]
};

// Triangle t (counter-clockwise vertex ids); inserts[k] refers to edge t[k] -> t[k+1].
// Appends the refined triangles (counter-clockwise) to `out`; only edges whose side bit is
// set in `mask` are refined.
void refine_triangle(const std::array<int, 3>& t, const std::array<EdgeInsert, 3>& inserts, unsigned mask,
                     std::vector<std::array<int, 3>>& out);

}  // namespace fest::terrainlod
