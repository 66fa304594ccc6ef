#include "sampling/separable_pass.hpp"

#include "sampling/separable_kernels.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

#include "core/cpu_features.hpp"

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

namespace pass_detail {

namespace {

// Four floats as one SSE/NEON register (GCC/Clang vector extension): element-wise
// arithmetic, so per channel exactly the scalar operations.
typedef float Lanes4 __attribute__((vector_size(16)));
typedef float Lanes8 __attribute__((vector_size(32)));

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
    if ((C == 3 || C == 4) && end > t.offset[static_cast<std::size_t>(o)] && (C == 4 || t.index[end - 1] < t.n_in - 1)) {
      // A pixel as one 4-lane vector (RGB: the fourth lane reads the next pixel's red and
      // is dropped): one vector multiply-add per tap, in the same order per channel as
      // the scalar loop below. RGB outputs whose taps reach the last pixel take that loop.
      Lanes4 sum = {0, 0, 0, 0};
      for (std::size_t j = t.offset[static_cast<std::size_t>(o)]; j < end; ++j) {
        Lanes4 p;
        std::memcpy(&p, src + static_cast<std::size_t>(t.index[j]) * C, sizeof p);
        sum += t.weight[j] * p;
      }
      std::memcpy(acc, &sum, sizeof acc);
      for (int ch = 0; ch < c; ++ch) dst[ch] = acc[ch];
      continue;
    }
    for (std::size_t j = t.offset[static_cast<std::size_t>(o)]; j < end; ++j) {
      const float w = t.weight[j];
      const float* p = src + static_cast<std::size_t>(t.index[j]) * static_cast<std::size_t>(c);
      for (int ch = 0; ch < c; ++ch) acc[ch] += w * p[ch];
    }
    for (int ch = 0; ch < c; ++ch) dst[ch] = acc[ch];
  }
}

// Four rows through the table at once (RGB or RGBA): each tap's index and weight are
// fetched once for the four rows. Per channel the same operations in the same order as
// filter_row; outputs whose RGB taps reach the last pixel go through filter_row's scalar
// loop, one row at a time.
template <int C>
void filter_four_rows(const float* const* src, float* const* dst, const WeightTable& t) {
  static_assert(C == 3 || C == 4, "pixels as one 4-lane vector");
  for (int o = 0; o < t.n_out; ++o) {
    const std::size_t first = t.offset[static_cast<std::size_t>(o)], end = t.offset[static_cast<std::size_t>(o) + 1];
    const std::size_t out_at = static_cast<std::size_t>(o) * C;
    if (end == first || (C == 3 && t.index[end - 1] >= t.n_in - 1)) {
      for (int r = 0; r < 4; ++r) {
        float* d = dst[r] + out_at;
        for (int ch = 0; ch < C; ++ch) d[ch] = 0;
        for (std::size_t j = first; j < end; ++j) {
          const float* p = src[r] + static_cast<std::size_t>(t.index[j]) * C;
          for (int ch = 0; ch < C; ++ch) d[ch] += t.weight[j] * p[ch];
        }
      }
      continue;
    }
    Lanes4 sum[4] = {};
    for (std::size_t j = first; j < end; ++j) {
      const float w = t.weight[j];
      const std::size_t at = static_cast<std::size_t>(t.index[j]) * C;
      for (int r = 0; r < 4; ++r) {
        Lanes4 p;
        std::memcpy(&p, src[r] + at, sizeof p);
        sum[r] += w * p;
      }
    }
    for (int r = 0; r < 4; ++r) std::memcpy(dst[r] + out_at, &sum[r], C * sizeof(float));
  }
}

}  // namespace

void filter_four_rows_any(const float* const* src, float* const* dst, const WeightTable& t, int c) {
  if (c == 3) return filter_four_rows<3>(src, dst, t);
  return filter_four_rows<4>(src, dst, t);
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

// dst[i] = Σ_j w[j] src[j][i] for i in [begin, end): contiguous and vectorisable. A block
// of outputs stays in registers (four vectors V) while every tap adds into it, so each tap
// costs one load, one multiply and one add per value (no reload and store of dst per
// tap). The additions per value run in the taps' order whatever the blocking or vector
// width, and no FMA is used, so results are bit-identical on every path.
template <typename V>
[[gnu::always_inline]] inline void accumulate_rows_with(float* dst, const float* const* src, const float* w, std::size_t taps,
                                                        std::size_t begin, std::size_t end) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(float), block = 4 * lanes;
  std::size_t i0 = begin;
  for (; i0 + block <= end; i0 += block) {
    V acc[4] = {};
    for (std::size_t j = 0; j < taps; ++j) {
      const float wj = w[j];
      const float* s = src[j] + i0;
      for (std::size_t k = 0; k < 4; ++k) {
        V v;
        std::memcpy(&v, s + k * lanes, sizeof v);
        acc[k] += wj * v;
      }
    }
    std::memcpy(dst + i0, acc, sizeof acc);
  }
  for (std::size_t i = i0; i < end; ++i) {
    float acc = 0;
    for (std::size_t j = 0; j < taps; ++j) acc += w[j] * src[j][i];
    dst[i] = acc;
  }
}

namespace {

#if defined(__x86_64__) && defined(__GNUC__)
// The optional AVX2 path (docs/resample.md "Separable passes and their order"): 8-lane vectors where the CPU has them.
__attribute__((target("avx2"))) void accumulate_rows_avx2(float* dst, const float* const* src, const float* w,
                                                          std::size_t taps, std::size_t begin, std::size_t end) {
  accumulate_rows_with<Lanes8>(dst, src, w, taps, begin, end);
}
#endif

}  // namespace

void accumulate_rows(float* dst, const float* const* src, const float* w, std::size_t taps, std::size_t begin,
                     std::size_t end) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) return accumulate_rows_avx2(dst, src, w, taps, begin, end);
#endif
  accumulate_rows_with<Lanes4>(dst, src, w, taps, begin, end);
}

}  // namespace pass_detail

using namespace pass_detail;

FloatImage resample_rows(const FloatImage& in, const WeightTable& table, int threads) {
  FloatImage out(table.n_out, in.height, in.channels);
  for_row_blocks(in.height, threads, [&](int begin, int end) {
    int y = begin;
    if (in.channels == 3 || in.channels == 4)
      for (; y + 4 <= end; y += 4) {
        const float* src[4] = {in.row(y), in.row(y + 1), in.row(y + 2), in.row(y + 3)};
        float* dst[4] = {out.row(y), out.row(y + 1), out.row(y + 2), out.row(y + 3)};
        if (in.channels == 3)
          filter_four_rows<3>(src, dst, table);
        else
          filter_four_rows<4>(src, dst, table);
      }
    for (; y < end; ++y) filter_row_any(in.row(y), out.row(y), table, in.channels);
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

FloatImage resample_columns(const FloatImage& in, const WeightTable& table, int threads) {
  FloatImage out(in.width, table.n_out, in.channels);
  const std::size_t row_len = static_cast<std::size_t>(in.width) * static_cast<std::size_t>(in.channels);
  for_row_blocks(table.n_out, threads, [&](int begin, int end) {
    std::vector<const float*> sources;
    for (int o = begin; o < end; ++o) {
      const std::size_t first = table.offset[static_cast<std::size_t>(o)], last = table.offset[static_cast<std::size_t>(o) + 1];
      sources.clear();
      for (std::size_t j = first; j < last; ++j) sources.push_back(in.row(table.index[j]));
      accumulate_rows(out.row(o), sources.data(), table.weight.data() + first, last - first, 0, row_len);
    }
  });
  return out;
}

}  // namespace fest::sampling
