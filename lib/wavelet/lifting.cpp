#include "wavelet/lifting.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string_view>

#include "core/cpu_features.hpp"
#include "core/parallel_for.hpp"

namespace fest::wavelet {

const char* wavelet_name(Wavelet w) noexcept {
  switch (w) {
    case Wavelet::haar: return "haar";
    case Wavelet::cdf53: return "cdf53";
    case Wavelet::cdf97: return "cdf97";
  }
  return "?";
}

bool parse_wavelet(const char* name, Wavelet& out) noexcept {
  const std::string_view n(name);
  if (n == "haar") out = Wavelet::haar;
  else if (n == "cdf53" || n == "53" || n == "5/3") out = Wavelet::cdf53;
  else if (n == "cdf97" || n == "97" || n == "9/7") out = Wavelet::cdf97;
  else return false;
  return true;
}

bool wavelet_is_integer(Wavelet w) noexcept { return w != Wavelet::cdf97; }

Dims level_dims(const Dims& dims, int level) noexcept {
  Dims d = dims;
  for (int l = 0; l < level; ++l)
    for (auto& n : d) n = (n + 1) / 2;
  return d;
}

int default_levels(const Dims& dims) noexcept {
  int levels = 0;
  while (levels < 8) {
    const Dims d = level_dims(dims, levels);
    if (std::max({d[0], d[1], d[2]}) <= 8) break;
    ++levels;
  }
  return levels;
}

std::vector<Subband> subbands(const Dims& dims, int levels) {
  std::vector<Subband> out;
  Subband approx;
  approx.level = levels;
  approx.hi = level_dims(dims, levels);
  out.push_back(approx);
  for (int l = levels - 1; l >= 0; --l) {
    const Dims n = level_dims(dims, l), h = level_dims(dims, l + 1);
    for (int o = 1; o < 8; ++o) {
      Subband b;
      b.level = l;
      b.orientation = o;
      for (int a = 0; a < 3; ++a) {
        const bool high = (o >> a) & 1;
        b.lo[a] = high ? h[a] : 0;
        b.hi[a] = high ? n[a] : h[a];
      }
      if (b.size() > 0) out.push_back(b);
    }
  }
  return out;
}

int chunk_of(const Subband& band, int levels) noexcept {
  return band.orientation == 0 ? 0 : levels - band.level;
}

// ---- 1-D lifting ----------------------------------------------------------------
// Even samples s[i] = x[2i] (h = ceil(n/2) of them), odd samples d[i] = x[2i+1]
// (m = floor(n/2)). Whole-sample symmetric extension: x[n] = x[n-2], x[-1] = x[1],
// which for the lifting steps means s[h] -> s[h-1] and d[-1] -> d[0], d[m] -> d[m-1].

namespace {

// Floor division by 2 and 4 of possibly negative integers (arithmetic shifts).
inline std::int64_t floor2(std::int64_t v) { return v >> 1; }
inline std::int64_t floor4(std::int64_t v) { return v >> 2; }

}  // namespace

void forward_line(std::int64_t* x, std::size_t n, Wavelet w, std::int64_t* scratch) {
  if (n < 2) return;
  const std::size_t h = (n + 1) / 2, m = n / 2;
  std::int64_t* s = scratch;
  std::int64_t* d = scratch + h;
  if (w == Wavelet::haar) {
    // S-transform: d = odd - even, s = even + floor(d / 2) (the integer mean).
    for (std::size_t i = 0; i < m; ++i) {
      d[i] = x[2 * i + 1] - x[2 * i];
      s[i] = x[2 * i] + floor2(d[i]);
    }
    if (h > m) s[h - 1] = x[n - 1];
  } else {
    // JPEG 2000 reversible 5/3: predict d from the two even neighbours, update s from
    // the two neighbouring details.
    for (std::size_t i = 0; i < m; ++i) {
      const std::int64_t right = (2 * i + 2 < n) ? x[2 * i + 2] : x[2 * i];
      d[i] = x[2 * i + 1] - floor2(x[2 * i] + right);
    }
    for (std::size_t i = 0; i < h; ++i) {
      const std::int64_t left = d[i > 0 ? i - 1 : 0];
      const std::int64_t right = d[i < m ? i : m - 1];
      s[i] = x[2 * i] + floor4(left + right + 2);
    }
  }
  std::memcpy(x, scratch, n * sizeof(std::int64_t));
}

namespace {

// CDF 9/7 lifting constants (Daubechies & Sweldens 1998, as in JPEG 2000 Part 1).
constexpr double kAlpha = -1.586134342059924;
constexpr double kBeta = -0.052980118572961;
constexpr double kGamma = 0.882911075530934;
constexpr double kDelta = 0.443506852043971;
constexpr double kK = 1.230174104914001;
// After the four steps a constant line gives s = K and an alternating one d = -2/K;
// these scales make both filters' gains sqrt(2), i.e. the transform nearly orthonormal,
// so a uniform quantiser step means the same error in every subband.
const double kLowScale = std::sqrt(2.0) / kK;
const double kHighScale = kK / std::sqrt(2.0);

void predict(double* s, double* d, std::size_t h, std::size_t m, double c) {
  for (std::size_t i = 0; i < m; ++i) d[i] += c * (s[i] + s[i + 1 < h ? i + 1 : i]);
}
void update(double* s, const double* d, std::size_t h, std::size_t m, double c) {
  for (std::size_t i = 0; i < h; ++i) s[i] += c * (d[i > 0 ? i - 1 : 0] + d[i < m ? i : m - 1]);
}

}  // namespace

void forward_line_97(double* x, std::size_t n, double* scratch) {
  if (n < 2) return;
  const std::size_t h = (n + 1) / 2, m = n / 2;
  double* s = scratch;
  double* d = scratch + h;
  for (std::size_t i = 0; i < h; ++i) s[i] = x[2 * i];
  for (std::size_t i = 0; i < m; ++i) d[i] = x[2 * i + 1];
  predict(s, d, h, m, kAlpha);
  update(s, d, h, m, kBeta);
  predict(s, d, h, m, kGamma);
  update(s, d, h, m, kDelta);
  for (std::size_t i = 0; i < h; ++i) x[i] = s[i] * kLowScale;
  for (std::size_t i = 0; i < m; ++i) x[h + i] = d[i] * kHighScale;
}

void inverse_line_97(double* x, std::size_t n, double* scratch) {
  if (n < 2) return;
  const std::size_t h = (n + 1) / 2, m = n / 2;
  double* s = scratch;
  double* d = scratch + h;
  for (std::size_t i = 0; i < h; ++i) s[i] = x[i] / kLowScale;
  for (std::size_t i = 0; i < m; ++i) d[i] = x[h + i] / kHighScale;
  update(s, d, h, m, -kDelta);
  predict(s, d, h, m, -kGamma);
  update(s, d, h, m, -kBeta);
  predict(s, d, h, m, -kAlpha);
  for (std::size_t i = 0; i < h; ++i) x[2 * i] = s[i];
  for (std::size_t i = 0; i < m; ++i) x[2 * i + 1] = d[i];
}

// ---- 3-D ---------------------------------------------------------------------------

namespace {

// Lines along axis a of the cube `c` inside an array of extent `dims`. Lines along y and
// z are gathered kBlock at a time (neighbouring x), so each read touches whole cache lines.
constexpr std::size_t kBlock = 16;

template <typename T, typename LineOp>
void transform_axis(T* data, const Dims& dims, const Dims& c, int axis, int threads, const LineOp& op) {
  const std::size_t n = c[axis];
  if (n < 2) return;
  const std::size_t sx = 1, sy = dims[0], sz = dims[0] * dims[1];
  if (axis == 0) {
    parallel_for(c[2], threads, [&](std::size_t z) {
      std::vector<T> scratch(n);
      for (std::size_t y = 0; y < c[1]; ++y) op(&data[y * sy + z * sz], n, scratch.data());
    });
    return;
  }
  const std::size_t stride = axis == 1 ? sy : sz;
  const std::size_t outer = axis == 1 ? c[2] : c[1];
  const std::size_t outer_stride = axis == 1 ? sz : sy;
  parallel_for(outer, threads, [&](std::size_t o) {
    std::vector<T> lines(kBlock * n), scratch(n);
    for (std::size_t x0 = 0; x0 < c[0]; x0 += kBlock) {
      const std::size_t w = std::min(kBlock, c[0] - x0);
      T* base = &data[o * outer_stride + x0 * sx];
      for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = 0; j < w; ++j) lines[j * n + k] = base[k * stride + j];
      for (std::size_t j = 0; j < w; ++j) op(&lines[j * n], n, scratch.data());
      for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = 0; j < w; ++j) base[k * stride + j] = lines[j * n + k];
    }
  });
}

