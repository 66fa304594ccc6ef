#pragma once
// The per-symbol operations of Spirale Reversi (reverse_decoder.hpp), defined inline here
// so that the connectivity coders' loops (conn_coder.cpp) get step() and everything it
// does without a call per symbol: the calls, and the registers saved for each, were a
// tenth of the decoder's instructions. Included only by the files that run the decoder.

#include <algorithm>
#include <cstddef>

#include "core/error.hpp"
#include "edgebreaker/corner_table.hpp"
#include "edgebreaker/reverse_decoder.hpp"

namespace fest::edgebreaker {

// A new triangle's first corner c is a multiple of 3, so its next and previous corners are
// written c + 1 and c + 2 below (the remainder in next() and prev() was a tenth of the
// decoder's instructions). Its three V entries are written by the caller.
inline int ReverseDecoder::new_triangle() {
  const std::size_t c = Growing<int>::extend_pair(V_, O_, 3);
  int* o = O_.data() + c;
  o[0] = o[1] = o[2] = -1;
  return static_cast<int>(c);
}

// A new vertex already counts the triangle that makes it (degree 1).
inline int ReverseDecoder::new_vertex(int degree) {
  const std::size_t v = vertices_.extend(1);
  vertices_[v] = {static_cast<int>(v), degree, 0};
  return static_cast<int>(v);
}

inline int ReverseDecoder::find(int v) {
  while (vertices_[static_cast<std::size_t>(v)].parent != v) {
    const int up = vertices_[static_cast<std::size_t>(vertices_[static_cast<std::size_t>(v)].parent)].parent;
    vertices_[static_cast<std::size_t>(v)].parent = up;  // path halving
    v = up;
  }
  return v;
}

// The root of a corner's vertex, written back into V: every reader of V goes through
// find(), so a root there changes no result and shortens later searches.
inline int ReverseDecoder::root_at(int corner) {
  const int r = find(V_[static_cast<std::size_t>(corner)]);
  V_[static_cast<std::size_t>(corner)] = r;
  return r;
}

// `fresh` is a corner of the triangle just made (open by construction): only the old
// corner can already be taken.
inline void ReverseDecoder::link_fresh(int fresh, int old) {
  if (O_[static_cast<std::size_t>(old)] != -1) fail("an edge would get a third triangle");
  O_[static_cast<std::size_t>(fresh)] = old;
  O_[static_cast<std::size_t>(old)] = fresh;
  ++links_;
}

inline void ReverseDecoder::link(int a, int b) {
  if (O_[static_cast<std::size_t>(a)] != -1 || O_[static_cast<std::size_t>(b)] != -1)
    fail("an edge would get a third triangle");
  O_[static_cast<std::size_t>(a)] = b;
  O_[static_cast<std::size_t>(b)] = a;
  ++links_;
}

inline ReverseDecoder::Loop& ReverseDecoder::top(const char* op) {
  if (loops_.empty()) fail(op);
  return loops_.back();
}

// The open edge y -> x that ends at x = V[next(a)], other than a's gate; returns the
// corner opposite it. A manifold vertex is swung around at most twice in all.
inline int ReverseDecoder::incoming_open_edge(int a) { return swing_to_open(a, prev(a)); }

// The swing of incoming_open_edge from j = prev(a), which is a + 2 for a loop's gate.
inline int ReverseDecoder::swing_to_open(int a, int j) {
  // Corners j = next(next(a)) = prev(a), then next(next(O[j])) = prev(O[j]): one step of
  // the swing is one remainder, not two.
  const int limit = static_cast<int>(V_.size());
  for (int step = 0; step <= limit; ++step) {
    const int o = O_[static_cast<std::size_t>(j)];
    if (o == -1) {
      if (j == a) fail("a loop closed on itself");
      return j;
    }
    j = prev_nonnegative(o);  // o != -1 here
  }
  fail("a vertex fan does not end");
}

// Valence context (docs/ebcode.md §4): decoded triangles at the new triangle's left vertex
// (next(c)), counted with the new triangle. Each inverse operation below counts its new
// triangle at its three vertices' roots; a vertex it creates starts at degree 1.
// clamp(d + 1, 2, 7) - 2 of docs/ebcode.md §4, for d >= 1 (the new triangle is counted).
inline void ReverseDecoder::set_valence(int left_degree) { valence_class_ = std::min(left_degree - 1, 5); }

inline void ReverseDecoder::inverse_E() {
  const int c = new_triangle();
  for (int k = 0; k < 3; ++k) V_[static_cast<std::size_t>(c + k)] = new_vertex(1);
  loops_.push_back({c, 3});
  set_valence(1);
  if (event_here()) remember_events(c);
}

inline void ReverseDecoder::inverse_L() {
  Loop& loop = top("L with no open loop");
  const int a = loop.gate, c = new_triangle();
  V_[static_cast<std::size_t>(c)] = V_[static_cast<std::size_t>(a + 1)];
  V_[static_cast<std::size_t>(c + 2)] = V_[static_cast<std::size_t>(a + 2)];
  V_[static_cast<std::size_t>(c + 1)] = new_vertex(1);  // the left vertex
  link_fresh(c + 1, a);
  loop = {c, loop.length < 0 ? -1 : loop.length + 1};
  ++vertices_[static_cast<std::size_t>(root_at(c))].degree;
  ++vertices_[static_cast<std::size_t>(root_at(c + 2))].degree;
  set_valence(1);
  if (event_here()) remember_events(c);
}

inline void ReverseDecoder::inverse_R() {
  Loop& loop = top("R with no open loop");
  const int a = loop.gate, c = new_triangle();
  V_[static_cast<std::size_t>(c + 1)] = V_[static_cast<std::size_t>(a + 1)];
  V_[static_cast<std::size_t>(c)] = V_[static_cast<std::size_t>(a + 2)];
  V_[static_cast<std::size_t>(c + 2)] = new_vertex(1);
  link_fresh(c + 2, a);
  loop = {c, loop.length < 0 ? -1 : loop.length + 1};
  ++vertices_[static_cast<std::size_t>(root_at(c))].degree;
  const int left = root_at(c + 1);
  set_valence(++vertices_[static_cast<std::size_t>(left)].degree);
  if (event_here()) remember_events(c);
}

inline void ReverseDecoder::inverse_C() {
  Loop& loop = top("C with no open loop");
  // C on a 3-loop leaves a 2-loop: only meshes with multi-edges do that (the chapter's
  // constraint 1a, which the context models exploit); C on a 2-loop would repeat a vertex.
  if (loop.length >= 0 && loop.length <= (simple_ ? 3 : 2))
    fail(simple_ ? "C on a loop of 3 edges" : "C on a loop of 2 edges");
  const int a = loop.gate;
  const int x = find(V_[static_cast<std::size_t>(a + 1)]);
  if (vertices_[static_cast<std::size_t>(x)].closed) fail("a vertex is closed twice");
  vertices_[static_cast<std::size_t>(x)].closed = 1;
  const int e = swing_to_open(a, a + 2);  // the open edge y -> x
  const int c = new_triangle();
  V_[static_cast<std::size_t>(c)] = x;
  V_[static_cast<std::size_t>(c + 1)] = V_[static_cast<std::size_t>(next(e))];
  V_[static_cast<std::size_t>(c + 2)] = V_[static_cast<std::size_t>(a + 2)];
  link_fresh(c + 1, a);
  link_fresh(c + 2, e);
  closed_at_.push_back(c);
  loop = {c, loop.length < 0 ? -1 : loop.length - 1};
  ++vertices_[static_cast<std::size_t>(x)].degree;
  const int left = root_at(c + 1);
  ++vertices_[static_cast<std::size_t>(left)].degree;
  ++vertices_[static_cast<std::size_t>(root_at(c + 2))].degree;
  set_valence(vertices_[static_cast<std::size_t>(left)].degree);
  if (event_here()) remember_events(c);
}

inline void ReverseDecoder::step(Symbol s) {
  if (position_ == 0) throw bad_input("invalid connectivity: more symbols than announced");
  --position_;
  switch (s) {
    case Symbol::E: inverse_E(); break;
    case Symbol::L: inverse_L(); break;
    case Symbol::R: inverse_R(); break;
    case Symbol::C: inverse_C(); break;
    case Symbol::S: inverse_S(); break;
    default: fail("not a CLERS symbol");
  }
  if (keep_symbols_) decoded_.push_back(s);
  previous_ = 1 + static_cast<int>(s);
  last_was_L_ = s == Symbol::L;
}

}  // namespace fest::edgebreaker
