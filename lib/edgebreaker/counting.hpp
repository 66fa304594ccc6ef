#pragma once
// The numbers behind the chapter's bounds (docs/ebcode.md §6): Tutte's count of rooted planar
// triangulations, and the same count obtained by enumerating CLERS strings, which is the
// exhaustive check that encode and decode form a bijection.

#include <cstdint>
#include <functional>

#include "edgebreaker/clers.hpp"

namespace fest::edgebreaker {

// Tutte (1962): rooted simple triangulations of a triangle with n interior vertices,
// 2(4n+1)! / ((n+1)! (3n+2)!) = 1, 1, 3, 13, 68, 399, 2530, ... Exact in 64 bits up to
// n = 17 at least; throws fest::Error(bad_input) for n < 0 or when it would overflow.
std::uint64_t tutte_rooted_triangulations(int interior_vertices);

// Every CLERS string of a sphere triangulation with n + 3 vertices (2n + 1 symbols, n C's)
// that decode() accepts, each passed to `visit` (if given) in the order C < L < E < R < S of
// the reversed string; returns how many. Strings are generated back to front, the order the
// decoder reads them, and a prefix is dropped as soon as the decoder would certainly
// reject it (no loop to work on, C on a 3-loop, too few symbols left to close the loops),
// so the count equals Tutte's only if decode() accepts each triangulation exactly once.
std::uint64_t enumerate_clers(int interior_vertices, const std::function<void(const Clers&)>& visit = {});

}  // namespace fest::edgebreaker