// Whether count values are all zero: eight at a time, so the loop vectorises, and a
// return at the first block holding a non-zero.
bool all_zero(const std::int64_t* p, std::size_t count) noexcept {
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    std::int64_t any = 0;
    for (std::size_t j = 0; j < 8; ++j) any |= p[i + j];
    if (any != 0) return false;
  }
  std::int64_t any = 0;
  for (; i < count; ++i) any |= p[i];
  return any == 0;
}

// The two lifting steps of CDF 5/3 and the Haar step over a row of w lines:
//   even  e[j] = s[j] - floor((l[j] + r[j] + 2) / 4)
//   odd   o[j] = d[j] + floor((e[j] + e2[j]) / 2)
//   haar  e[j] = s[j] - floor(d[j] / 2), o[j] = d[j] + e[j]
// Portable loops, and AVX2 ones (four lines per instruction) where the CPU has it.
// AVX2 has no 64-bit arithmetic shift, so floor(v / 2^k) is computed as
// ~(~v >>> k) for v < 0 (the sign mask from a compare with 0): integer arithmetic either
// way, so both paths give the same values bit for bit. The int64 shifts kept the
// portable loops scalar (callgrind: ~5 instructions per sample and step).
void even_row(const std::int64_t* s, const std::int64_t* l, const std::int64_t* r, std::int64_t* e, std::size_t w) {
  for (std::size_t j = 0; j < w; ++j) e[j] = s[j] - floor4(l[j] + r[j] + 2);
}
void odd_row(const std::int64_t* d, const std::int64_t* e, const std::int64_t* e2, std::int64_t* o, std::size_t w) {
  for (std::size_t j = 0; j < w; ++j) o[j] = d[j] + floor2(e[j] + e2[j]);
}
void haar_row(const std::int64_t* s, const std::int64_t* d, std::int64_t* e, std::int64_t* o, std::size_t w) {
  for (std::size_t j = 0; j < w; ++j) {
    const std::int64_t even = s[j] - floor2(d[j]);
    e[j] = even;
    o[j] = d[j] + even;
  }
}
// x[2j] = e[j], x[2j + 1] = o[j]: a line's samples from its lifted halves.
void interleave_row(const std::int64_t* e, const std::int64_t* o, std::int64_t* x, std::size_t w) {
  for (std::size_t j = 0; j < w; ++j) {
    x[2 * j] = e[j];
    x[2 * j + 1] = o[j];
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) inline __m256i floor_shift(__m256i v, int k) {
  const __m256i sign = _mm256_cmpgt_epi64(_mm256_setzero_si256(), v);
  return _mm256_xor_si256(_mm256_srli_epi64(_mm256_xor_si256(v, sign), k), sign);
}
__attribute__((target("avx2"))) inline __m256i load4(const std::int64_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}
__attribute__((target("avx2"))) inline void store4(std::int64_t* p, __m256i v) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v);
}

