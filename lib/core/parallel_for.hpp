#pragma once
// Independent jobs on a few threads, taken dynamically (uneven jobs balance themselves).
// Callers keep results per job index and combine them in index order, so output does not
// depend on the thread count.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace fest {

namespace detail {

// Test hook: when 0 or more, parallel_for starts at most this many threads besides the
// calling one and the next start fails the way std::thread fails when the system refuses a
// thread (std::system_error, EAGAIN: too many threads or processes). -1 (always, outside
// tests/unit/test_core_parallel_for.cpp): no such limit.
inline std::atomic<int> thread_start_limit_for_tests{-1};

template <typename Worker>
std::thread start_thread(std::size_t already_started, Worker& worker) {
  const int limit = thread_start_limit_for_tests.load(std::memory_order_relaxed);
  if (limit >= 0 && already_started >= static_cast<std::size_t>(limit))
    throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again), "thread refused (test hook)");
  return std::thread(worker);
}

}  // namespace detail

// Runs job(i) for every i in [0, count) on up to `threads` threads, the calling one
// included. After a failure no new jobs start; the first failure is rethrown here once
// all threads have joined.
//
// When the system refuses a thread (std::thread throws std::system_error), the jobs run on
// the threads already started and the calling one: they take jobs from the same counter,
// so every job still runs once and the results are those of any thread count -- slower,
// not wrong. (Letting the exception leave with threads unjoined would std::terminate.)
template <typename Job>
void parallel_for(std::size_t count, int threads, const Job& job) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < count;) {
      try {
        job(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> pool;
  const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), count);
  try {
    if (workers > 1) pool.reserve(workers - 1);
    for (std::size_t t = 1; t < workers; ++t) pool.push_back(detail::start_thread(pool.size(), worker));
  } catch (const std::system_error&) {
    // Fewer threads than asked for: the ones in `pool` and this one do all the jobs.
  } catch (const std::bad_alloc&) {
    // No room for the pool's vector: as above, with what was started.
  }
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// Contiguous bands of [0, count), one per thread (at most `threads`, at least one):
// body(band, begin, end) with band in [0, band_count(count, threads)), each band processed
// in order by one thread. For work whose setup per band is costly (a rasteriser scans
// every triangle once per band of rows); results that depend only on the item (a pixel
// row) are the same for every thread count.
inline int band_count(int count, int threads) { return std::max(1, std::min(threads, count)); }

template <typename Body>
void parallel_bands_indexed(int count, int threads, const Body& body) {
  if (count <= 0) return;
  const int bands = band_count(count, threads);
  parallel_for(static_cast<std::size_t>(bands), bands, [&](std::size_t k) {
    const int band = static_cast<int>(k);
    const int begin = static_cast<int>(static_cast<long long>(count) * band / bands);
    const int end = static_cast<int>(static_cast<long long>(count) * (band + 1) / bands);
    body(band, begin, end);
  });
}

template <typename Body>  // body(begin, end)
void parallel_bands(int count, int threads, const Body& body) {
  parallel_bands_indexed(count, threads, [&body](int, int begin, int end) { body(begin, end); });
}

}  // namespace fest
