#include "wavelet/quantiser.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "core/cpu_features.hpp"
#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::wavelet {

namespace {

constexpr double kMaxKey = 1125899906842624.0;  // 2^50: keys and their sums stay exact

// std::round (halves away from zero, the sign of a zero result kept) without the libm
// call: below 2^52 the fraction v - trunc(v) is exact, above it every double is integral.
inline double round_half_away(double v) noexcept {
  if (!(std::fabs(v) < 4503599627370496.0)) return v;
  double t = static_cast<double>(static_cast<std::int64_t>(v));
  const double f = v - t;
  if (f >= 0.5) t += 1.0;
  else if (f <= -0.5) t -= 1.0;
  return std::copysign(t, v);
}

template <typename T>
inline double clamp_round(double v) noexcept {
  if (std::isnan(v)) return 0.0;
  const double r = round_half_away(v);
  const double lo = static_cast<double>(std::numeric_limits<T>::lowest());
  const double hi = static_cast<double>(std::numeric_limits<T>::max());
  return std::clamp(r, lo, hi);
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  std::size_t nonfinite = 0;
  bool integral = true;
};

Range range_of(const Volume& v) {
  Range r;
  for (double x : v.voxels) {
    if (!std::isfinite(x)) {
      ++r.nonfinite;
      continue;
    }
    r.lo = std::min(r.lo, x);
    r.hi = std::max(r.hi, x);
    if (r.integral && (x != std::floor(x) || std::fabs(x) >= kMaxKey)) r.integral = false;
  }
  if (r.lo > r.hi) r.lo = r.hi = 0.0;
  return r;
}

// The value of key 0 for float data: 0 itself when the range holds it, so that empty
// space (a plume's surroundings) has keys, and wavelet coefficients, of zero -- rows
// the coder skips with one decision and blocks the inverse transform skips -- and
// decodes to exact zeros; else the middle of the range.
double float_offset(const Range& r) noexcept { return (r.lo <= 0 && 0 <= r.hi) ? 0.0 : 0.5 * (r.lo + r.hi); }

void refuse_nonfinite(const Range& r) {
  if (r.nonfinite > 0)
    throw bad_input("{} voxels are NaN or infinite: no error bound can hold for them (only lossless coding keeps them)",
                    r.nonfinite);
}

}  // namespace

std::int64_t float_key(float f) noexcept {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  if (u & 0x80000000u) return -static_cast<std::int64_t>(u & 0x7fffffffu) - 1;
  return static_cast<std::int64_t>(u);
}