__attribute__((target("avx2"))) void even_row_avx2(const std::int64_t* s, const std::int64_t* l, const std::int64_t* r,
                                                   std::int64_t* e, std::size_t w) {
  const __m256i two = _mm256_set1_epi64x(2);
  std::size_t j = 0;
  for (; j + 4 <= w; j += 4)
    store4(e + j, _mm256_sub_epi64(load4(s + j), floor_shift(_mm256_add_epi64(_mm256_add_epi64(load4(l + j), load4(r + j)), two), 2)));
  even_row(s + j, l + j, r + j, e + j, w - j);
}
__attribute__((target("avx2"))) void odd_row_avx2(const std::int64_t* d, const std::int64_t* e, const std::int64_t* e2,
                                                  std::int64_t* o, std::size_t w) {
  std::size_t j = 0;
  for (; j + 4 <= w; j += 4)
    store4(o + j, _mm256_add_epi64(load4(d + j), floor_shift(_mm256_add_epi64(load4(e + j), load4(e2 + j)), 1)));
  odd_row(d + j, e + j, e2 + j, o + j, w - j);
}
__attribute__((target("avx2"))) void haar_row_avx2(const std::int64_t* s, const std::int64_t* d, std::int64_t* e,
                                                   std::int64_t* o, std::size_t w) {
  std::size_t j = 0;
  for (; j + 4 <= w; j += 4) {
    const __m256i dj = load4(d + j);
    const __m256i even = _mm256_sub_epi64(load4(s + j), floor_shift(dj, 1));
    store4(e + j, even);
    store4(o + j, _mm256_add_epi64(dj, even));
  }
  haar_row(s + j, d + j, e + j, o + j, w - j);
}
__attribute__((target("avx2"))) void interleave_row_avx2(const std::int64_t* e, const std::int64_t* o, std::int64_t* x,
                                                        std::size_t w) {
  std::size_t j = 0;
  for (; j + 4 <= w; j += 4) {
    const __m256i ej = load4(e + j), oj = load4(o + j);
    const __m256i lo = _mm256_unpacklo_epi64(ej, oj), hi = _mm256_unpackhi_epi64(ej, oj);  // e0 o0 e2 o2, e1 o1 e3 o3
    store4(x + 2 * j, _mm256_permute2x128_si256(lo, hi, 0x20));
    store4(x + 2 * j + 4, _mm256_permute2x128_si256(lo, hi, 0x31));
  }
  interleave_row(e + j, o + j, x + 2 * j, w - j);
}
#endif

