// reencodes_exactly(): the decoder's re-encoding check in one pass (reencode_check.hpp).
// Each part below mirrors one part of the reference check and says which.
#include "edgebreaker/reencode_check.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>

#include "edgebreaker/corner_table.hpp"

namespace fest::edgebreaker {
namespace {

// next() and prev() of corner_table.hpp for corners known to be >= 0: "a multiple of 3" as
// a multiply by the inverse of 3 modulo 2^32 and a compare (prev_nonnegative), cheaper
// than even an unsigned remainder.
inline int next_corner(int c) { return static_cast<std::uint32_t>(c + 1) * 0xAAAAAAABu <= 0x55555555u ? c - 2 : c + 1; }
inline int prev_corner(int c) { return prev_nonnegative(c); }

}  // namespace

bool reencodes_exactly(const int* V, const int* O, int t, int vertex_count, const Symbol* reversed, std::size_t symbols,
                       const std::vector<HandleEvent>& events) {
  if (t <= 0 || vertex_count <= 0) return false;  // nothing to gain: the reference decides
  const unsigned n = 3u * static_cast<unsigned>(t);
  const unsigned nv = static_cast<unsigned>(vertex_count);

  // check_closed_manifold(), first part: vertex ids in range, no triangle repeats a vertex,
  // O an involution between corners of different triangles, and each pair of opposite
  // corners across the same edge in reverse (tested once per pair, at its lower corner:
  // the condition is symmetric).
  // The edge test is made for every corner and folded into one flag (a branch on
  // "lower corner of its pair" is taken at random, half the time).
  bool ok = true;
  for (int c = 0; c < static_cast<int>(n); c += 3) {
    const auto a = static_cast<unsigned>(V[c]), b = static_cast<unsigned>(V[c + 1]), d = static_cast<unsigned>(V[c + 2]);
    if (a >= nv || b >= nv || d >= nv || a == b || b == d || d == a) return false;
    const unsigned across[3][2] = {{b, d}, {d, a}, {a, b}};  // corner j's edge (V[next], V[prev])
    for (int j = 0; j < 3; ++j) {
      const int k = c + j;
      const int o = O[k];
      if (static_cast<unsigned>(o) >= n || static_cast<unsigned>(o - c) < 3u || O[o] != k) return false;
      const int on = next_corner(o), op = prev_corner(o);
      ok &= (static_cast<unsigned>(V[op]) == across[j][0]) & (static_cast<unsigned>(V[on]) == across[j][1]);
    }
  }
  if (!ok) return false;

  // traverse() and the comparisons: every face must come as the next index, every vertex
  // reached as the next index, every symbol and handle event as decoded. While that holds,
  // triangle x has been seen exactly when x < k and vertex v exactly when v < g.
  std::unique_ptr<int[]> first_corner(new int[nv]);  // per vertex: the corner the walk reached it at
  std::vector<int> stack;
  std::vector<int> starts;  // each component's start triangle
  int k = 0;
  unsigned g = 0;
  std::size_t sym = 0, ev = 0;
  const auto expected = [&](std::size_t i) { return reversed[symbols - 1 - i]; };
  // traverse()'s check_split: the neighbour x = nb / 3 was seen; it was an S triangle
  // (split_symbol >= 0) when it is not a start triangle and its symbol, index x minus the
  // start triangles up to x, is S. Then the event is the next one expected.
  int f0 = 0;
  const auto split_event = [&](int nb, bool right_edge) {
    const int x = nb / 3;
    std::size_t starts_upto;
    bool is_start;
    if (x >= f0) {
      is_start = x == f0;
      starts_upto = starts.size();
    } else {  // a neighbour in an earlier component: not on a closed manifold, but exact
      const auto it = std::upper_bound(starts.begin(), starts.end(), x);
      is_start = it != starts.begin() && *(it - 1) == x;
      starts_upto = static_cast<std::size_t>(it - starts.begin());
    }
    if (is_start) return true;
    const std::size_t j = static_cast<std::size_t>(x) - starts_upto;
    if (expected(j) != Symbol::S) return true;
    const HandleEvent e{static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(sym - 1), right_edge};
    if (ev >= events.size() || events[ev] != e) return false;
    ++ev;
    return true;
  };
  while (k < t) {
    f0 = k;  // the lowest triangle not yet seen starts the next component
    starts.push_back(f0);
    ++k;
    for (int j = 0; j < 3; ++j) {
      if (static_cast<unsigned>(V[3 * f0 + j]) != g) return false;
      first_corner[g++] = 3 * f0 + j;
    }
    stack.push_back(O[3 * f0]);
    while (!stack.empty()) {
      int c = stack.back();
      stack.pop_back();
      if (c < 3 * k) continue;  // its triangle was reached through a handle
      for (;;) {
        // The triangle must be the next index, k; then c's place in it gives its next
        // and previous corners without a remainder, and "seen" is "corner below 3k".
        const auto j = static_cast<unsigned>(c - 3 * k);
        if (j >= 3u) return false;  // the face order would not be the identity
        ++k;
        const int cn = j == 2u ? c - 2 : c + 1, cp = j == 0u ? c + 2 : c - 1;
        const auto v = static_cast<unsigned>(V[c]);
        if (v >= g) {  // not seen: a C, which must reach the next vertex
          if (v != g || sym >= symbols || expected(sym) != Symbol::C) return false;
          first_corner[g++] = c;
          ++sym;
          c = O[cn];
          continue;
        }
        const int r = O[cn], l = O[cp];
        const bool right_done = r < 3 * k, left_done = l < 3 * k;
        const Symbol s = right_done ? (left_done ? Symbol::E : Symbol::R) : (left_done ? Symbol::L : Symbol::S);
        if (sym >= symbols || expected(sym) != s) return false;
        ++sym;
        if (s == Symbol::E) {
          if (!split_event(l, false) || !split_event(r, true)) return false;
          break;
        }
        if (s == Symbol::R) {
          if (!split_event(r, true)) return false;
          c = l;
        } else if (s == Symbol::L) {
          if (!split_event(l, false)) return false;
          c = r;
        } else {
          stack.push_back(r);
          c = l;
        }
      }
    }
  }
  if (sym != symbols || ev != events.size() || g != nv) return false;

  // check_closed_manifold(), second part (one fan per vertex): the swing c -> next(O[next(c)])
  // is a permutation that keeps a corner's vertex (by the edge test above), so its cycles
  // split each vertex's corners into fans. The walk reached every vertex, and the cycles
  // through the corners it reached them at are one per vertex; they cover all corners
  // exactly when no vertex has a second fan.
  // One remainder per step: c = next(d) has the residue after d's.
  unsigned covered = 0;
  for (unsigned v = 0; v < nv; ++v) {
    const int start = first_corner[v];
    int c = start;
    unsigned rc = static_cast<unsigned>(c) % 3u;
    do {
      const int d = O[rc == 2u ? c - 2 : c + 1];
      const unsigned rd = static_cast<unsigned>(d) % 3u;
      c = rd == 2u ? d - 2 : d + 1;
      rc = rd == 2u ? 0u : rd + 1u;
      if (++covered > n) return false;
    } while (c != start);
  }
  return covered == n;
}

}  // namespace fest::edgebreaker
