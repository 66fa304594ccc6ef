#pragma once
// Worker threads of the segbrain operators (segbrain(1) --threads; deterministic output). The
// operators split their work into independent slices, rows or line blocks whose results
// do not depend on which thread computes them, and every reduction runs in a fixed order
// on the calling thread, so the output is byte-identical for any thread count.
//
// The count is one setting for the whole library (set once by the tool from --threads)
// rather than an argument of every operator: the rule engine calls the operators through
// the workspace and has no use for it.

#include <algorithm>
#include <cstddef>

#include "core/parallel_for.hpp"

namespace fest::segbrain {

// Threads the operators may use (>= 1); 1 until set.
int worker_threads();
void set_worker_threads(int n);

// Calls body(worker, begin, end) on contiguous bands of [0, count), one per worker
// (worker in [0, workers)); at most worker_threads() workers and none with fewer than
// min_per_worker items. The bands are fest::parallel_for's jobs (each runs once, on the
// calling thread or another); the first failure is rethrown here after all joined.
template <typename Body>
void parallel_bands(std::size_t count, std::size_t min_per_worker, Body&& body) {
  const std::size_t by_size = std::max<std::size_t>(1, count / std::max<std::size_t>(1, min_per_worker));
  const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(worker_threads()), by_size);
  if (count == 0) return;
  if (workers <= 1) {
    body(std::size_t{0}, std::size_t{0}, count);
    return;
  }
  parallel_for(workers, static_cast<int>(workers),
               [&](std::size_t w) { body(w, count * w / workers, count * (w + 1) / workers); });
}

}  // namespace fest::segbrain
