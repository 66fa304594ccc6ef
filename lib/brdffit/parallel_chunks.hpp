#pragma once
// Deterministic data parallelism for the materials side of brdffit: work is cut into
// chunks of a fixed size (independent of the thread count), lib/core's parallel_for runs
// the chunks as its jobs, and callers reduce the per-chunk results in chunk order. So the
// same input gives bit-identical sums with 1 or 16 threads (deterministic output: the same
// input gives the same bytes).

#include <algorithm>
#include <cstddef>

#include "core/parallel_for.hpp"

namespace fest::brdffit {

inline std::size_t chunk_count(std::size_t n, std::size_t chunk) { return (n + chunk - 1) / chunk; }

// Calls body(chunk_index, begin, end) for every chunk of [0, n) on up to `threads`
// threads. The first exception thrown is rethrown on the caller's thread once all
// workers have stopped.
template <typename Body>
void for_each_chunk(std::size_t n, std::size_t chunk, int threads, Body&& body) {
  parallel_for(chunk_count(n, chunk), threads,
               [&](std::size_t c) { body(c, c * chunk, std::min(n, (c + 1) * chunk)); });
}

}  // namespace fest::brdffit
