// Exact Euclidean distance transform and the ball morphology built on it (docs/segbrain.md §3,
// O(N) for any radius).
//
// Separable: the first pass (along x, contiguous) needs only the nearest target of the
// row, found by a forward and a backward scan; the passes along y and z take the lower
// envelope of parabolas (Felzenszwalb & Huttenlocher 2012), on lines gathered kBlock at a
// time from consecutive x so every strided cache line is used whole.
//
// Two savings keep the result exact:
// * Cropping. Erosion and depth need distances only inside the mask's bounding box; one
//   voxel of complement around the box stands in for all the complement beyond it (the
//   nearest complement voxel, clamped onto that layer, is no farther in any coordinate).
//   Dilation by r needs only the box grown by r, which holds every target.
// * A cap. Morphology compares distances with r² only, so partial distances above r²
//   become +inf: a parabola that starts above r² can never bring a voxel within r, and
//   lines with no finite value left cost one pass.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "segbrain/morphology.hpp"
#include "segbrain/parallel.hpp"

namespace fest::segbrain {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kBlock = 16;

// A box of the grid: origin lo and size n, in voxels.
struct Box {
  std::array<std::size_t, 3> lo{0, 0, 0}, n{0, 0, 0};
  std::size_t size() const { return n[0] * n[1] * n[2]; }
};

// Bounding box of the nonzero voxels; false when there are none.
bool bounding_box(const Grid& g, const Mask& m, Box& box) {
  std::array<std::size_t, 3> lo = g.n, hi{0, 0, 0};
  bool any = false;
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y) {
      const std::uint8_t* row = m.data() + g.index(0, y, z);
      const std::uint8_t* end = row + g.n[0];
      const std::uint8_t* first = std::find_if(row, end, [](std::uint8_t v) { return v != 0; });
      if (first == end) continue;
      std::size_t last = g.n[0] - 1;
      while (!row[last]) --last;
      any = true;
      lo[0] = std::min(lo[0], static_cast<std::size_t>(first - row));
      hi[0] = std::max(hi[0], last);
      lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
      lo[2] = std::min(lo[2], z), hi[2] = std::max(hi[2], z);
    }
  if (!any) return false;
  for (int a = 0; a < 3; ++a) box.lo[a] = lo[a], box.n[a] = hi[a] - lo[a] + 1;
  return true;
}

// The box grown by margin[a] voxels per side, clipped to the grid.
Box grown(const Grid& g, const Box& b, const std::array<double, 3>& margin) {
  Box out;
  for (int a = 0; a < 3; ++a) {
    const std::size_t m = static_cast<std::size_t>(std::min(margin[a], double(g.n[a])));
    const std::size_t lo = b.lo[a] > m ? b.lo[a] - m : 0;
    const std::size_t hi = std::min(g.n[a], b.lo[a] + b.n[a] + m);
    out.lo[a] = lo, out.n[a] = hi - lo;
  }
  return out;
}

// Scratch of one worker for lines up to n long.
struct LineScratch {
  std::vector<int> v;
  std::vector<double> zn, zd, gv, hv, fv;
  std::array<std::vector<double>, kBlock> lines;
  explicit LineScratch(std::size_t n) : v(n), zn(n + 1), zd(n + 1), gv(n), hv(n), fv(n) {
    for (auto& l : lines) l.resize(n);
  }
};

