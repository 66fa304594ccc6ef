// The forward traversal for any closed manifold (docs/ebcode.md §1, with §5's handle events).
// Components are taken in order of their lowest triangle; each is the chapter's traversal
// from its own start triangle. On a handle, the S's pushed right corner is found marked
// when popped and skipped; the triangle that reached it first records the event.
#include "edgebreaker/traversal.hpp"

namespace fest::edgebreaker {

Traversal traverse(const CornerTable& table) {
  const int t = table.triangles();
  std::vector<char> vertex_seen(static_cast<std::size_t>(table.vertex_count), 0);
  std::vector<char> triangle_seen(static_cast<std::size_t>(t), 0);
  // Symbol id of each S triangle, -1 for the others: the handle-event lookup.
  std::vector<int> split_symbol(static_cast<std::size_t>(t), -1);
  Traversal out;
  out.code.clers.reserve(static_cast<std::size_t>(t));
  out.vertex_order.reserve(static_cast<std::size_t>(table.vertex_count));
  out.triangle_order.reserve(static_cast<std::size_t>(t));

  const auto visit = [&](int v) {
    vertex_seen[static_cast<std::size_t>(v)] = 1;
    out.vertex_order.push_back(v);
  };
  const auto emit = [&](Symbol s, int c) {
    out.code.clers.push_back(s);
    out.triangle_order.push_back(c / 3);
  };
  const auto check_split = [&](int neighbour_corner, bool right_edge) {
    const int j = split_symbol[static_cast<std::size_t>(neighbour_corner / 3)];
    if (j >= 0)
      out.code.events.push_back({static_cast<std::uint32_t>(j),
                                 static_cast<std::uint32_t>(out.code.clers.size() - 1), right_edge});
  };

  std::vector<int> stack;
  for (int f0 = 0; f0 < t; ++f0) {
    if (triangle_seen[static_cast<std::size_t>(f0)]) continue;
    ++out.components;
    triangle_seen[static_cast<std::size_t>(f0)] = 1;
    out.triangle_order.push_back(f0);
    for (int k = 0; k < 3; ++k) visit(table.V[static_cast<std::size_t>(3 * f0 + k)]);
    stack.push_back(table.O[static_cast<std::size_t>(3 * f0)]);
    while (!stack.empty()) {
      int c = stack.back();
      stack.pop_back();
      if (triangle_seen[static_cast<std::size_t>(c / 3)]) continue;  // reached through a handle
      for (;;) {
        triangle_seen[static_cast<std::size_t>(c / 3)] = 1;
        if (!vertex_seen[static_cast<std::size_t>(table.V[static_cast<std::size_t>(c)])]) {
          visit(table.V[static_cast<std::size_t>(c)]);
          emit(Symbol::C, c);
          c = right(table, c);
          continue;
        }
        const int r = right(table, c), l = left(table, c);
        const bool right_done = triangle_seen[static_cast<std::size_t>(r / 3)] != 0;
        const bool left_done = triangle_seen[static_cast<std::size_t>(l / 3)] != 0;
        if (right_done && left_done) {
          emit(Symbol::E, c);
          check_split(l, false);
          check_split(r, true);
          break;
        }
        if (right_done) {
          emit(Symbol::R, c);
          check_split(r, true);
          c = l;
        } else if (left_done) {
          emit(Symbol::L, c);
          check_split(l, false);
          c = r;
        } else {
          split_symbol[static_cast<std::size_t>(c / 3)] = static_cast<int>(out.code.clers.size());
          emit(Symbol::S, c);
          stack.push_back(r);
          c = l;
        }
      }
    }
  }
  return out;
}

}  // namespace fest::edgebreaker
