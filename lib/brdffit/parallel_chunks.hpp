#pragma once
// Deterministic data parallelism for the materials side of brdffit: work is cut into
// chunks of a fixed size (independent of the thread count), workers take chunks in a
// strided order, and callers reduce the per-chunk results in chunk order. So the same
// input gives bit-identical sums with 1 or 16 threads (deterministic output: the same input gives the same bytes).

#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace fest::brdffit {

inline std::size_t chunk_count(std::size_t n, std::size_t chunk) { return (n + chunk - 1) / chunk; }

// Calls body(chunk_index, begin, end) for every chunk of [0, n). The first exception thrown
// by a worker is rethrown on the caller's thread once all workers have stopped.
template <typename Body>
void for_each_chunk(std::size_t n, std::size_t chunk, int threads, Body&& body) {
  const std::size_t chunks = chunk_count(n, chunk);
  if (chunks == 0) return;
  const std::size_t workers = std::min<std::size_t>(chunks, static_cast<std::size_t>(std::max(1, threads)));
  auto run = [&](std::size_t w, std::exception_ptr& error) {
    try {
      for (std::size_t c = w; c < chunks; c += workers) body(c, c * chunk, std::min(n, (c + 1) * chunk));
    } catch (...) {
      error = std::current_exception();
    }
  };
  std::vector<std::exception_ptr> errors(workers);
  if (workers == 1) {
    run(0, errors[0]);
  } else {
    std::vector<std::thread> pool;
    for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(run, w, std::ref(errors[w]));
    for (std::thread& t : pool) t.join();
  }
  for (std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace fest::brdffit
