#pragma once
// Rossignac's corner table (docs/ebcode.md §1) and the checks that make a triangle list one the
// chapter's coder can take: closed, manifold, oriented, connected, genus 0.

#include <cstdint>
#include <vector>

#include "edgebreaker/clers.hpp"

namespace fest::edgebreaker {

// Triangle t owns corners 3t, 3t+1, 3t+2 in the input's vertex order, so orientation is
// kept. O[c] is the corner across the edge (V[next(c)], V[prev(c)]), or -1 while open.
struct CornerTable {
  std::vector<int> V;
  std::vector<int> O;
  int vertex_count = 0;

  int corners() const { return static_cast<int>(V.size()); }
  int triangles() const { return corners() / 3; }
};

// One remainder and a select instead of two remainders: these are the inner loops of the
// traversal and both reverse decoders. Equal to c - c % 3 + (c + 1) % 3 for c >= -2, so
// the -1 of an open corner maps as before.
inline int next(int c) { return c % 3 == 2 ? c - 2 : c + 1; }
inline int prev(int c) { return c % 3 == 0 ? c + 2 : c - 1; }  // next(next(c)), one remainder
// prev(c) for a corner c >= 0 (never -1): "c is a multiple of 3" as c times the inverse of
// 3 modulo 2^32 landing in the first third of the range (one multiply and a compare; the
// remainder takes a multiply, a shift and a subtraction). The swing of Spirale Reversi's
// C steps by it (docs/ebcode.md §6).
inline int prev_nonnegative(int c) { return static_cast<std::uint32_t>(c) * 0xAAAAAAABu <= 0x55555555u ? c + 2 : c - 1; }
// right(c): the corner across the edge (V[c], V[prev(c)]); left(c): across (V[next(c)], V[c]).
inline int right(const CornerTable& t, int c) { return t.O[static_cast<std::size_t>(next(c))]; }
inline int left(const CornerTable& t, int c) { return t.O[static_cast<std::size_t>(prev(c))]; }

// Builds the table and checks the mesh; throws fest::Error(bad_input) naming the first
// offending triangle, edge or vertex. O(t log t): sorting the directed edges.
CornerTable build_corner_table(const std::vector<Triangle>& triangles, int vertex_count);

// The same checks without "connected" and "genus 0": any number of closed, oriented,
// edge- and vertex-manifold components of any genus, every vertex used. This is what the
// general traversal (traversal.hpp) takes.
// Checks a table whose O is already filled in (the decoder's): every corner has an
// opposite, O is an involution between corners of reversed edges, every vertex is used and
// its corners form one fan. Multi-edges (two edges between the same vertices) are allowed:
// cutting non-manifold input can leave them, and the corner table does not mind.
// Throws bad_input naming the first problem. O(t).
void check_closed_manifold(const CornerTable& table);

CornerTable build_closed_corner_table(const std::vector<Triangle>& triangles, int vertex_count);

}  // namespace fest::edgebreaker
