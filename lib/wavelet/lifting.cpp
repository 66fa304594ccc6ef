#include "wavelet/lifting.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string_view>

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
    for (std::size_t i = 0; i < m; ++i) {
      const std::int64_t* si = s(i);
      const std::int64_t* di = d(i);
      std::int64_t* e = out(2 * i);
      std::int64_t* o = out(2 * i + 1);
      for (std::size_t j = 0; j < w; ++j) {
        const std::int64_t even = si[j] - floor2(di[j]);
        e[j] = even;
        o[j] = di[j] + even;
      }
    }
    if (h > m) std::memcpy(out(n - 1), s(h - 1), w * sizeof(std::int64_t));
    return;
  }
  // Even samples (undo the update), then odd samples (undo the prediction) from the
  // even ones just written.
  for (std::size_t i = 0; i < h; ++i) {
    const std::int64_t* si = s(i);
    const std::int64_t* left = d(i > 0 ? i - 1 : 0);
    const std::int64_t* right = d(i < m ? i : m - 1);
    std::int64_t* e = out(2 * i);
    for (std::size_t j = 0; j < w; ++j) e[j] = si[j] - floor4(left[j] + right[j] + 2);
  }
  for (std::size_t i = 0; i < m; ++i) {
    const std::int64_t* di = d(i);
    const std::int64_t* e = out(2 * i);
    const std::int64_t* e2 = out(2 * i + 2 < n ? 2 * i + 2 : 2 * i);
    std::int64_t* o = out(2 * i + 1);
    for (std::size_t j = 0; j < w; ++j) o[j] = di[j] + floor2(e[j] + e2[j]);
  }
}

// The inverse integer transform of one level along y or z: blocks of up to kRowBlock
// neighbouring x (contiguous) are copied sample-major into a scratch buffer (whole
// cache lines, one memcpy per sample) and transformed from there straight back.
constexpr std::size_t kRowBlock = 256;

// Where the non-zero samples of a line of n can be after its inverse transform, given
// that before it they lie in storage positions [a, b) (low half [0, h), high half
// [h, n)): sample k depends on low samples near k/2 and high samples near k/2 only
// (CDF 5/3: even 2i on s_i, d_(i-1), d_i; odd 2i+1 on d_i and the even 2i, 2i+2; Haar
// less), so [2 i_min - 2, 2 i_max + 4) holds them, with a margin.
void propagate(std::size_t n, std::size_t& a, std::size_t& b) noexcept {
  if (n < 2 || a >= b) return;
  const std::size_t h = (n + 1) / 2;
  std::size_t imin = n, imax = 0;
  if (a < h) imin = a, imax = std::min(b, h) - 1;
  if (b > h) imin = std::min(imin, std::max(a, h) - h), imax = std::max(imax, b - h - 1);
  a = imin >= 1 ? 2 * imin - 2 : 0;
  b = std::min(n, 2 * imax + 4);
}

void inverse_axis_rows(std::int64_t* data, const Dims& dims, const Dims& c, int axis, Wavelet wav,
                       int threads, Box& box) {
  const std::size_t n = c[axis];
  if (n < 2 || box.empty()) return;
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::size_t stride = axis == 1 ? sy : sz;
  const int outer_axis = axis == 1 ? 2 : 1;
  const std::size_t outer0 = box.lo[outer_axis], outer = box.hi[outer_axis] - outer0;
  const std::size_t outer_stride = axis == 1 ? sz : sy;
  const std::size_t xb0 = box.lo[0], xb1 = box.hi[0];
  // Columns outside the box are zero and stay zero; lines run the full length n (the
  // lifting writes every sample in place).
  parallel_for(outer, threads, [&](std::size_t oi) {
    const std::size_t o = outer0 + oi;
    // Left uninitialised (every element is written before it is read): zeroing it cost
    // as much as the transform.
    const std::unique_ptr<std::int64_t[]> rows(new std::int64_t[n * std::min(kRowBlock, xb1 - xb0)]);
    for (std::size_t x0 = xb0; x0 < xb1; x0 += kRowBlock) {
      const std::size_t w = std::min(kRowBlock, xb1 - x0);
      std::int64_t* base = &data[o * outer_stride + x0];
      // Every column (one x) is a line of its own: all zero in, all zero out, in
      // place. So only the columns from the first to the last holding a non-zero (in
      // groups of eight) are transformed, and a block without any is skipped: sparse
      // volumes (a plume in empty space, air around a head) skip most of their work.
      // A row is only looked at outside the columns already known to be needed, so
      // dense data stops looking after its first row.
      const std::size_t groups = (w + 7) / 8;
      std::size_t glo = groups, ghi = 0;  // groups [glo, ghi) hold non-zeros
      for (std::size_t k = 0; k < n; ++k) {
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
      // Narrowed only when that saves a quarter of the block: the copies of pieces
      // cost more than they save on dense data (CT head: +14 M instructions in memcpy).
      std::size_t x_lo = 8 * glo, x_hi = std::min(w, 8 * ghi);
      if (4 * (x_hi - x_lo) > 3 * w) x_lo = 0, x_hi = w;
      const std::size_t cols = x_hi - x_lo;
      for (std::size_t k = 0; k < n; ++k)
        std::memcpy(&rows[k * cols], base + x_lo + k * stride, cols * sizeof(std::int64_t));
      inverse_rows(rows.get(), cols, n, wav, base + x_lo, stride);
    }
  });
  propagate(n, box.lo[axis], box.hi[axis]);
}

// The inverse along x of the lines of the cube `c` inside the box (the others are zero).
void inverse_axis_x(std::int64_t* data, const Dims& dims, const Dims& c, Wavelet wav, int threads, Box& box) {
  const std::size_t n = c[0];
  if (n < 2 || box.empty()) return;
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  parallel_for(box.hi[2] - box.lo[2], threads, [&](std::size_t zi) {
    const std::size_t z = box.lo[2] + zi;
    std::vector<std::int64_t> scratch(n);
    for (std::size_t y = box.lo[1]; y < box.hi[1]; ++y) {
      std::int64_t* line = data + y * sy + z * sz;
      if (!all_zero(line + box.lo[0], box.hi[0] - box.lo[0])) inverse_line(line, n, wav, scratch.data());
    }
  });
  propagate(n, box.lo[0], box.hi[0]);
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

void Box::add(const Box& b) noexcept {
  if (b.empty()) return;
  if (empty()) {
    *this = b;
    return;
  }
  for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
}

void Box::add(std::size_t x0, std::size_t x1, std::size_t y, std::size_t z) noexcept {
  add(Box{{x0, y, z}, {x1, y + 1, z + 1}});
}

void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads) {
  std::vector<Box> all(static_cast<std::size_t>(levels) + 1);
  for (int l = 0; l <= levels; ++l) all[static_cast<std::size_t>(l)].hi = level_dims(dims, l);
  inverse_3d(data, dims, levels, w, threads, all);
}

void inverse_3d(std::int64_t* data, const Dims& dims, int levels, Wavelet w, int threads,
                const std::vector<Box>& nonzero) {
  Box box = nonzero[static_cast<std::size_t>(levels)];
  for (int l = levels - 1; l >= 0; --l) {
    const Dims c = level_dims(dims, l);
    box.add(nonzero[static_cast<std::size_t>(l)]);
    for (int a = 0; a < 3; ++a) box.hi[a] = std::min(box.hi[a], c[a]);
    inverse_axis_rows(data, dims, c, 2, w, threads, box);
    inverse_axis_rows(data, dims, c, 1, w, threads, box);
    inverse_axis_x(data, dims, c, w, threads, box);
  }
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
