#pragma once
// The decoder's self-check (docs/ebcode.md §2: only exact encodings are accepted) in one
// pass over the decoded corner table, without building the traversal's results.
//
// The reference check (ReverseDecoder::finish) is check_closed_manifold() on the decoded
// table, then traverse() on it, then a comparison of what traverse() returns with what
// was decoded: the same symbols and handle events, and the identity as vertex and face
// order. reencodes_exactly() decides the same question directly:
//   - the manifold conditions of check_closed_manifold(), with the opposite-edge test
//     made once per edge and the one-fan-per-vertex test as "the swing from the corner
//     where the traversal first reached a vertex returns after as many steps as the vertex
//     has corners" (the swings partition the corners of each vertex, so this holds exactly
//     when every vertex has one fan);
//   - traverse()'s walk, compared step by step: while every triangle and vertex so far
//     came in identity order, "seen" is "index below the count so far", so the walk needs
//     no seen flags, no split-symbol table and no output arrays.
// It only ever says "shown" or "not shown"; on "not shown" the caller runs the reference
// check, which names the problem exactly as before (and stays the judge of what is
// accepted).

#include <cstddef>
#include <vector>

#include "edgebreaker/clers.hpp"
#include "edgebreaker/traversal.hpp"

namespace fest::edgebreaker {

// V, O: 3 * triangles corners (the decoder's output order, G vertex ids); `reversed`:
// the symbols in decode order (forward symbol i is reversed[symbols - 1 - i]).
bool reencodes_exactly(const int* V, const int* O, int triangles, int vertex_count, const Symbol* reversed,
                       std::size_t symbols, const std::vector<HandleEvent>& events);

}  // namespace fest::edgebreaker