// In place: f[q] <- min_p (h (q - p))² + f[p] over the n samples (spacing h), the lower
// envelope of parabolas; results above cap become +inf. The envelope's breakpoints are
// kept as fractions zn/zd (zd > 0) and compared by cross-multiplication: no division on
// the loop's critical path, and on integer data (unit spacing) the comparisons are exact.
void envelope_line(double* f, int n, double h, double cap, LineScratch& s) {
  int k = -1, zeros = 0;
  for (int q = 0; q < n; ++q) {
    const double fq = f[q];
    if (fq == kInf) continue;
    zeros += fq == 0;
    const double qh = q * h, gq = fq + qh * qh;
    double num = 0, den = 0;
    while (k >= 0) {
      // Breakpoint of parabolas v[k] and q: num / den.
      num = gq - s.gv[k], den = 2 * (qh - s.hv[k]);
      if (k > 0 && num * s.zd[k] <= s.zn[k] * den) --k;
      else break;
    }
    ++k;
    s.v[k] = q, s.gv[k] = gq, s.hv[k] = qh, s.fv[k] = fq;
    s.zn[k] = num, s.zd[k] = den;  // k == 0: -inf, never read
  }
  if (k < 0 || zeros == n) return;  // all +inf, or all targets: nothing changes
  s.zn[k + 1] = 1, s.zd[k + 1] = 0;  // +inf: 1 < qh * 0 never holds
  int j = 0;
  for (int q = 0; q < n; ++q) {
    const double qh = q * h;
    while (s.zn[j + 1] < qh * s.zd[j + 1]) ++j;
    const double dq = (q - s.v[j]) * h;
    const double d = dq * dq + s.fv[j];
    f[q] = d <= cap ? d : kInf;
  }
}

// Envelope pass along axis 1 or 2 of the box-shaped array d: lines gathered kBlock at a
// time from consecutive x. Parallel over the other outer axis (z for y lines, y for z).
void envelope_pass(std::vector<double>& d, const Box& b, int axis, double h, double cap) {
  const std::size_t n = b.n[axis];
  const std::size_t stride = axis == 1 ? b.n[0] : b.n[0] * b.n[1];
  const std::size_t outer = axis == 1 ? b.n[2] : b.n[1];
  const std::size_t outer_step = axis == 1 ? b.n[0] * b.n[1] : b.n[0];
  parallel_bands(outer, 4, [&](std::size_t, std::size_t o0, std::size_t o1) {
    LineScratch s(n);
    for (std::size_t o = o0; o < o1; ++o)
      for (std::size_t x0 = 0; x0 < b.n[0]; x0 += kBlock) {
        const std::size_t nb = std::min(kBlock, b.n[0] - x0);
        double* base = d.data() + o * outer_step + x0;
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t k = 0; k < nb; ++k) s.lines[k][i] = base[k + i * stride];
        for (std::size_t k = 0; k < nb; ++k) envelope_line(s.lines[k].data(), static_cast<int>(n), h, cap, s);
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t k = 0; k < nb; ++k) base[k + i * stride] = s.lines[k][i];
      }
  });
}

// Largest R with (R h)² <= cap: a capped pass looks no farther than R samples.
long window_radius(double h, double cap) {
  const double samples = std::floor(std::sqrt(cap) / h);
  if (!(samples < 1e6)) return 1000000;  // far beyond any direct window
  long r = static_cast<long>(samples);
  while (double(r + 1) * h * (double(r + 1) * h) <= cap) ++r;
  while (r > 0 && double(r) * h * (double(r) * h) > cap) --r;
  return r;
}

// out[j] = min over k of in[j + k L] + c[k] (k = 0..2R), +inf above cap. R is a
// template argument so the taps unroll and the loop over j vectorises with the running
// minimum in registers.
template <int R>
void window_min(const double* in, std::size_t m, std::size_t L, const double* c, double cap, double* out) {
  for (std::size_t j = 0; j < m; ++j) {
    double v = in[j] + c[0];
    for (int k = 1; k <= 2 * R; ++k) {
      const double w = in[j + static_cast<std::size_t>(k) * L] + c[k];
      v = w < v ? w : v;
    }
    out[j] = v <= cap ? v : kInf;
  }
}

inline void copy_block(const double* from, double* to) {
  double t[kBlock];
  for (std::size_t k = 0; k < kBlock; ++k) t[k] = from[k];
  for (std::size_t k = 0; k < kBlock; ++k) to[k] = t[k];
}

constexpr long kMaxWindow = 6;  // 13 taps: about the cost of the envelope