float key_float(std::int64_t key) noexcept {
  std::uint32_t u = key >= 0 ? static_cast<std::uint32_t>(key & 0xffffffff)
                             : (static_cast<std::uint32_t>((-(key + 1)) & 0x7fffffff) | 0x80000000u);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

double stored_as(double v, ScalarType type) noexcept {
  switch (type) {
    case ScalarType::u8: return clamp_round<std::uint8_t>(v);
    case ScalarType::i8: return clamp_round<std::int8_t>(v);
    case ScalarType::u16: return clamp_round<std::uint16_t>(v);
    case ScalarType::i16: return clamp_round<std::int16_t>(v);
    case ScalarType::u32: return clamp_round<std::uint32_t>(v);
    case ScalarType::i32: return clamp_round<std::int32_t>(v);
    case ScalarType::u64: return clamp_round<std::uint64_t>(v);
    case ScalarType::i64: return clamp_round<std::int64_t>(v);
    case ScalarType::f32: {
      if (std::isnan(v)) return v;
      const double m = static_cast<double>(std::numeric_limits<float>::max());
      if (v > m * (1 + 1e-7)) return std::numeric_limits<double>::infinity();
      if (v < -m * (1 + 1e-7)) return -std::numeric_limits<double>::infinity();
      return static_cast<double>(static_cast<float>(std::clamp(v, -m, m)));
    }
    case ScalarType::f64: return v;
  }
  return v;
}

Quantiser plan_max_error(const Volume& volume, double bound) {
  if (!(bound > 0) || !std::isfinite(bound)) throw bad_input("the error bound must be positive and finite, not {}", bound);
  const Range r = range_of(volume);
  refuse_nonfinite(r);
  Quantiser q;
  if (scalar_type_is_integer(volume.type) && r.integral) {
    q.step = 2.0 * std::floor(bound) + 1.0;
    q.offset = std::round(r.lo);
  } else {
    q.step = 2.0 * bound;
    q.offset = float_offset(r);
  }
  if ((r.hi - r.lo) / q.step > kMaxKey)
    throw bad_input("error bound {} is too small for the value range [{}, {}] (more than 2^50 steps)", bound, r.lo, r.hi);
  return q;
}

Quantiser plan_step(const Volume& volume, double step) {
  if (!(step > 0) || !std::isfinite(step)) throw bad_input("the quantiser step must be positive, not {}", step);
  const Range r = range_of(volume);
  refuse_nonfinite(r);
  Quantiser q;
  q.step = step;
  q.offset = scalar_type_is_integer(volume.type) ? std::round(r.lo) : float_offset(r);
  if ((r.hi - r.lo) / q.step > kMaxKey)
    throw bad_input("quantiser step {} is too small for the value range [{}, {}]", step, r.lo, r.hi);
  return q;
}

Quantiser plan_lossless(const Volume& volume) {
  const Range r = range_of(volume);
  Quantiser q;
  if (r.nonfinite == 0 && r.integral) return q;  // step 1, offset 0: the values themselves
  std::size_t misfits = 0;
  for (double x : volume.voxels) {
    if (std::isnan(x)) continue;
    if (static_cast<double>(static_cast<float>(x)) != x) ++misfits;
  }
  if (misfits > 0)
    throw bad_input("lossless coding of {} float64 voxels that float32 cannot hold exactly is not supported", misfits);
  q.kind = KeyKind::float32_bits;
  return q;
}

std::int64_t key_of(const Quantiser& q, double v) noexcept {
  return q.kind == KeyKind::float32_bits ? float_key(static_cast<float>(v))
                                         : static_cast<std::int64_t>(std::llround((v - q.offset) / q.step));
}

std::vector<std::int64_t> quantise(const Volume& volume, const Quantiser& q, int threads) {
  std::vector<std::int64_t> keys(volume.voxels.size());
  const std::size_t block = 1 << 16;
  const std::size_t n = keys.size();
  parallel_for((n + block - 1) / block, threads, [&](std::size_t b) {
    const std::size_t end = std::min(n, (b + 1) * block);
    for (std::size_t i = b * block; i < end; ++i) keys[i] = key_of(q, volume.voxels[i]);
  });
  return keys;
}

namespace {

// Keys are read through memcpy: `keys` may be the very storage the values are written to
// (dequantise_in_place), the key of voxel i read before its value is written.
inline std::int64_t key_at(const unsigned char* keys, std::size_t i) noexcept {
  std::int64_t k;
  std::memcpy(&k, keys + 8 * i, 8);
  return k;
}

// offset + step * key, clamped to [lo, hi], for an integral step and offset (below).
void dequantise_integral(const unsigned char* k, double* v, std::size_t count, double step, double offset, double lo,
                         double hi) noexcept {
  for (std::size_t i = 0; i < count; ++i) {
    const double x = offset + step * static_cast<double>(key_at(k, i));
    v[i] = std::min(hi, std::max(lo, x));
  }
}

// stored_as's float32 rule for offset + step * key, inlined: finite values only come
// from keys.
constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());
constexpr double kFloatOverflow = kFloatMax * (1 + 1e-7);
void dequantise_f32(const unsigned char* k, double* v, std::size_t count, const Quantiser& q) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    const double x = key_value(q, key_at(k, i));
    v[i] = x > kFloatOverflow ? inf
         : x < -kFloatOverflow ? -inf
                               : static_cast<double>(static_cast<float>(std::clamp(x, -kFloatMax, kFloatMax)));
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same four keys at a time. AVX2 converts no int64 to double, but a key k with
// |k| < 2^51 is exactly the double (bits of k + 2^52 + 2^51) - (2^52 + 2^51); four keys
// whose lanes are not all that small take the scalar loop. Multiply, then add, as above
// (no FMA in this target: the same roundings), and max then min in the scalar order
// (both zeros give lo, as std::max(lo, x) does): the same doubles bit for bit
// (unit_wavelet WaveletCodec.DequantiserAvx2MatchesScalar).
__attribute__((target("avx2"))) inline bool keys_small(__m256i key) {
  const __m256i below = _mm256_set1_epi64x(-(std::int64_t{1} << 51));
  const __m256i above = _mm256_set1_epi64x(std::int64_t{1} << 51);
  const __m256i outside = _mm256_or_si256(_mm256_cmpgt_epi64(below, key), _mm256_cmpgt_epi64(key, above));
  return _mm256_testz_si256(outside, outside);
}
__attribute__((target("avx2"))) inline __m256d small_keys_to_double(__m256i key) {
  const __m256i magic_i = _mm256_set1_epi64x(0x4338000000000000LL);  // the bits of 2^52 + 2^51
  const __m256d magic_d = _mm256_set1_pd(6755399441055744.0);
  return _mm256_sub_pd(_mm256_castsi256_pd(_mm256_add_epi64(key, magic_i)), magic_d);
}
__attribute__((target("avx2"))) inline __m256i load_keys(const unsigned char* k) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k));
}