void lift_even(const std::int64_t* s, const std::int64_t* l, const std::int64_t* r, std::int64_t* e, std::size_t w) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) return even_row_avx2(s, l, r, e, w);
#endif
  even_row(s, l, r, e, w);
}
void lift_odd(const std::int64_t* d, const std::int64_t* e, const std::int64_t* e2, std::int64_t* o, std::size_t w) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) return odd_row_avx2(d, e, e2, o, w);
#endif
  odd_row(d, e, e2, o, w);
}
void lift_haar(const std::int64_t* s, const std::int64_t* d, std::int64_t* e, std::int64_t* o, std::size_t w) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) return haar_row_avx2(s, d, e, o, w);
#endif
  haar_row(s, d, e, o, w);
}
void interleave(const std::int64_t* e, const std::int64_t* o, std::int64_t* x, std::size_t w) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) return interleave_row_avx2(e, o, x, w);
#endif
  interleave_row(e, o, x, w);
}

// The lifting of the outputs [2p, n) of a line x of n, for inverse_line (p = 0) and the
// lines along x of a sparse volume (inverse_axis_x): the even samples e_i = x'[2i],
// i in [p, h), and the odd ones o_i = x'[2i + 1], i in [p, m), into scratch at i and
// h + i; x is only read. A line's low and high halves are contiguous, so the steps are
// the row steps above with w = the count (AVX2 where the CPU has it); the symmetric
// extension (d[-1] -> d[0], d[m] -> d[m-1], x[n] -> x[n-2]) only touches the first and
// last samples, done apart. The same integers, element by element, as the interleaved
// scalar loops this replaced, at a third of their instructions on the plume's lines
// (docs/volwave.md §2). p < m.
void lift_line(const std::int64_t* x, std::size_t n, Wavelet w, std::int64_t* scratch, std::size_t p) {
  const std::size_t h = (n + 1) / 2, m = n / 2;
  const std::int64_t* s = x;
  const std::int64_t* d = x + h;
  std::int64_t* e = scratch;
  std::int64_t* o = scratch + h;
  if (w == Wavelet::haar) {
    lift_haar(s + p, d + p, e + p, o + p, m - p);
    if (h > m) e[m] = s[m];
    return;
  }
  std::size_t i = p;
  if (i == 0) {
    e[0] = s[0] - floor4(d[0] + d[0] + 2);
    i = 1;
  }
  if (m > i) lift_even(s + i, d + i - 1, d + i, e + i, m - i);
  if (h > m) e[m] = s[m] - floor4(d[m - 1] + d[m - 1] + 2);
  if (m - 1 > p) lift_odd(d + p, e + p, e + p + 1, o + p, m - 1 - p);
  o[m - 1] = d[m - 1] + floor2(e[m - 1] + (h > m ? e[m] : e[m - 1]));
}

// x[2p, n) from lift_line's scratch.
void place_line(const std::int64_t* scratch, std::size_t n, std::size_t p, std::int64_t* x) {
  const std::size_t h = (n + 1) / 2, m = n / 2;
  interleave(scratch + p, scratch + h + p, x + 2 * p, m - p);
  if (h > m) x[n - 1] = scratch[m];
}

}  // namespace

void inverse_line(std::int64_t* x, std::size_t n, Wavelet w, std::int64_t* scratch) {
  if (n < 2) return;
  lift_line(x, n, w, scratch, 0);
  place_line(scratch, n, 0, x);
}

