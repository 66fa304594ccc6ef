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

// One row through the weight table, with the channel count known at compile time so
// that the per-tap channel loop unrolls (C = 0: any count, at run time).
template <int C>
void filter_row(const float* src, float* dst, const WeightTable& t, int channels) {
  const int c = C > 0 ? C : channels;
  if (C == 0) {  // any channel count: accumulate in the output directly
    for (int o = 0; o < t.n_out; ++o, dst += c) {
      for (int ch = 0; ch < c; ++ch) dst[ch] = 0;
      for (std::size_t j = t.offset[static_cast<std::size_t>(o)]; j < t.offset[static_cast<std::size_t>(o) + 1]; ++j) {
        const float* p = src + static_cast<std::size_t>(t.index[j]) * static_cast<std::size_t>(c);
        for (int ch = 0; ch < c; ++ch) dst[ch] += t.weight[j] * p[ch];
      }
    }
    return;
  }
  for (int o = 0; o < t.n_out; ++o, dst += c) {
    float acc[4] = {0, 0, 0, 0};
    const std::size_t end = t.offset[static_cast<std::size_t>(o) + 1];
    for (std::size_t j = t.offset[static_cast<std::size_t>(o)]; j < end; ++j) {
      const float w = t.weight[j];
      const float* p = src + static_cast<std::size_t>(t.index[j]) * static_cast<std::size_t>(c);
      for (int ch = 0; ch < c; ++ch) acc[ch] += w * p[ch];
    }
    for (int ch = 0; ch < c; ++ch) dst[ch] = acc[ch];
  }
}

void filter_row_any(const float* src, float* dst, const WeightTable& t, int c) {
  switch (c) {
    case 1: return filter_row<1>(src, dst, t, c);
    case 2: return filter_row<2>(src, dst, t, c);
    case 3: return filter_row<3>(src, dst, t, c);
    case 4: return filter_row<4>(src, dst, t, c);
    default: return filter_row<0>(src, dst, t, c);
  }
}

// dst[i] = Σ_j w[j] src[j][i] over whole rows: contiguous and vectorisable. A block of
// outputs stays in registers while every tap adds into it, so each tap costs one load,
// one multiply and one add per value (no reload and store of dst per tap). The additions
// per value run in the taps' order whatever the blocking, so results do not depend on it.
void accumulate_rows(float* dst, const float* const* src, const float* w, std::size_t taps, std::size_t row_len) {
  constexpr std::size_t block = 16;  // four SSE or two AVX registers of accumulators
  std::size_t i0 = 0;
  for (; i0 + block <= row_len; i0 += block) {
    float acc[block] = {};
    for (std::size_t j = 0; j < taps; ++j) {
      const float wj = w[j];
      const float* s = src[j] + i0;
      for (std::size_t k = 0; k < block; ++k) acc[k] += wj * s[k];
    }
    for (std::size_t k = 0; k < block; ++k) dst[i0 + k] = acc[k];
  }
  for (std::size_t i = i0; i < row_len; ++i) {
    float acc = 0;
    for (std::size_t j = 0; j < taps; ++j) acc += w[j] * src[j][i];
    dst[i] = acc;
  }
}

}  // namespace

FloatImage resample_rows(const FloatImage& in, const WeightTable& table, int threads) {
  FloatImage out(table.n_out, in.height, in.channels);
  for_row_blocks(in.height, threads, [&](int begin, int end) {
    for (int y = begin; y < end; ++y) filter_row_any(in.row(y), out.row(y), table, in.channels);
  });
  return out;
}

FloatImage resample_rows_decoded(const cv::Mat& in, const Encoding& enc, const WeightTable& table, int threads) {
  FloatImage out(table.n_out, in.rows, in.channels());
  for_row_blocks(in.rows, threads, [&](int begin, int end) {
    std::vector<float> row(static_cast<std::size_t>(in.cols) * static_cast<std::size_t>(in.channels()));
    for (int y = begin; y < end; ++y) {
      decode_row(in, y, enc, row.data());
      filter_row_any(row.data(), out.row(y), table, in.channels());
    }
  });
  return out;
}

FloatImage resample_columns_decoded(const cv::Mat& in, const Encoding& enc, const WeightTable& table, int threads) {
  const int c = in.channels();
  FloatImage out(in.cols, table.n_out, c);
  const std::size_t row_len = static_cast<std::size_t>(in.cols) * static_cast<std::size_t>(c);
  for_row_blocks(table.n_out, threads, [&](int begin, int end) {
    // Decoded input rows kept while output rows still read them: the taps of successive
    // outputs move forward, so a row is decoded once per block.
    struct Slot {
      int row = -1;
      std::vector<float> values;
    };
    std::vector<Slot> slots;
    std::vector<const float*> sources;
    auto decoded = [&](int row) -> const float* {
      Slot* free_slot = nullptr;
      for (auto& s : slots) {
        if (s.row == row) return s.values.data();
        if (!free_slot && s.row < 0) free_slot = &s;
      }
      if (!free_slot) {
        slots.push_back({-1, std::vector<float>(row_len)});
        free_slot = &slots.back();
      }
      free_slot->row = row;
      decode_row(in, row, enc, free_slot->values.data());
      return free_slot->values.data();
    };
    for (int o = begin; o < end; ++o) {
      const std::size_t first = table.offset[static_cast<std::size_t>(o)], last = table.offset[static_cast<std::size_t>(o) + 1];
      int lo = in.rows;
      for (std::size_t j = first; j < last; ++j) lo = std::min(lo, table.index[j]);
      for (auto& s : slots)
        if (s.row < lo) s.row = -1;  // no later output reads rows above this one's first
      sources.clear();
      for (std::size_t j = first; j < last; ++j) sources.push_back(decoded(table.index[j]));
      accumulate_rows(out.row(o), sources.data(), table.weight.data() + first, last - first, row_len);
    }
  });
  return out;
}

FloatImage resample_columns(const FloatImage& in, const WeightTable& table, int threads) {
  FloatImage out(in.width, table.n_out, in.channels);
  const std::size_t row_len = static_cast<std::size_t>(in.width) * static_cast<std::size_t>(in.channels);
  for_row_blocks(table.n_out, threads, [&](int begin, int end) {
    std::vector<const float*> sources;
    for (int o = begin; o < end; ++o) {
      const std::size_t first = table.offset[static_cast<std::size_t>(o)], last = table.offset[static_cast<std::size_t>(o) + 1];
      sources.clear();
      for (std::size_t j = first; j < last; ++j) sources.push_back(in.row(table.index[j]));
      accumulate_rows(out.row(o), sources.data(), table.weight.data() + first, last - first, row_len);
    }
  });
  return out;
}

}  // namespace fest::sampling