__attribute__((target("avx2"))) void dequantise_integral_avx2(const unsigned char* k, double* v, std::size_t count,
                                                              double step, double offset, double lo,
                                                              double hi) noexcept {
  const __m256d s = _mm256_set1_pd(step), o = _mm256_set1_pd(offset), l = _mm256_set1_pd(lo), h = _mm256_set1_pd(hi);
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m256i key = load_keys(k + 8 * i);
    if (!keys_small(key)) {
      dequantise_integral(k + 8 * i, v + i, 4, step, offset, lo, hi);
      continue;
    }
    const __m256d x = _mm256_add_pd(o, _mm256_mul_pd(s, small_keys_to_double(key)));
    _mm256_storeu_pd(v + i, _mm256_min_pd(_mm256_max_pd(x, l), h));
  }
  dequantise_integral(k + 8 * i, v + i, count - i, step, offset, lo, hi);
}

// dequantise_f32 four keys at a time, as above: max then min is std::clamp for the
// finite x here (a zero keeps its sign either way), the conversions to float and back
// round as the scalar ones do (to nearest), and the overflow tests pick the infinities
// afterwards -- the same doubles bit for bit (a fifth of the plume's dequantising
// instructions were this loop in scalar form).
__attribute__((target("avx2"))) void dequantise_f32_avx2(const unsigned char* k, double* v, std::size_t count,
                                                         const Quantiser& q) noexcept {
  const __m256d s = _mm256_set1_pd(q.step), o = _mm256_set1_pd(q.offset);
  const __m256d m = _mm256_set1_pd(kFloatMax), big = _mm256_set1_pd(kFloatOverflow);
  const __m256d inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m256i key = load_keys(k + 8 * i);
    if (!keys_small(key)) {
      dequantise_f32(k + 8 * i, v + i, 4, q);
      continue;
    }
    const __m256d x = _mm256_add_pd(o, _mm256_mul_pd(s, small_keys_to_double(key)));
    const __m256d c = _mm256_min_pd(_mm256_max_pd(x, _mm256_sub_pd(_mm256_setzero_pd(), m)), m);
    __m256d r = _mm256_cvtps_pd(_mm256_cvtpd_ps(c));
    r = _mm256_blendv_pd(r, inf, _mm256_cmp_pd(x, big, _CMP_GT_OQ));
    r = _mm256_blendv_pd(r, _mm256_sub_pd(_mm256_setzero_pd(), inf), _mm256_cmp_pd(x, _mm256_sub_pd(_mm256_setzero_pd(), big), _CMP_LT_OQ));
    _mm256_storeu_pd(v + i, r);
  }
  dequantise_f32(k + 8 * i, v + i, count - i, q);
}
#endif

