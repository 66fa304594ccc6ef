#pragma once
// Splits [0, count) into contiguous bands, one per worker thread. Each band is processed in
// order by one thread, so results that depend only on the band (a row of pixels) are the
// same for every thread count: rendering stays deterministic.

#include <algorithm>
#include <thread>
#include <vector>

namespace fest::reflectance {

// The number of bands parallel_bands uses for `count` items and `threads` threads.
inline int band_count(int count, int threads) { return std::max(1, std::min(threads, count)); }

template <typename Body>  // body(band, begin, end), band in [0, band_count(count, threads))
void parallel_bands_indexed(int count, int threads, Body&& body) {
  threads = band_count(count, threads);
  if (threads <= 1) {
    if (count > 0) body(0, 0, count);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int k = 0; k < threads; ++k) {
    const int begin = static_cast<int>(static_cast<long long>(count) * k / threads);
    const int end = static_cast<int>(static_cast<long long>(count) * (k + 1) / threads);
    pool.emplace_back([&body, k, begin, end] { body(k, begin, end); });
  }
  for (std::thread& t : pool) t.join();
}

template <typename Body>  // body(begin, end)
void parallel_bands(int count, int threads, Body&& body) {
  parallel_bands_indexed(count, threads, [&body](int, int begin, int end) { body(begin, end); });
}

}  // namespace fest::reflectance
