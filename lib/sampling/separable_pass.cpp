#include "sampling/separable_pass.hpp"

#include <algorithm>
#include <functional>
#include <thread>
#include <vector>

namespace fest::sampling {

namespace {

// Calls body(begin, end) on contiguous blocks of [0, rows) from up to `threads` threads.
void for_row_blocks(int rows, int threads, const std::function<void(int, int)>& body) {
  const int n = std::max(1, std::min(threads, rows));
  if (n == 1) {
    body(0, rows);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) {
    const int begin = static_cast<int>(static_cast<long long>(rows) * t / n);
    const int end = static_cast<int>(static_cast<long long>(rows) * (t + 1) / n);
    pool.emplace_back(body, begin, end);
  }
  for (auto& th : pool) th.join();
}

}  // namespace

FloatImage resample_rows(const FloatImage& in, const WeightTable& table, int threads) {
  FloatImage out(table.n_out, in.height, in.channels);
  const int c = in.channels;
  for_row_blocks(in.height, threads, [&](int begin, int end) {
    for (int y = begin; y < end; ++y) {
      const float* src = in.row(y);
      float* dst = out.row(y);
      for (int o = 0; o < table.n_out; ++o, dst += c) {
        for (std::size_t j = table.offset[static_cast<std::size_t>(o)]; j < table.offset[static_cast<std::size_t>(o) + 1]; ++j) {
          const float w = table.weight[j];
          const float* p = src + static_cast<std::size_t>(table.index[j]) * static_cast<std::size_t>(c);
          for (int ch = 0; ch < c; ++ch) dst[ch] += w * p[ch];
        }
      }
    }
  });
  return out;
}

FloatImage resample_columns(const FloatImage& in, const WeightTable& table, int threads) {
  FloatImage out(in.width, table.n_out, in.channels);
  const std::size_t row_len = static_cast<std::size_t>(in.width) * static_cast<std::size_t>(in.channels);
  for_row_blocks(table.n_out, threads, [&](int begin, int end) {
    for (int o = begin; o < end; ++o) {
      float* dst = out.row(o);
      // Whole input rows are accumulated at once: contiguous memory, vectorisable.
      for (std::size_t j = table.offset[static_cast<std::size_t>(o)]; j < table.offset[static_cast<std::size_t>(o) + 1]; ++j) {
        const float w = table.weight[j];
        const float* src = in.row(table.index[j]);
        for (std::size_t i = 0; i < row_len; ++i) dst[i] += w * src[i];
      }
    }
  });
  return out;
}

}  // namespace fest::sampling