template <typename T>
void dequantise_as(const unsigned char* k, double* v, std::size_t count, const Quantiser& q) noexcept {
  // An integer step and offset (integer data, docs/volwave.md §3) give integral values
  // below 2^53, so the rounding is the identity there and only the clamp is left: a
  // branch-free loop, four voxels an instruction with AVX2 (a tenth of the MRI head's
  // decode instructions at E = 16 were this loop in scalar form). Beyond 2^53 every
  // double is integral too, and the clamp settles it.
  const double lo = static_cast<double>(std::numeric_limits<T>::lowest());
  const double hi = static_cast<double>(std::numeric_limits<T>::max());
  if (q.step == std::floor(q.step) && q.offset == std::floor(q.offset)) {
#if defined(__x86_64__) && defined(__GNUC__)
    if (cpu_has_avx2()) return dequantise_integral_avx2(k, v, count, q.step, q.offset, lo, hi);
#endif
    return dequantise_integral(k, v, count, q.step, q.offset, lo, hi);
  }
  for (std::size_t i = 0; i < count; ++i) v[i] = clamp_round<T>(key_value(q, key_at(k, i)));
}

void dequantise_run(const unsigned char* k, double* v, std::size_t count, const Quantiser& q, ScalarType type) {
  if (q.kind == KeyKind::float32_bits) {
    for (std::size_t i = 0; i < count; ++i) v[i] = static_cast<double>(key_float(key_at(k, i)));
    return;
  }
  // One loop per stored type, so the per-voxel work is a multiply, a rounding and a
  // clamp (the same arithmetic as stored_as(key_value(...)), hence the same values).
  switch (type) {
    case ScalarType::u8: return dequantise_as<std::uint8_t>(k, v, count, q);
    case ScalarType::i8: return dequantise_as<std::int8_t>(k, v, count, q);
    case ScalarType::u16: return dequantise_as<std::uint16_t>(k, v, count, q);
    case ScalarType::i16: return dequantise_as<std::int16_t>(k, v, count, q);
    case ScalarType::u32: return dequantise_as<std::uint32_t>(k, v, count, q);
    case ScalarType::i32: return dequantise_as<std::int32_t>(k, v, count, q);
    case ScalarType::f32:
#if defined(__x86_64__) && defined(__GNUC__)
      if (cpu_has_avx2()) return dequantise_f32_avx2(k, v, count, q);
#endif
      return dequantise_f32(k, v, count, q);
    case ScalarType::f64:
      for (std::size_t i = 0; i < count; ++i) v[i] = key_value(q, key_at(k, i));
      return;
    default:
      for (std::size_t i = 0; i < count; ++i) v[i] = stored_as(key_value(q, key_at(k, i)), type);
  }
}

// Whether the eight keys from key i on are all zero.
inline bool zero_group(const unsigned char* k, std::size_t i) noexcept {
  std::int64_t any = 0;
  for (std::size_t j = 0; j < 8; ++j) any |= key_at(k, i + j);
  return any == 0;
}

// dequantise_run over runs: groups of eight zero keys take the value of key 0 without
// the per-voxel arithmetic, and when that value is +0.0 -- whose bytes are those of the
// key 0, as when float data is quantised around 0 (docs/volwave.md §3) -- nothing is
// written at all when the values replace the keys in place. Empty space (98 % of the
// plume's voxels) then costs one test per eight voxels instead of a rounding and a
// clamp per voxel; dense data pays one OR of eight keys per 32 voxels.
// The value of the key 0, and its bytes.
struct ZeroValue {
  double value = 0;
  std::uint64_t bits = 0;
};
ZeroValue zero_value_of(const Quantiser& q, ScalarType type) {
  const std::int64_t zero_key = 0;
  ZeroValue z;
  dequantise_run(reinterpret_cast<const unsigned char*>(&zero_key), &z.value, 1, q, type);
  std::memcpy(&z.bits, &z.value, 8);
  return z;
}