namespace {

// The inverse integer lifting of many lines at once, stored sample-major: in[k] points
// to sample k of every line (w values, contiguous), k in [0, h) the low half and [h, n)
// the high half; sample k of the result goes to dst + k * stride. The arithmetic is
// inverse_line's, element by element, so the values are the same; but every step is a
// branch-free loop over contiguous memory, and the boundary cases (the symmetric
// extension) are settled per row, not per sample.
// Only the output rows flagged in out_flags are computed: the others are known to be
// zero (propagate, docs/volwave.md §4), and are written as zeros only where they held a
// possibly non-zero input (in_flags), since the rest already hold zeros. A sample
// depends only on samples near half its index, so on the plume most of a line's outputs
// are skipped this way. Every even row is settled (computed, zeroed or already zero)
// before the odd rows read it.
template <typename Steps>
__attribute__((always_inline)) inline void inverse_rows_with(const std::int64_t* const* in, std::size_t w, std::size_t n,
                                                             Wavelet wav, std::int64_t* dst, std::size_t stride,
                                                             const std::uint8_t* in_flags, const std::uint8_t* out_flags) {
  const std::size_t h = (n + 1) / 2, m = n / 2;
  auto s = [&](std::size_t i) { return in[i]; };
  auto d = [&](std::size_t i) { return in[h + i]; };
  auto out = [&](std::size_t k) { return dst + k * stride; };
  auto settle_zero = [&](std::size_t k) {
    if (in_flags[k]) std::memset(out(k), 0, w * sizeof(std::int64_t));
  };
  if (wav == Wavelet::haar) {
    for (std::size_t i = 0; i < m; ++i) {
      if (out_flags[2 * i] | out_flags[2 * i + 1]) {
        Steps::haar(s(i), d(i), out(2 * i), out(2 * i + 1), w);
      } else {
        settle_zero(2 * i);
        settle_zero(2 * i + 1);
      }
    }
    if (h > m) {
      if (out_flags[n - 1]) std::memcpy(out(n - 1), s(h - 1), w * sizeof(std::int64_t));
      else settle_zero(n - 1);
    }
    return;
  }
  // Even samples (undo the update), then odd samples (undo the prediction) from the
  // even ones just written.
  for (std::size_t i = 0; i < h; ++i) {
    if (!out_flags[2 * i]) {
      settle_zero(2 * i);
      continue;
    }
    const std::int64_t* left = d(i > 0 ? i - 1 : 0);
    const std::int64_t* right = d(i < m ? i : m - 1);
    Steps::even(s(i), left, right, out(2 * i), w);
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (!out_flags[2 * i + 1]) {
      settle_zero(2 * i + 1);
      continue;
    }
    const std::int64_t* e = out(2 * i);
    const std::int64_t* e2 = out(2 * i + 2 < n ? 2 * i + 2 : 2 * i);
    Steps::odd(d(i), e, e2, out(2 * i + 1), w);
  }
}

// The row steps as types, so that inverse_rows is compiled once per instruction set with
// its steps inlined: dispatching per row (a call, the CPU test, the scalar tail's test)
// cost as much as the AVX2 loop on the plume's short runs of columns.
struct ScalarSteps {
  static void even(const std::int64_t* s, const std::int64_t* l, const std::int64_t* r, std::int64_t* e, std::size_t w) {
    even_row(s, l, r, e, w);
  }
  static void odd(const std::int64_t* d, const std::int64_t* e, const std::int64_t* e2, std::int64_t* o, std::size_t w) {
    odd_row(d, e, e2, o, w);
  }
  static void haar(const std::int64_t* s, const std::int64_t* d, std::int64_t* e, std::int64_t* o, std::size_t w) {
    haar_row(s, d, e, o, w);
  }
};
void inverse_rows_scalar(const std::int64_t* const* in, std::size_t w, std::size_t n, Wavelet wav, std::int64_t* dst,
                         std::size_t stride, const std::uint8_t* in_flags, const std::uint8_t* out_flags) {
  inverse_rows_with<ScalarSteps>(in, w, n, wav, dst, stride, in_flags, out_flags);
}
#if defined(__x86_64__) && defined(__GNUC__)
struct Avx2Steps {
  __attribute__((target("avx2"))) static void even(const std::int64_t* s, const std::int64_t* l, const std::int64_t* r,
                                                   std::int64_t* e, std::size_t w) {
    even_row_avx2(s, l, r, e, w);
  }
  __attribute__((target("avx2"))) static void odd(const std::int64_t* d, const std::int64_t* e, const std::int64_t* e2,
                                                  std::int64_t* o, std::size_t w) {
    odd_row_avx2(d, e, e2, o, w);
  }
  __attribute__((target("avx2"))) static void haar(const std::int64_t* s, const std::int64_t* d, std::int64_t* e,
                                                   std::int64_t* o, std::size_t w) {
    haar_row_avx2(s, d, e, o, w);
  }
};
__attribute__((target("avx2"))) void inverse_rows_avx2(const std::int64_t* const* in, std::size_t w, std::size_t n,
                                                       Wavelet wav, std::int64_t* dst, std::size_t stride,
                                                       const std::uint8_t* in_flags, const std::uint8_t* out_flags) {
  inverse_rows_with<Avx2Steps>(in, w, n, wav, dst, stride, in_flags, out_flags);
}
#endif
void inverse_rows(const std::int64_t* const* in, std::size_t w, std::size_t n, Wavelet wav, std::int64_t* dst,
                  std::size_t stride, const std::uint8_t* in_flags, const std::uint8_t* out_flags) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) return inverse_rows_avx2(in, w, n, wav, dst, stride, in_flags, out_flags);
