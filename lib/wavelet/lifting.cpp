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

void inverse_line(std::int64_t* x, std::size_t n, Wavelet w, std::int64_t* scratch) {
  if (n < 2) return;
  const std::size_t h = (n + 1) / 2, m = n / 2;
  std::memcpy(scratch, x, n * sizeof(std::int64_t));
  const std::int64_t* s = scratch;
  const std::int64_t* d = scratch + h;
  if (w == Wavelet::haar) {
    for (std::size_t i = 0; i < m; ++i) {
      x[2 * i] = s[i] - floor2(d[i]);
      x[2 * i + 1] = d[i] + x[2 * i];
    }
    if (h > m) x[n - 1] = s[h - 1];
  } else {
    // The symmetric extension (d[-1] -> d[0], d[m] -> d[m-1], x[n] -> x[n-2]) only
    // touches the first and last samples: those are done apart, the interior loops
    // have no branches.
    x[0] = s[0] - floor4(d[0] + d[0] + 2);
    for (std::size_t i = 1; i < m; ++i) x[2 * i] = s[i] - floor4(d[i - 1] + d[i] + 2);
    if (h > m) x[2 * m] = s[m] - floor4(d[m - 1] + d[m - 1] + 2);
    for (std::size_t i = 0; i + 1 < m; ++i) x[2 * i + 1] = d[i] + floor2(x[2 * i] + x[2 * i + 2]);
    const std::size_t i = m - 1;
    x[2 * i + 1] = d[i] + floor2(x[2 * i] + (2 * i + 2 < n ? x[2 * i + 2] : x[2 * i]));
  }
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

// The inverse integer lifting of many lines at once, stored sample-major: row k of `src`
// (w values, contiguous) holds sample k of every line, rows [0, h) the low half and
// [h, n) the high half. Sample k of the result goes to dst + k * stride. The arithmetic
// is inverse_line's, element by element, so the values are the same; but every step is
// a branch-free loop over contiguous memory, and the boundary cases (the symmetric
// extension) are settled per row, not per sample.
void inverse_rows(const std::int64_t* src, std::size_t w, std::size_t n, Wavelet wav, std::int64_t* dst,
                  std::size_t stride) {
  const std::size_t h = (n + 1) / 2, m = n / 2;
  auto s = [&](std::size_t i) { return src + i * w; };
  auto d = [&](std::size_t i) { return src + (h + i) * w; };
  auto out = [&](std::size_t k) { return dst + k * stride; };
  if (wav == Wavelet::haar) {
    for (std::size_t i = 0; i < m; ++i) lift_haar(s(i), d(i), out(2 * i), out(2 * i + 1), w);
    if (h > m) std::memcpy(out(n - 1), s(h - 1), w * sizeof(std::int64_t));
    return;
  }
  // Even samples (undo the update), then odd samples (undo the prediction) from the
  // even ones just written.
  for (std::size_t i = 0; i < h; ++i) {
    const std::int64_t* si = s(i);
    const std::int64_t* left = d(i > 0 ? i - 1 : 0);
    const std::int64_t* right = d(i < m ? i : m - 1);
    lift_even(si, left, right, out(2 * i), w);
  }
  for (std::size_t i = 0; i < m; ++i) {
    const std::int64_t* di = d(i);
    const std::int64_t* e = out(2 * i);
    const std::int64_t* e2 = out(2 * i + 2 < n ? 2 * i + 2 : 2 * i);
    lift_odd(di, e, e2, out(2 * i + 1), w);
  }
}

// The inverse integer transform of one level along y or z: blocks of up to kRowBlock
// neighbouring x (contiguous) are copied sample-major into a scratch buffer (whole
// cache lines, one memcpy per sample) and transformed from there straight back.
constexpr std::size_t kRowBlock = 256;

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

// The inverse along z (axis 2, one plane of fixed y at a time) or y (axis 1, fixed z)
// of the cube `c`: only planes with a flagged row are transformed, and in them only the
// columns (x, in groups of eight) where a flagged row holds a non-zero. Afterwards the
// flags of each plane say which output rows can be non-zero.
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
  parallel_for(outer, threads, [&](std::size_t o) {
    std::vector<std::uint8_t> in(n), out(n);
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) any |= (in[k] = flags[o * flag_outer + k * flag_stride]) != 0;
    if (!any) return;
    // Left uninitialised (every element is written before it is read): zeroing it cost
    // as much as the transform.
    const std::unique_ptr<std::int64_t[]> rows(new std::int64_t[n * std::min(kRowBlock, c[0])]);
    bool transformed = false;
    for (std::size_t x0 = 0; x0 < c[0]; x0 += kRowBlock) {
      const std::size_t w = std::min(kRowBlock, c[0] - x0);
      std::int64_t* base = &data[o * outer_stride + x0];
      // Every column (one x) is a line of its own: all zero in, all zero out, in
      // place. So only the columns from the first to the last holding a non-zero (in
      // groups of eight) are transformed, and a block without any is skipped. A row
      // is only looked at when flagged, and outside the columns already known to be
      // needed, so dense data stops looking after its first row.
      const std::size_t groups = (w + 7) / 8;
      std::size_t glo = groups, ghi = 0;  // groups [glo, ghi) hold non-zeros
      for (std::size_t k = 0; k < n; ++k) {
        if (!in[k]) continue;
        const std::int64_t* r = base + k * stride;
        auto nonzero = [&](std::size_t g) { return !all_zero(r + 8 * g, std::min<std::size_t>(8, w - 8 * g)); };
        for (std::size_t g = 0; g < glo; ++g)
          if (nonzero(g)) {
            glo = g;
            break;
          }
        for (std::size_t g = groups; g > std::max(ghi, glo); --g)
          if (nonzero(g - 1)) {
            ghi = g;
            break;
          }
      }
      if (glo >= ghi) continue;
      transformed = true;
      const std::size_t x_lo = 8 * glo, x_hi = std::min(w, 8 * ghi), cols = x_hi - x_lo;
      for (std::size_t k = 0; k < n; ++k)
        std::memcpy(&rows[k * cols], base + x_lo + k * stride, cols * sizeof(std::int64_t));
      inverse_rows(rows.get(), cols, n, wav, base + x_lo, stride);
    }
    if (transformed) propagate(n, in.data(), out.data());
    else std::fill(out.begin(), out.end(), 0);  // flagged, but zero after all
    for (std::size_t k = 0; k < n; ++k) flags[o * flag_outer + k * flag_stride] = out[k];
  });
}

