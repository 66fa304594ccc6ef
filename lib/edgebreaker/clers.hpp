#pragma once
// Edgebreaker connectivity coding for closed, connected, oriented genus-0 triangle meshes
// (the "planar triangulations" of seed chapter 5; docs/ebcode.md §1-2).
//
// In memory only: triangles are vertex-index triples, the code is a vector of symbols.
// Bitstreams, entropy coding and general meshes come later and build on this.

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace fest::edgebreaker {

// One symbol per triangle except the start triangle (docs/ebcode.md §1, "The symbol string").
enum class Symbol : unsigned char { C, L, E, R, S };

using Triangle = std::array<int, 3>;
using Clers = std::vector<Symbol>;

struct Encoded {
  // Symbols in traversal (forward) order: clers[0] is the first triangle after the start
  // triangle and the last symbol is always E. The decoder reads it back to front; storing
  // it reversed is a matter for the bitstream, not for this type.
  Clers clers;
  // Input vertex ids in the order the traversal first reaches them: the start triangle's
  // three corners, then each C's tip. decode() numbers vertex i as the input's
  // vertex_order[i], so decode(encode(M).clers) == M with ids mapped through this order.
  std::vector<int> vertex_order;
};

// Forward traversal (docs/ebcode.md §1). Throws fest::Error(bad_input) unless the triangles form one
// closed, edge- and vertex-manifold, consistently oriented surface of genus 0 that uses
// every vertex 0..vertex_count-1.
Encoded encode(const std::vector<Triangle>& triangles, int vertex_count);

// Spirale Reversi (docs/ebcode.md §2). Returns the start triangle first, then one triangle per
// symbol in forward order, with the input's orientation; vertices are numbered in the
// encoder's visit order, so the vertex count is #C + 3. Throws fest::Error(bad_input) for
// every string that is not exactly the encoding of the mesh it decodes to (it re-encodes
// the result to make sure); never loops or crashes on garbage. Time O(n log n) in the
// string length: linear decoding plus the re-encoding's edge sort.
std::vector<Triangle> decode(const Clers& clers);

// String form, e.g. "CCRRSLE", in forward order.
char to_char(Symbol s) noexcept;
std::string to_string(const Clers& clers);
// Throws fest::Error(bad_input) naming the first character that is not one of CLERS.
Clers parse_clers(std::string_view text);

}  // namespace fest::edgebreaker
