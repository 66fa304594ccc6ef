// The forward Edgebreaker traversal (spec 2.2) with Gumhold's split order: at S the
// left branch is continued and the right one waits on the stack. That order is what
// makes the chapter's exclusion patterns hold, so it is part of the format.
#include <utility>

#include "edgebreaker/clers.hpp"
#include "edgebreaker/corner_table.hpp"

namespace fest::edgebreaker {

Encoded encode(const std::vector<Triangle>& triangles, int vertex_count) {
  const CornerTable table = build_corner_table(triangles, vertex_count);
  std::vector<char> vertex_seen(static_cast<std::size_t>(vertex_count), 0);
  std::vector<char> triangle_seen(static_cast<std::size_t>(table.triangles()), 0);
  Encoded out;
  out.clers.reserve(static_cast<std::size_t>(table.triangles() - 1));
  out.vertex_order.reserve(static_cast<std::size_t>(vertex_count));

  const auto visit = [&](int v) {
    vertex_seen[v] = 1;
    out.vertex_order.push_back(v);
  };
  // One component (checked above) whose start triangle is triangle 0; its corner 0 is the
  // tip the decoder restores, so the root of the triangulation is (triangle 0, corner 0).
  triangle_seen[0] = 1;
  for (int k = 0; k < 3; ++k) visit(table.V[k]);
  std::vector<int> stack{table.O[0]};

  while (!stack.empty()) {
    int c = stack.back();
    stack.pop_back();
    if (triangle_seen[c / 3]) continue;  // only with handles; kept for the general case
    for (;;) {
      triangle_seen[c / 3] = 1;
      if (!vertex_seen[table.V[c]]) {
        // The tip is new: the gate turns around the vertex it points to.
        visit(table.V[c]);
        out.clers.push_back(Symbol::C);
        c = right(table, c);
        continue;
      }
      const bool right_done = triangle_seen[right(table, c) / 3] != 0;
      const bool left_done = triangle_seen[left(table, c) / 3] != 0;
      if (right_done && left_done) {
        out.clers.push_back(Symbol::E);
        break;
      }
      if (right_done) {
        out.clers.push_back(Symbol::R);
        c = left(table, c);
      } else if (left_done) {
        out.clers.push_back(Symbol::L);
        c = right(table, c);
      } else {
        out.clers.push_back(Symbol::S);
        stack.push_back(right(table, c));
        c = left(table, c);
      }
    }
  }
  return out;
}

}  // namespace fest::edgebreaker