// The same pass for a finite cap whose window of R samples is short: every voxel takes
// the minimum of f[p] + (h (q - p))² over |q - p| <= R directly. Candidates farther
// away would exceed the cap, so this is the envelope's exact result; with the lanes
// interleaved the minimum runs branch-free over contiguous memory.
void window_pass(std::vector<double>& d, const Box& b, int axis, double h, double cap, long radius) {
  const std::size_t n = b.n[axis], R = static_cast<std::size_t>(radius);
  const std::size_t stride = axis == 1 ? b.n[0] : b.n[0] * b.n[1];
  const std::size_t outer = axis == 1 ? b.n[2] : b.n[1];
  const std::size_t outer_step = axis == 1 ? b.n[0] * b.n[1] : b.n[0];
  std::vector<double> c(2 * R + 1);
  for (std::size_t k = 0; k <= 2 * R; ++k) {
    const double dq = double(static_cast<long>(k) - radius) * h;
    c[k] = dq * dq;
  }
  using Kernel = void (*)(const double*, std::size_t, std::size_t, const double*, double, double*);
  static constexpr Kernel kernels[kMaxWindow + 1] = {window_min<0>, window_min<1>, window_min<2>, window_min<3>,
                                                     window_min<4>, window_min<5>, window_min<6>};
  const Kernel kernel = kernels[R];
  parallel_bands(outer, 4, [&](std::size_t, std::size_t o0, std::size_t o1) {
    std::vector<double> in((n + 2 * R) * kBlock), out(n * kBlock);
    for (std::size_t o = o0; o < o1; ++o)
      for (std::size_t x0 = 0; x0 < b.n[0]; x0 += kBlock) {
        const std::size_t L = std::min(kBlock, b.n[0] - x0);
        double* base = d.data() + o * outer_step + x0;
        // Beyond the box's ends nothing is known: +inf contributes nothing.
        std::fill(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(R * L), kInf);
        std::fill(in.begin() + static_cast<std::ptrdiff_t>((n + R) * L), in.begin() + static_cast<std::ptrdiff_t>((n + 2 * R) * L), kInf);
        if (L == kBlock) {  // fixed-size copies inline (no memmove call per row)
          for (std::size_t i = 0; i < n; ++i) copy_block(base + i * stride, in.data() + (i + R) * kBlock);
        } else {
          for (std::size_t i = 0; i < n; ++i) std::copy(base + i * stride, base + i * stride + L, in.data() + (i + R) * L);
        }
        kernel(in.data(), n * L, L, c.data(), cap, out.data());
        if (L == kBlock) {
          for (std::size_t i = 0; i < n; ++i) copy_block(out.data() + i * kBlock, base + i * stride);
        } else {
          for (std::size_t i = 0; i < n; ++i) std::copy(out.data() + i * L, out.data() + (i + 1) * L, base + i * stride);
        }
      }
  });
}

// Pass along axis 1 or 2: the direct window when the cap makes it short, else the
// lower envelope.
void line_pass(std::vector<double>& d, const Box& b, int axis, double h, double cap) {
  const long r = cap < kInf ? window_radius(h, cap) : kMaxWindow + 1;
  if (r <= kMaxWindow) window_pass(d, b, axis, h, cap, r);
  else envelope_pass(d, b, axis, h, cap);
}

// Squared distances (mm²) inside box b to the nearest voxel of b with is_target(grid
// index); values above cap are +inf. Returned in box order (x fastest).
template <typename IsTarget>
std::vector<double> box_squared_distance(const Grid& g, const Box& b, IsTarget&& is_target, double cap) {
  std::vector<double> d(b.size());
  const double hx = g.spacing[0];
  // Pass 1, along x: index distance to the nearest target of the row.
  parallel_bands(b.n[2], 4, [&](std::size_t, std::size_t z0, std::size_t z1) {
    std::vector<long> fwd(b.n[0]);
    const long nx = static_cast<long>(b.n[0]), none = std::numeric_limits<long>::max() / 4;
    for (std::size_t z = z0; z < z1; ++z)
      for (std::size_t y = 0; y < b.n[1]; ++y) {
        const std::size_t src = g.index(b.lo[0], b.lo[1] + y, b.lo[2] + z);
        double* row = d.data() + b.n[0] * (y + b.n[1] * z);
        long last = -none;
        for (long x = 0; x < nx; ++x) {
          if (is_target(src + static_cast<std::size_t>(x))) last = x;
          fwd[static_cast<std::size_t>(x)] = x - last;
        }
        long next = none;
        for (long x = nx - 1; x >= 0; --x) {
          if (fwd[static_cast<std::size_t>(x)] == 0) next = x;
          const long k = std::min(fwd[static_cast<std::size_t>(x)], next - x);
          const double dx = double(k) * hx, v = dx * dx;
          row[x] = k < none / 2 && v <= cap ? v : kInf;
        }
      }
  });
  if (b.n[1] > 1) line_pass(d, b, 1, g.spacing[1], cap);
  if (b.n[2] > 1) line_pass(d, b, 2, g.spacing[2], cap);
  return d;
}