#endif
  inverse_rows_scalar(in, w, n, wav, dst, stride, in_flags, out_flags);
}

// The inverse integer transform of one level along y or z: blocks of up to kRowBlock
// neighbouring x (contiguous) are copied sample-major into a scratch buffer (whole
// cache lines, one memcpy per sample) and transformed from there straight back.
constexpr std::size_t kRowBlock = 256;
constexpr std::size_t kGroups = kRowBlock / 8;  // groups of 8 columns in a block
static_assert(kGroups <= 64, "a block's groups are the bits of one std::uint64_t");

// The input of rows known to be zero: inverse_rows reads it instead of a copy.
alignas(64) constexpr std::int64_t kZeroRow[kRowBlock] = {};

// Which samples of a line of n can be non-zero after its inverse transform, from which
// can be before it (storage order: low half [0, h), high half [h, n)): sample k
// depends on low and high samples near k/2 only (CDF 5/3: even 2i on s_i, d_(i-1),
// d_i; odd 2i+1 on d_i and the evens 2i, 2i+2; Haar less), so a non-zero at low or
// high index i can reach the samples [2i - 2, 2i + 4) at most, with a margin.
void propagate(std::size_t n, const std::uint8_t* in, std::uint8_t* out) noexcept {
  const std::size_t h = (n + 1) / 2;
  std::fill_n(out, n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (!in[k]) continue;
    const std::size_t i = k < h ? k : k - h;
    const std::size_t a = i >= 1 ? 2 * i - 2 : 0, b = std::min(n, 2 * i + 4);
    std::fill(out + a, out + b, 1);
  }
}

// Flags of the rows (y + dims[1] * z): 1 where a row of the cube being transformed may
// hold non-zeros, 0 where it is known to be zero.
using RowFlags = std::vector<std::uint8_t>;

// body(begin, end) over [0, count): in one call on this thread when threads == 1, so
// that a pass sets up its scratch once instead of once per plane (malloc and free were
// 3 % of the plume's decode); else one job per item, since the planes holding a sparse
// volume's non-zeros are few and uneven.
template <typename Body>
void for_each_range(std::size_t count, int threads, const Body& body) {
  if (threads <= 1) return body(std::size_t{0}, count);
  parallel_for(count, threads, [&](std::size_t i) { body(i, i + 1); });
}

// The groups of 8 columns (bit g: columns [8g, 8g + 8) of the w from `base`) where a
// flagged row (in[k], row k at base + k * stride) holds a non-zero. A group is looked
// at only until a row shows it non-zero, so dense data stops looking after its first
// row; a single zero group between two others is added (one run costs less than two).
std::uint64_t nonzero_groups(const std::int64_t* base, std::size_t stride, std::size_t w, const std::uint8_t* in,
                             std::size_t n) noexcept {
  const std::size_t groups = (w + 7) / 8;
  const std::uint64_t all = groups == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << groups) - 1;
  std::uint64_t mask = 0;
  for (std::size_t k = 0; k < n && mask != all; ++k) {
    if (!in[k]) continue;
    const std::int64_t* r = base + k * stride;
    for (std::size_t g = 0; g < groups; ++g)
      if (!(mask >> g & 1) && !all_zero(r + 8 * g, std::min<std::size_t>(8, w - 8 * g))) mask |= std::uint64_t{1} << g;
  }
  return mask | ((mask >> 1) & (mask << 1) & all);
}

