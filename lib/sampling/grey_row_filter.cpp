#include "sampling/grey_row_filter.hpp"

#include <algorithm>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "sampling/separable_kernels.hpp"
#include "core/cpu_features.hpp"

namespace fest::sampling {

namespace {

constexpr int lanes = 8;

#if defined(__x86_64__) && defined(__GNUC__)

// Lane k adds w[j][k] * src[start[k] + j] for j < count[k]; lanes past their count keep
// their sum (a blend, not a multiply by 0, which would turn an infinite sample into NaN).
__attribute__((target("avx2"))) void grey_block(const float* src, const std::int32_t* start, const std::int32_t* count,
                                                int taps, const float* w, float* dst) {
  const __m256i first = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(start));
  const __m256i n = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(count));
  __m256 acc = _mm256_setzero_ps();
  int j = 0;
  const int common = _mm256_extract_epi32(n, 0);  // all lanes alike: no masks (the usual case)
  bool uniform = true;
  for (int k = 1; k < lanes; ++k) uniform = uniform && count[k] == common;
  if (uniform) {
    for (; j < taps; ++j) {
      const __m256 v = _mm256_i32gather_ps(src + j, first, 4);
      acc = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_loadu_ps(w + static_cast<std::size_t>(j) * lanes), v));
    }
  } else {
    for (; j < taps; ++j) {
      const __m256 live = _mm256_castsi256_ps(_mm256_cmpgt_epi32(n, _mm256_set1_epi32(j)));
      // Lanes past their taps gather their first sample again (always inside the row).
      const __m256i at = _mm256_blendv_epi8(first, _mm256_add_epi32(first, _mm256_set1_epi32(j)), _mm256_castps_si256(live));
      const __m256 v = _mm256_i32gather_ps(src, at, 4);
      const __m256 sum = _mm256_add_ps(acc, _mm256_mul_ps(_mm256_loadu_ps(w + static_cast<std::size_t>(j) * lanes), v));
      acc = _mm256_blendv_ps(acc, sum, live);
    }
  }
  _mm256_storeu_ps(dst, acc);
}
#endif

}  // namespace

GreyRowFilter::GreyRowFilter(const WeightTable& t) : t_(t) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (!cpu_has_avx2()) return;
  const int blocks = t.n_out / lanes;  // the last n_out % 8 outputs take the scalar loop
  start_.assign(static_cast<std::size_t>(blocks) * lanes, 0);
  count_.assign(static_cast<std::size_t>(blocks) * lanes, 0);
  block_taps_.assign(static_cast<std::size_t>(blocks), 0);
  weight_at_.assign(static_cast<std::size_t>(blocks), 0);
  for (int b = 0; b < blocks; ++b) {
    bool regular = true;
    int most = 0;
    for (int k = 0; k < lanes; ++k) {
      const std::size_t o = static_cast<std::size_t>(b) * lanes + static_cast<std::size_t>(k);
      const std::size_t first = t.offset[o], last = t.offset[o + 1];
      for (std::size_t j = first; j < last; ++j)
        regular = regular && t.index[j] == t.index[first] + static_cast<int>(j - first);
      start_[o] = last > first ? t.index[first] : 0;
      count_[o] = static_cast<std::int32_t>(last - first);
      most = std::max(most, count_[o]);
    }
    if (!regular) {
      count_[static_cast<std::size_t>(b) * lanes] = -1;
      continue;
    }
    vector_ = true;
    block_taps_[static_cast<std::size_t>(b)] = most;
    weight_at_[static_cast<std::size_t>(b)] = weights_.size();
    weights_.resize(weights_.size() + static_cast<std::size_t>(most) * lanes, 0.0f);
    float* w = weights_.data() + weight_at_[static_cast<std::size_t>(b)];
    for (int k = 0; k < lanes; ++k) {
      const std::size_t o = static_cast<std::size_t>(b) * lanes + static_cast<std::size_t>(k);
      for (int j = 0; j < count_[o]; ++j) w[static_cast<std::size_t>(j) * lanes + static_cast<std::size_t>(k)] = t.weight[t.offset[o] + static_cast<std::size_t>(j)];
    }
  }
#endif
}

void GreyRowFilter::operator()(const float* src, float* dst) const {
#if defined(__x86_64__) && defined(__GNUC__)
  if (vector_) {
    const int blocks = static_cast<int>(block_taps_.size());
    for (int b = 0; b < blocks; ++b) {
      const std::size_t o = static_cast<std::size_t>(b) * lanes;
      if (count_[o] < 0) {  // irregular: output by output
        for (std::size_t k = o; k < o + lanes; ++k) {
          float acc = 0;
          for (std::size_t j = t_.offset[k]; j < t_.offset[k + 1]; ++j) acc += t_.weight[j] * src[t_.index[j]];
          dst[k] = acc;
        }
        continue;
      }
      grey_block(src, start_.data() + o, count_.data() + o, block_taps_[static_cast<std::size_t>(b)],
                 weights_.data() + weight_at_[static_cast<std::size_t>(b)], dst + o);
    }
    for (std::size_t k = static_cast<std::size_t>(blocks) * lanes; k < static_cast<std::size_t>(t_.n_out); ++k) {
      float acc = 0;
      for (std::size_t j = t_.offset[k]; j < t_.offset[k + 1]; ++j) acc += t_.weight[j] * src[t_.index[j]];
      dst[k] = acc;
    }
    return;
  }
#endif
  pass_detail::filter_row_any(src, dst, t_, 1);
}

}  // namespace fest::sampling
