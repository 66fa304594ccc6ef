#pragma once
// One cell -> closed polygons ("loops") of edge crossings, built from face segments as
// docs/isosurf.md "Loop construction" describes: marching squares on each of the six
// faces (asymptotic decider or "separate" on ambiguous faces), segments oriented so the
// inside lies to their left when seen from outside the cell, chained by shared edges.
// The 256 corner cases x 64 face decisions are built once into a table; the extractor
// only looks up loops.
//
// Cube numbering: corner v = x + 2y + 4z (x, y, z in {0,1}); edge along x: y + 2z, along
// y: 4 + x + 2z, along z: 8 + x + 2y (the edge's lower corner gives the other two bits);
// face f = 2*axis + side, its outward normal (2*side - 1) e_axis. A corner is inside iff
// f >= iso; case bit v set iff corner v is inside.

#include <array>
#include <cstdint>
#include <vector>

namespace fest::isosurface {

enum class FaceRule { decider, separate };

struct CellLoops {
  std::uint8_t count = 0;                 // loops
  std::array<std::uint8_t, 4> length{};   // edges per loop
  std::array<std::uint8_t, 12> edges{};   // loops one after another
};

// Faces of `cube_case` whose corners form the ambiguous diagonal pattern (bit f).
std::uint8_t ambiguous_faces(int cube_case);

// The loops of a case with, for each ambiguous face f, bit f of `connected` telling
// whether the face's two inside corners are connected (the decider said s >= iso).
const CellLoops& cell_loops(int cube_case, int connected);

// The asymptotic decider of Nielson & Hamann (1991) on a face with corner values in square
// order q0 (0,0), q1 (1,0), q2 (1,1), q3 (0,1), all relative to iso (g = f - iso):
// the bilinear saddle value s satisfies s >= iso iff the product of the inside diagonal
// is >= the product of the outside diagonal. Only meaningful on an ambiguous face.
inline bool inside_connected(double g0, double g1, double g2, double g3) {
  return g0 >= 0 ? g0 * g2 >= g1 * g3 : g1 * g3 >= g0 * g2;
}

// Corners of face f in square order (for callers that evaluate the decider).
const std::array<std::uint8_t, 4>& face_corners(int face);
// Lower corner and axis of an edge.
struct EdgeInfo { std::uint8_t corner, axis; };
const EdgeInfo& edge_info(int edge);
// The two faces an edge lies on (bit f).
std::uint8_t edge_faces(int edge);

// The generic construction (used to fill the table and by the tests).
std::vector<std::vector<int>> build_loops(int cube_case, int connected);

}  // namespace fest::isosurface