void dequantise_block(const unsigned char* k, double* v, std::size_t count, const Quantiser& q, ScalarType type,
                      bool in_place, const ZeroValue& zero) {
  const double zero_value = zero.value;
  const std::uint64_t zero_bits = zero.bits;
  std::size_t i = 0;
  while (i < count) {
    std::size_t j = i;
    while (j + 8 <= count && zero_group(k, j)) j += 8;
    if (j > i && (zero_bits != 0 || !in_place)) std::fill(v + i, v + j, zero_value);
    // A run with non-zeros is taken 32 keys at a time: dense data checks one group in
    // four, and the few zero keys swept along are dequantised the long way.
    std::size_t e = j;
    while (e + 8 <= count && !zero_group(k, e)) e += 32;
    e = std::min(e, count);
    if (e + 8 > count) e = count;  // the tail (< 8 keys) the long way
    if (e > j) dequantise_run(k + 8 * j, v + j, e - j, q, type);
    i = e;
  }
}

}  // namespace

void dequantise(const std::vector<std::int64_t>& keys, const Quantiser& q, ScalarType type, std::vector<double>& values,
                int threads) {
  values.resize(keys.size());
  const std::size_t block = 1 << 16;
  const std::size_t n = keys.size();
  const auto* k = reinterpret_cast<const unsigned char*>(keys.data());
  const ZeroValue zero = zero_value_of(q, type);
  parallel_for((n + block - 1) / block, threads, [&](std::size_t b) {
    const std::size_t begin = b * block, end = std::min(n, (b + 1) * block);
    dequantise_block(k + 8 * begin, values.data() + begin, end - begin, q, type, false, zero);
  });
}

void dequantise_in_place(double* buffer, std::size_t n, const Quantiser& q, ScalarType type, int threads) {
  const ZeroValue zero = zero_value_of(q, type);
  const std::size_t block = 1 << 16;
  parallel_for((n + block - 1) / block, threads, [&](std::size_t b) {
    const std::size_t begin = b * block, end = std::min(n, (b + 1) * block);
    dequantise_block(reinterpret_cast<const unsigned char*>(buffer + begin), buffer + begin, end - begin, q, type, true, zero);
  });
}

void dequantise_rows_in_place(double* buffer, std::size_t row_length, const std::vector<RowSpan>& row_spans,
                               const Quantiser& q, ScalarType type, int threads) {
  const ZeroValue zero = zero_value_of(q, type);
  const std::size_t block = std::max<std::size_t>(1, (std::size_t{1} << 16) / std::max<std::size_t>(1, row_length));
  const std::size_t rows = row_spans.size();
  const RowSpan* spans = row_spans.data();
  parallel_for((rows + block - 1) / block, threads, [&](std::size_t b) {
    // Local copies: dequantise_block writes doubles, which (the buffer being punned,
    // -fno-strict-aliasing) the compiler must assume may change anything it reads
    // through a reference; the plume's 4,356 rows, 90 % empty, cost 20 instructions
    // each for the test alone.
    const std::size_t end = std::min(rows, (b + 1) * block);
    const bool fill = zero.bits != 0;
    for (std::size_t r = b * block; r < end; ++r) {
      double* row = buffer + r * row_length;
      const std::size_t from = spans[r].begin, to = spans[r].end;
      if (from < to)
        dequantise_block(reinterpret_cast<const unsigned char*>(row + from), row + from, to - from, q, type, true, zero);
      if (fill) {
        std::fill(row, row + std::min(from, to), zero.value);
        std::fill(row + std::max(from, to), row + row_length, zero.value);
      }
    }
  });
}

}  // namespace fest::wavelet