// The inverse along z (axis 2, one plane of fixed y at a time) or y (axis 1, fixed z)
// of the cube `c`: only planes with a flagged row are transformed, in them only the
// runs of columns (x, in groups of eight) where a flagged row holds a non-zero, and of
// those only the output samples that can be non-zero (propagate). Rows known to be
// zero are not copied (inverse_rows reads kZeroRow for them). Afterwards the flags of
// each plane say which output rows can be non-zero.
void inverse_axis_rows(std::int64_t* data, const Dims& dims, const Dims& c, int axis, Wavelet wav,
                       int threads, RowFlags& flags) {
  const std::size_t n = c[axis];
  if (n < 2) return;
  const std::size_t sy = dims[0], sz = dims[0] * dims[1], ny = dims[1];
  const std::size_t stride = axis == 1 ? sy : sz;
  const std::size_t outer = axis == 1 ? c[2] : c[1];
  const std::size_t outer_stride = axis == 1 ? sz : sy;
  // Flag of sample k of the lines of plane o.
  const std::size_t flag_stride = axis == 1 ? 1 : ny, flag_outer = axis == 1 ? ny : 1;
  // Which planes hold a flagged row, by loops over contiguous flags (gathering a plane's
  // flags along z is strided: 13 instructions a flag on the plume, where 60 % of the
  // planes hold none).
  std::vector<std::uint8_t> plane_flagged(outer, 0);
  const std::uint8_t* f = flags.data();
  for (std::size_t z = 0; z < c[2]; ++z) {
    const std::uint8_t* row_flags = f + ny * z;
    if (axis == 1) {
      std::uint8_t any = 0;
      for (std::size_t y = 0; y < c[1]; ++y) any |= row_flags[y];
      plane_flagged[z] = any;
    } else {
      for (std::size_t y = 0; y < c[1]; ++y) plane_flagged[y] |= row_flags[y];
    }
  }
  for_each_range(outer, threads, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint8_t> in(n), out(n);
    std::vector<const std::int64_t*> src(n);
    // Left uninitialised (every element is written before it is read): zeroing it cost
    // as much as the transform. Allocated at the first plane that needs it.
    std::unique_ptr<std::int64_t[]> rows;
    for (std::size_t o = begin; o < end; ++o) {
      if (!plane_flagged[o]) continue;
      std::uint8_t* plane_flags = flags.data() + o * flag_outer;
      for (std::size_t k = 0; k < n; ++k) in[k] = plane_flags[k * flag_stride];
      propagate(n, in.data(), out.data());
      bool transformed = false;
      for (std::size_t x0 = 0; x0 < c[0]; x0 += kRowBlock) {
        const std::size_t w = std::min(kRowBlock, c[0] - x0);
        std::int64_t* base = &data[o * outer_stride + x0];
        // Every column (one x) is a line of its own: all zero in, all zero out, in
        // place. So only the runs of columns holding a non-zero are transformed.
        const std::uint64_t mask = nonzero_groups(base, stride, w, in.data(), n);
        if (mask == 0) continue;
        transformed = true;
        if (!rows) rows.reset(new std::int64_t[n * std::min(kRowBlock, c[0])]);
        for (std::size_t g = 0; g < kGroups; ++g) {
          if (!(mask >> g & 1)) continue;
          std::size_t g_end = g + 1;
          while (g_end < kGroups && (mask >> g_end & 1)) ++g_end;
          const std::size_t x_lo = 8 * g, x_hi = std::min(w, 8 * g_end), cols = x_hi - x_lo;
          for (std::size_t k = 0; k < n; ++k) {
            if (!in[k]) {
              src[k] = kZeroRow;
              continue;
            }
            std::memcpy(&rows[k * cols], base + x_lo + k * stride, cols * sizeof(std::int64_t));
            src[k] = &rows[k * cols];
          }
          inverse_rows(src.data(), cols, n, wav, base + x_lo, stride, in.data(), out.data());
          g = g_end;
        }
      }
      if (!transformed) std::fill(out.begin(), out.end(), 0);  // flagged, but zero after all
      for (std::size_t k = 0; k < n; ++k) plane_flags[k * flag_stride] = out[k];
    }
  });
}

// The index of the first non-zero of p[0, count), count if none: eight values a test
// (all_zero), then one at a time. Only from the front: a scan from the back as well
// (to narrow the lines' ends too) made the MRI head's decode 3 % slower in CPU time --
// its rows, read from memory, end in runs of zeros, and the scans against the stream
// of the lifting defeat the prefetcher -- for 0.13 M instructions of the plume's 8.8 M.
std::size_t first_nonzero(const std::int64_t* p, std::size_t count) noexcept {
  std::size_t i = 0;
  while (i + 8 <= count && all_zero(p + i, 8)) i += 8;
  while (i < count && p[i] == 0) ++i;
  return i;
}

