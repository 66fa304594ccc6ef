#pragma once
// Edgebreaker for general closed meshes (docs/ebcode.md §5): several
// components, one after the other, and handles (genus > 0) through handle events, the
// mechanism Draco calls "topology split events". Holes and non-manifold input are made
// closed and manifold before this (prepare.hpp).

#include <cstdint>
#include <vector>

#include "edgebreaker/clers.hpp"
#include "edgebreaker/corner_table.hpp"

namespace fest::edgebreaker {

// Symbol `source` (forward numbering) was an L, R or E whose neighbour across its left
// (right_edge false) or right edge was the triangle of the S at symbol `split`: the S's
// right branch was reached through a handle before it was popped. A closed surface of
// genus g gives 2g events; genus 0 gives none.
struct HandleEvent {
  std::uint32_t split = 0;
  std::uint32_t source = 0;
  bool right_edge = false;
  friend bool operator==(const HandleEvent& a, const HandleEvent& b) {
    return a.split == b.split && a.source == b.source && a.right_edge == b.right_edge;
  }
  friend bool operator!=(const HandleEvent& a, const HandleEvent& b) { return !(a == b); }
};

// What the bitstream must carry about connectivity.
struct Connectivity {
  Clers clers;                      // forward order, all components
  std::vector<HandleEvent> events;  // sorted by source, then left before right
};

struct Traversal {
  Connectivity code;
  // Geometry order G: per component (in order of its lowest triangle), the start
  // triangle's three vertices, then each C's tip in forward order. vertex_order[g] is the
  // table's vertex id of G-vertex g.
  std::vector<int> vertex_order;
  // Output face order: per component its start triangle, then one triangle per symbol in
  // forward order. triangle_order[k] is the table's triangle of output face k.
  std::vector<int> triangle_order;
  int components = 0;
};

// Forward traversal with Gumhold's left-first split order. `table` must be closed and
// manifold with every vertex used (build_closed_corner_table); components start at their
// lowest triangle, corner 0 of which is the root.
Traversal traverse(const CornerTable& table);

}  // namespace fest::edgebreaker