// The inverse along x of the flagged rows of the cube `c` (the others are zero).
void inverse_axis_x(std::int64_t* data, const Dims& dims, const Dims& c, Wavelet wav, int threads,
                    const RowFlags& flags) {
  const std::size_t n = c[0];
  if (n < 2) return;
  const std::size_t sy = dims[0], sz = dims[0] * dims[1], ny = dims[1];
  parallel_for(c[2], threads, [&](std::size_t z) {
    std::vector<std::int64_t> scratch(n);
    for (std::size_t y = 0; y < c[1]; ++y) {
      if (!flags[y + ny * z]) continue;
      std::int64_t* line = data + y * sy + z * sz;
      if (!all_zero(line, n)) inverse_line(line, n, wav, scratch.data());
    }
  });
}

void inverse_3d_rows(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads, RowFlags& flags,
                     const std::vector<RowList>* add) {
  if (add)
    for (std::size_t r : (*add)[static_cast<std::size_t>(levels)]) flags[r] = 1;
  for (int l = levels - 1; l >= 0; --l) {
    const Dims c = level_dims(dims, l);
    if (add)
      for (std::size_t r : (*add)[static_cast<std::size_t>(l)]) flags[r] = 1;
    inverse_axis_rows(data, dims, c, 2, w, threads, flags);
    inverse_axis_rows(data, dims, c, 1, w, threads, flags);
    inverse_axis_x(data, dims, c, w, threads, flags);
  }
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
  inverse_3d_rows(data, dims, levels, w, threads, all, nullptr);
}

void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads,
                const std::vector<RowList>& nonzero_rows, std::vector<std::uint8_t>* row_flags) {
  RowFlags flags(dims[1] * dims[2], 0);
  inverse_3d_rows(data, dims, levels, w, threads, flags, &nonzero_rows);
  if (row_flags) *row_flags = std::move(flags);
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