// The inverse along x of the flagged rows of the cube `c` (the others are zero). A row
// is lifted from the first output that can be non-zero on (propagate's reach, from the
// first non-zeros of its low and high halves); the inputs before it, known to turn to
// zero, are zeroed. A row found all zero loses its flag. `spans`, when given (the last
// level), receives per row the columns outside which the result is zero.
void inverse_axis_x(std::int64_t* data, const Dims& dims, const Dims& c, Wavelet wav, int threads, RowFlags& flags,
                    std::vector<RowSpan>* spans) {
  const std::size_t n = c[0];
  const std::size_t sy = dims[0], sz = dims[0] * dims[1], ny = dims[1];
  if (n < 2) {
    if (spans)
      for (std::size_t r = 0; r < flags.size(); ++r) (*spans)[r] = flags[r] ? RowSpan{0, 1} : RowSpan{};
    return;
  }
  const std::size_t h = (n + 1) / 2, m = n / 2;
  for_each_range(c[2], threads, [&](std::size_t begin, std::size_t end) {
    std::vector<std::int64_t> scratch(n);
    for (std::size_t z = begin; z < end; ++z)
      for (std::size_t y = 0; y < c[1]; ++y) {
        const std::size_t r = y + ny * z;
        if (!flags[r]) continue;
        std::int64_t* line = data + y * sy + z * sz;
        // The high half is looked at only up to the low half's first non-zero (the
        // first index of either is what counts), so a dense row costs two tests.
        const std::size_t lo = first_nonzero(line, h), hi = first_nonzero(line + h, std::min(m, lo));
        if (lo == h && hi == m) {
          flags[r] = 0;
          if (spans) (*spans)[r] = RowSpan{};
          continue;
        }
        const std::size_t first = std::min(lo, hi);
        const std::size_t a = first >= 1 ? 2 * first - 2 : 0;
        lift_line(line, n, wav, scratch.data(), a / 2);
        // The inputs before a turn to zero: low ones from lo on; no high one, since
        // a < h + first.
        if (lo < a) std::fill(line + lo, line + std::min(h, a), 0);
        place_line(scratch.data(), n, a / 2, line);
        if (spans) (*spans)[r] = RowSpan{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(n)};
      }
  });
}

void inverse_3d_rows(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads, RowFlags& flags,
                     const std::vector<RowList>* add, std::vector<RowSpan>* spans) {
  if (add)
    for (std::size_t r : (*add)[static_cast<std::size_t>(levels)]) flags[r] = 1;
  for (int l = levels - 1; l >= 0; --l) {
    const Dims c = level_dims(dims, l);
    // The passes clear the flags of rows they find zero inside the cube, but such a row
    // goes on past c[0] with the finer levels' details: the rows holding those are
    // flagged again here (all rows, when the caller does not know which).
    if (add)
      for (std::size_t r : (*add)[static_cast<std::size_t>(l)]) flags[r] = 1;
    else
      std::fill(flags.begin(), flags.end(), 1);
    inverse_axis_rows(data, dims, c, 2, w, threads, flags);
    inverse_axis_rows(data, dims, c, 1, w, threads, flags);
    inverse_axis_x(data, dims, c, w, threads, flags, l == 0 ? spans : nullptr);
  }
  if (spans && levels == 0)
    for (std::size_t r = 0; r < flags.size(); ++r)
      (*spans)[r] = flags[r] ? RowSpan{0, static_cast<std::uint32_t>(dims[0])} : RowSpan{};
}

}  // namespace

void forward_3d(std::vector<std::int64_t>& data, const Dims& dims, int levels, Wavelet w, int threads) {
  auto op = [w](std::int64_t* line, std::size_t n, std::int64_t* scratch) { forward_line(line, n, w, scratch); };
  for (int l = 0; l < levels; ++l) {
    const Dims c = level_dims(dims, l);
    for (int a = 0; a < 3; ++a) transform_axis(data.data(), dims, c, a, threads, op);
  }
}

void inverse_3d(std::vector<std::int64_t>& data, const Dims& dims, int levels, Wavelet w, int threads) {
  inverse_3d(data.data(), dims, levels, w, threads);
}

void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads) {
  RowFlags all(dims[1] * dims[2], 1);
  inverse_3d_rows(data, dims, levels, w, threads, all, nullptr, nullptr);
}

void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads,
                const std::vector<RowList>& nonzero_rows, std::vector<RowSpan>* row_spans) {
  RowFlags flags(dims[1] * dims[2], 0);
  if (row_spans) row_spans->assign(flags.size(), RowSpan{});
  inverse_3d_rows(data, dims, levels, w, threads, flags, &nonzero_rows, row_spans);
}

void forward_3d(std::vector<double>& data, const Dims& dims, int levels, int threads) {
  auto op = [](double* line, std::size_t n, double* scratch) { forward_line_97(line, n, scratch); };
  for (int l = 0; l < levels; ++l) {
    const Dims c = level_dims(dims, l);
    for (int a = 0; a < 3; ++a) transform_axis(data.data(), dims, c, a, threads, op);
  }
}

void inverse_3d(std::vector<double>& data, const Dims& dims, int levels, int threads) {
  auto op = [](double* line, std::size_t n, double* scratch) { inverse_line_97(line, n, scratch); };
  for (int l = levels - 1; l >= 0; --l) {
    const Dims c = level_dims(dims, l);
    for (int a = 2; a >= 0; --a) transform_axis(data.data(), dims, c, a, threads, op);
  }
}

}  // namespace fest::wavelet
