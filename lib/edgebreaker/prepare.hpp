#pragma once
// Making any triangle list something the traversal takes (docs/ebcode.md §5;
// project engineering, the chapter covers planar triangulations only): degenerate faces dropped,
// edges paired without flipping any face (non-manifold edges and inconsistent orientation
// become boundary), vertices split into manifold fans (stitch pairs remember the copies),
// every boundary loop closed by a dummy vertex (Rossignac), unreferenced vertices set aside.

#include <cstddef>
#include <vector>

#include "edgebreaker/clers.hpp"
#include "edgebreaker/corner_table.hpp"

namespace fest::edgebreaker {

struct PreparedMesh {
  // Closed and manifold, every vertex used. Vertices: [0, input) the input's (those used
  // by some face), [input, input + copies) copies made by vertex splitting, then one dummy
  // per hole. Triangles: the kept input faces in input order, then the dummy triangles.
  CornerTable table;
  int input_vertices = 0;
  std::vector<int> copy_of;  // copy input_vertices + k is a copy of input vertex copy_of[k]
  int first_dummy = 0;       // vertices >= first_dummy are dummies
  std::vector<int> face_of;  // per table triangle: the input face, or -1 for a dummy triangle
  std::vector<int> isolated;  // input vertices no kept face uses, ascending
  std::size_t dropped_degenerate = 0;  // faces that repeat a vertex
  std::size_t holes = 0;
  bool is_dummy(int v) const { return v >= first_dummy; }
};

// Throws bad_input for an index outside 0..vertex_count-1, or (strict) for a degenerate
// face or any cut, split or hole. Time O(t log t).
PreparedMesh prepare_mesh(const std::vector<Triangle>& faces, int vertex_count, bool strict = false);

}  // namespace fest::edgebreaker
