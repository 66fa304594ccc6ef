// encode() of clers.hpp: the general traversal (traversal.hpp) restricted to the chapter's
// setting, one closed genus-0 surface; build_corner_table rejects everything else.
#include "edgebreaker/clers.hpp"
#include "edgebreaker/corner_table.hpp"
#include "edgebreaker/traversal.hpp"

namespace fest::edgebreaker {

Encoded encode(const std::vector<Triangle>& triangles, int vertex_count) {
  Traversal t = traverse(build_corner_table(triangles, vertex_count));
  return {std::move(t.code.clers), std::move(t.vertex_order)};
}

}  // namespace fest::edgebreaker