// Calls f(grid index, box index, length) for every row of the box, parallel over z.
template <typename F>
void for_box_rows(const Grid& g, const Box& b, F&& f) {
  parallel_bands(b.n[2], 4, [&](std::size_t, std::size_t z0, std::size_t z1) {
    for (std::size_t z = z0; z < z1; ++z)
      for (std::size_t y = 0; y < b.n[1]; ++y)
        f(g.index(b.lo[0], b.lo[1] + y, b.lo[2] + z), b.n[0] * (y + b.n[1] * z), b.n[0]);
  });
}

}  // namespace

std::vector<double> squared_distance(const Grid& g, const Mask& target) {
  Box all;
  all.n = g.n;
  return box_squared_distance(g, all, [&](std::size_t i) { return target[i] != 0; }, kInf);
}

std::vector<double> depth(const Grid& g, const Mask& m) {
  std::vector<double> out(g.size(), 0.0);
  Box b;
  if (!bounding_box(g, m, b)) return out;
  b = grown(g, b, {1, 1, 1});
  std::vector<double> d = box_squared_distance(g, b, [&](std::size_t i) { return m[i] == 0; }, kInf);
  for_box_rows(g, b, [&](std::size_t gi, std::size_t bi, std::size_t n) {
    double* o = out.data() + gi;
    const double* s = d.data() + bi;
    for (std::size_t x = 0; x < n; ++x) o[x] = std::sqrt(s[x]);
  });
  return out;
}

Mask erode(const Grid& g, const Mask& m, double r) {
  Mask out(g.size(), 0);
  Box b;
  if (std::isnan(r) || !bounding_box(g, m, b)) return out;  // d > NaN never holds
  b = grown(g, b, {1, 1, 1});
  const double r2 = r * r;
  std::vector<double> d = box_squared_distance(g, b, [&](std::size_t i) { return m[i] == 0; }, r2);
  for_box_rows(g, b, [&](std::size_t gi, std::size_t bi, std::size_t n) {
    std::uint8_t* o = out.data() + gi;  // raw pointers: the loop vectorises
    const std::uint8_t* in = m.data() + gi;
    const double* s = d.data() + bi;
    for (std::size_t x = 0; x < n; ++x) o[x] = static_cast<std::uint8_t>((in[x] != 0) & (s[x] > r2));
  });
  return out;
}

Mask dilate(const Grid& g, const Mask& m, double r) {
  Mask out(g.size(), 0);
  Box b;
  if (std::isnan(r) || !bounding_box(g, m, b)) return out;  // d <= NaN never holds
  const double r2 = r * r;
  b = grown(g, b, {std::floor(std::abs(r) / g.spacing[0]) + 1, std::floor(std::abs(r) / g.spacing[1]) + 1,
                   std::floor(std::abs(r) / g.spacing[2]) + 1});
  std::vector<double> d = box_squared_distance(g, b, [&](std::size_t i) { return m[i] != 0; }, r2);
  for_box_rows(g, b, [&](std::size_t gi, std::size_t bi, std::size_t n) {
    std::uint8_t* o = out.data() + gi;
    const double* s = d.data() + bi;
    for (std::size_t x = 0; x < n; ++x) o[x] = static_cast<std::uint8_t>(s[x] <= r2);
  });
  return out;
}

Mask open(const Grid& g, const Mask& m, double r) { return dilate(g, erode(g, m, r), r); }
Mask close(const Grid& g, const Mask& m, double r) { return erode(g, dilate(g, m, r), r); }

}  // namespace fest::segbrain
