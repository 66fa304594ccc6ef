#include "raycast/render.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "core/parallel_for.hpp"
#include "raycast/exp_neg.hpp"

namespace fest::raycast {
namespace {

using volume_pyramid::MinMaxPyramid;
using volume_pyramid::ScalarGrid;

constexpr int kTile = 16;
constexpr int kBatch = 8;  // samples scheduled, then computed together (dvr_batched)
constexpr int kSkipLevels = 6;  // skipping tables: the pyramid's finest level and up to 5 coarser

struct Mat3 {
  double m[9];
  Vec3 operator*(const Vec3& v) const {
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2], m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
  }
  Mat3 transposed() const { return {{m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]}}; }
};

Mat3 inverse(const std::array<double, 9>& a) {
  const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
  if (std::abs(det) < 1e-300) throw std::invalid_argument("volume axes are singular");
  const double s = 1.0 / det;
  return {{(a[4] * a[8] - a[5] * a[7]) * s, (a[2] * a[7] - a[1] * a[8]) * s, (a[1] * a[5] - a[2] * a[4]) * s,
           (a[5] * a[6] - a[3] * a[8]) * s, (a[0] * a[8] - a[2] * a[6]) * s, (a[2] * a[3] - a[0] * a[5]) * s,
           (a[3] * a[7] - a[4] * a[6]) * s, (a[1] * a[6] - a[0] * a[7]) * s, (a[0] * a[4] - a[1] * a[3]) * s}};
}

// Slab-method clipping of the index-space ray o + t d to the sample box [0, dims - 1].
bool clip_index(const ScalarGrid& g, const Vec3& o, const Vec3& d, double& t0, double& t1);

// std::floor without a library call where SSE4.1's rounding is not available (exact: a
// truncation corrected by one below zero, |x| < 2^52).
inline double floor_of(double x) {
  if (!(std::abs(x) < 4503599627370496.0)) return std::floor(x);
  const double t = static_cast<double>(static_cast<std::int64_t>(x));
  return t > x ? t - 1 : t;
}

// Fixed integer hash of a pixel -> [0, 1) (deterministic jitter).
double pixel_hash(int i, int j, int s) {
  std::uint32_t h = static_cast<std::uint32_t>(i) * 73856093u ^ static_cast<std::uint32_t>(j) * 19349663u ^
                    static_cast<std::uint32_t>(s) * 83492791u;
  h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
  return (h >> 8) * (1.0 / 16777216.0);
}

class Caster {
 public:
  Caster(const ScalarGrid& g, const MinMaxPyramid* p, const TransferFunction& tf, const RenderOptions& o,
         SurfaceTracer surf, const void* ctx, const ShadingVolume* sv)
      : g_(g), pyr_(p), tf_(tf), o_(o), surf_(surf), ctx_(ctx), inv_(inverse(g.axes)), inv_t_(inv_.transposed()) {
    double hmin = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 3; ++c) hmin = std::min(hmin, std::sqrt(g.axes[c] * g.axes[c] + g.axes[3 + c] * g.axes[3 + c] + g.axes[6 + c] * g.axes[6 + c]));
    hmin_ = hmin;
    const double* m = inv_t_.m;
    diagonal_ = m[1] == 0 && m[2] == 0 && m[3] == 0 && m[5] == 0 && m[6] == 0 && m[7] == 0;
    if (o.phong[3] >= 0 && o.phong[3] <= 1024 && o.phong[3] == std::floor(o.phong[3])) spec_int_ = static_cast<int>(o.phong[3]);
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    if (p && p->root_level() >= p->finest_level()) {  // the root node holds every sample
      const int r = p->root_level();
      for (std::size_t k = 0; k < p->nodes(r)[2]; ++k)
        for (std::size_t j = 0; j < p->nodes(r)[1]; ++j)
          for (std::size_t i = 0; i < p->nodes(r)[0]; ++i) lo = std::min(lo, p->min(r, i, j, k)), hi = std::max(hi, p->max(r, i, j, k));
    } else {
      for (float v : g.values) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    range_ = hi > lo ? double(hi) - lo : 1.0;
    gmin_ = 1e-6 * range_;
    ka_ = o.phong[0], kd_ = o.phong[1], ks_ = o.phong[2];
    if (pyr_) lf_ = pyr_->finest_level();
    for (int a = 0; a < 3; ++a) hi_[a] = static_cast<double>(g.dims[a] - 1), cmax_[a] = g.dims[a] - 2;
    // Skipping tables, finest level first: a node is skippable when no sample in it can
    // contribute (DVR: tau = 0 over [min, max]; iso: no iso-value in [min, max]). A node
    // skippable at one level is skippable at every finer level inside it (its range shrinks).
    const bool skip_dvr = pyr_ && o.skip_empty && o.mode == Mode::dvr && !o.preint;
    const bool skip_iso = pyr_ && o.skip_empty && o.mode == Mode::iso;
    if (skip_dvr || skip_iso) {
      for (int L = lf_; L <= pyr_->root_level() && L < lf_ + kSkipLevels; ++L) {
        const auto n = pyr_->nodes(L);
        std::vector<char> t(n[0] * n[1] * n[2]);
        for (std::size_t k = 0; k < n[2]; ++k)
          for (std::size_t j = 0; j < n[1]; ++j)
            for (std::size_t i = 0; i < n[0]; ++i) {
              const float mn = pyr_->min(L, i, j, k), mx = pyr_->max(L, i, j, k);
              bool none = true;
              if (skip_dvr) none = tf.transparent(mn, mx);
              else
                for (const auto& I : o.isos) none = none && !(mn <= I.value && I.value <= mx);
              t[i + n[0] * (j + n[1] * k)] = none;
            }
        transparent_.push_back(std::move(t));
        bn_.push_back(n);
      }
      skip_levels_ = static_cast<int>(transparent_.size());
      // Dense nodes: every finest node inside is not skippable, so the march may compute
      // every sample inside without looking again (dvr_batched: one node exit per dense
      // region instead of one per finest node; the same samples are computed).
      for (int L = 0; L < skip_levels_; ++L) {
        const auto& n = bn_[L];
        std::vector<char> t(n[0] * n[1] * n[2]);
        if (L == 0) {
          for (std::size_t q = 0; q < t.size(); ++q) t[q] = !transparent_[0][q];
        } else {
          const auto& c = bn_[L - 1];
          const auto& child = dense_[L - 1];
          for (std::size_t k = 0; k < n[2]; ++k)
            for (std::size_t j = 0; j < n[1]; ++j)
              for (std::size_t i = 0; i < n[0]; ++i) {
                bool all = true;
                for (std::size_t dk = 0; dk < 2; ++dk)
                  for (std::size_t dj = 0; dj < 2; ++dj)
                    for (std::size_t di = 0; di < 2; ++di) {
                      const std::size_t ci = 2 * i + di, cj = 2 * j + dj, ck = 2 * k + dk;
                      if (ci < c[0] && cj < c[1] && ck < c[2]) all = all && child[ci + c[0] * (cj + c[1] * ck)];
                    }
                t[i + n[0] * (j + n[1] * k)] = all;
              }
        }
        dense_.push_back(std::move(t));
      }
      for (int L = 0; L < skip_levels_; ++L)
        skip_[L] = {transparent_[L].data(), dense_[L].data(), bn_[L][0], bn_[L][1], {bn_[L][0] - 1, bn_[L][1] - 1, bn_[L][2] - 1}, lf_ + L};
    }
    if (o.shade && o.gradient_cache) {
      if (!sv) own_ = shading_volume(g, o.threads), sv = &own_;
      f4_ = sv->data.get();
      i16_ = sv->data16.get();
      sy4_ = 4 * g.dims[0], sz4_ = sy4_ * g.dims[1];
    }
  }

  // One ray: premultiplied colour, alpha, depth.
  void cast(const Ray& wr, double jit, std::array<double, 4>& out, double& depth, RenderStats& st) const {
    out = {0, 0, 0, 0};
    depth = std::numeric_limits<double>::infinity();
    ++st.rays;
    if (!wr.valid) return;
    SurfaceHit hit;
    if (surf_) hit = surf_(ctx_, wr);
    double t0, t1;
    const Vec3 o = inv_ * (wr.origin - g_.origin), d = inv_ * wr.dir;
    const bool in_box = clip_index(g_, o, d, t0, t1);  // = clip_to_grid, the inverse computed once
    t0 = std::max(t0, wr.t_min);
    if (in_box) t1 = std::min(t1, hit.t);
    const double dlen = norm(wr.dir);  // world length per unit t
    if (in_box && t1 > t0) {
      const double vox_per_t = dlen / hmin_;
      const double dt = o_.step / vox_per_t;
      switch (o_.mode) {
        case Mode::dvr:
          if (!o_.preint && !o_.nearest && (f4_ || i16_ || !o_.shade)) dvr_batched(o, d, wr.dir, t0, t1, dt, vox_per_t, dlen, jit, out, depth, st);
          else dvr(o, d, wr.dir, t0, t1, dt, vox_per_t, dlen, jit, out, depth, st);
          break;
        case Mode::iso: iso(o, d, wr.dir, t0, t1, dt, dlen, out, depth, st); break;
        case Mode::slices: slices(wr, o, d, t0, t1, dlen, out, depth, st); break;
        default: projection(o, d, t0, t1, dt, dlen, out, depth, st); break;
      }
    }
    if (hit.t < std::numeric_limits<double>::infinity() && out[3] < 1) {
      const double w = 1 - out[3];
      for (int c = 0; c < 3; ++c) out[c] += w * hit.rgb[c];
      out[3] = 1;
      if (!(depth < std::numeric_limits<double>::infinity())) depth = hit.t * dlen;
    }
  }

 private:
  // Where a point falls: its cell's lower corner (clamped into the box) and the trilinear
  // weights; shared by the value and the gradient of one sample.
  // floor of a coordinate already clamped to [0, n - 1] (a signed conversion: one instruction)
  static std::size_t index_of(double x) { return static_cast<std::size_t>(static_cast<std::int64_t>(x)); }
  struct Cell {
    std::size_t c[3];
    std::size_t base;
    double w[3];
  };
  Cell locate(const Vec3& p) const {
    Cell e;
    for (int a = 0; a < 3; ++a) {
      const double x = std::clamp(p[a], 0.0, hi_[a]);
      e.c[a] = std::min(index_of(x), cmax_[a]);
      e.w[a] = x - e.c[a];
    }
    e.base = g_.index(e.c[0], e.c[1], e.c[2]);
    return e;
  }
  // Trilinear value (the same arithmetic as sample_trilinear).
  double trilinear(const Cell& e) const {
    const float* b;
    std::size_t sx, sy, sz;
    if (f4_) b = f4_ + 4 * e.base, sx = 4, sy = sy4_, sz = sz4_;
    else b = &g_.values[e.base], sx = 1, sy = g_.dims[0], sz = sy * g_.dims[1];
    const double c00 = b[0] + e.w[0] * (double(b[sx]) - b[0]);
    const double c10 = b[sy] + e.w[0] * (double(b[sy + sx]) - b[sy]);
    const double c01 = b[sz] + e.w[0] * (double(b[sz + sx]) - b[sz]);
    const double c11 = b[sz + sy] + e.w[0] * (double(b[sz + sy + sx]) - b[sz + sy]);
    const double c0 = c00 + e.w[1] * (c10 - c00), c1 = c01 + e.w[1] * (c11 - c01);
    return c0 + e.w[2] * (c1 - c0);
  }
  // Value and index-space gradient of a sample from the shading volume in one pass: the 8
  // corners {f, fi, fj, fk} are each read once and the four channels interpolated together
  // by the lerps of trilinear() (two channels per SSE2 register, double precision), so the
  // value is bit-identical to trilinear()'s and the gradient equal to the corner-weight sum
  // of gradient() up to rounding (docs/volrender.md "Acceleration").
  struct Fetched {
    double f;
    Vec3 gi;
  };
  Fetched fetch(const Cell& e) const {
    return i16_ ? fetch_from(i16_ + 4 * e.base, e) : fetch_from(f4_ + 4 * e.base, e);
  }
  // T = float: {f, fi, fj, fk}; T = int16: {f, 2 fi, 2 fj, 2 fk}, halved at the end (exact:
  // the lerps commute with a factor 2).
  template <typename T>
  Fetched fetch_from(const T* q, const Cell& e) const {
    const std::size_t sy = sy4_, sz = sz4_;
#if defined(__SSE2__)
    const __m128d wx = _mm_set1_pd(e.w[0]), wy = _mm_set1_pd(e.w[1]), wz = _mm_set1_pd(e.w[2]);
    const auto lerp = [](__m128d a, __m128d b, __m128d w) { return _mm_add_pd(a, _mm_mul_pd(w, _mm_sub_pd(b, a))); };
    // one x-edge of the cell: lo = {f, fi}, hi = {fj, fk}, interpolated along x
    const auto edge = [&](const T* c, __m128d& lo, __m128d& hi) {
      __m128d alo, ahi, blo, bhi;
      if constexpr (std::is_same_v<T, float>) {
        const __m128 a = _mm_loadu_ps(c), b = _mm_loadu_ps(c + 4);
        alo = _mm_cvtps_pd(a), blo = _mm_cvtps_pd(b);
        ahi = _mm_cvtps_pd(_mm_movehl_ps(a, a)), bhi = _mm_cvtps_pd(_mm_movehl_ps(b, b));
      } else {
        const __m128i ab = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c));  // both corners
        const __m128i a = _mm_srai_epi32(_mm_unpacklo_epi16(ab, ab), 16), b = _mm_srai_epi32(_mm_unpackhi_epi16(ab, ab), 16);
        alo = _mm_cvtepi32_pd(a), blo = _mm_cvtepi32_pd(b);
        ahi = _mm_cvtepi32_pd(_mm_shuffle_epi32(a, _MM_SHUFFLE(1, 0, 3, 2)));
        bhi = _mm_cvtepi32_pd(_mm_shuffle_epi32(b, _MM_SHUFFLE(1, 0, 3, 2)));
      }
      lo = lerp(alo, blo, wx), hi = lerp(ahi, bhi, wx);
    };
    __m128d l00, h00, l10, h10, l01, h01, l11, h11;
    edge(q, l00, h00);
    edge(q + sy, l10, h10);
    edge(q + sz, l01, h01);
    edge(q + sz + sy, l11, h11);
    const __m128d l0 = lerp(l00, l10, wy), h0 = lerp(h00, h10, wy), l1 = lerp(l01, l11, wy), h1 = lerp(h01, h11, wy);
    const __m128d lo = lerp(l0, l1, wz), hi = lerp(h0, h1, wz);
    double v[4];
    _mm_storeu_pd(v, lo);
    _mm_storeu_pd(v + 2, hi);
#else
    double v[4];
    for (int ch = 0; ch < 4; ++ch) {
      const T* b = q + ch;
      const double c00 = b[0] + e.w[0] * (double(b[4]) - b[0]);
      const double c10 = b[sy] + e.w[0] * (double(b[sy + 4]) - b[sy]);
      const double c01 = b[sz] + e.w[0] * (double(b[sz + 4]) - b[sz]);
      const double c11 = b[sz + sy] + e.w[0] * (double(b[sz + sy + 4]) - b[sz + sy]);
      const double c0 = c00 + e.w[1] * (c10 - c00), c1 = c01 + e.w[1] * (c11 - c01);
      v[ch] = c0 + e.w[2] * (c1 - c0);
    }
#endif
    if constexpr (std::is_same_v<T, float>) return {v[0], {v[1], v[2], v[3]}};
    else return {v[0], {0.5 * v[1], 0.5 * v[2], 0.5 * v[3]}};
  }
  double value(const Vec3& p) const {
    if (o_.nearest) {
      auto idx = [&](double x, int a) {
        return static_cast<std::size_t>(std::clamp(std::floor(x + 0.5), 0.0, static_cast<double>(g_.dims[a] - 1)));
      };
      return g_.at(idx(p[0], 0), idx(p[1], 1), idx(p[2], 2));
    }
    return trilinear(locate(p));
  }

  // Central-difference gradient at the 8 surrounding samples, trilinearly interpolated
  // (index space), then mapped to world space.
  Vec3 gradient(const Cell& e) const {
    const double* w = e.w;
    Vec3 gi{0, 0, 0};
    if (i16_) {  // the corner-weight sum below, of the doubled differences, halved (exact)
      const std::size_t sy = sy4_, sz = sz4_;
      const std::size_t offset[8] = {0, 4, sy, sy + 4, sz, sz + 4, sz + sy, sz + sy + 4};
      const double x0 = 1 - w[0], y0 = 1 - w[1], z0 = 1 - w[2];
      const double xy[4] = {x0 * y0, w[0] * y0, x0 * w[1], w[0] * w[1]};
      const std::int16_t* q = i16_ + 4 * e.base;
      for (int corner = 0; corner < 8; ++corner) {
        const double wt = xy[corner & 3] * (corner & 4 ? w[2] : z0);
        for (int a = 0; a < 3; ++a) gi[a] += wt * q[offset[corner] + 1 + a];
      }
      return inv_t_ * (0.5 * gi);
    }
    if (f4_) {
      const std::size_t sy = sy4_, sz = sz4_;
      const std::size_t offset[8] = {0, 4, sy, sy + 4, sz, sz + 4, sz + sy, sz + sy + 4};
      // corner weights ((x-weight * y-weight) * z-weight), the same products as the scalar
      // loop below
      const double x0 = 1 - w[0], y0 = 1 - w[1], z0 = 1 - w[2];
      const double xy[4] = {x0 * y0, w[0] * y0, x0 * w[1], w[0] * w[1]};
      const float* q = f4_ + 4 * e.base;
#if defined(__SSE2__)
      // the x and y components in the two lanes of one register, z alone: per component the
      // same double products and sums in the same order as the scalar loop
      __m128d gxy = _mm_setzero_pd();
      double gz = 0;
      for (int corner = 0; corner < 8; ++corner) {
        const double wt = xy[corner & 3] * (corner & 4 ? w[2] : z0);
        const __m128 v = _mm_loadu_ps(q + offset[corner]);  // f, fx, fy, fz
        gxy = _mm_add_pd(gxy, _mm_mul_pd(_mm_set1_pd(wt), _mm_cvtps_pd(_mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 3, 2, 1)))));
        gz += wt * double(_mm_cvtss_f32(_mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 3, 3, 3))));
      }
      _mm_storeu_pd(&gi[0], gxy);
      gi[2] = gz;
#else
      for (int corner = 0; corner < 8; ++corner) {
        const double wt = xy[corner & 3] * (corner & 4 ? w[2] : z0);
        for (int a = 0; a < 3; ++a) gi[a] += wt * q[offset[corner] + 1 + a];
      }
#endif
      return inv_t_ * gi;
    }
    const std::size_t* c = e.c;
    for (int corner = 0; corner < 8; ++corner) {
      const std::size_t q[3] = {c[0] + (corner & 1), c[1] + (corner >> 1 & 1), c[2] + (corner >> 2 & 1)};
      const double wt = (corner & 1 ? w[0] : 1 - w[0]) * (corner >> 1 & 1 ? w[1] : 1 - w[1]) * (corner >> 2 & 1 ? w[2] : 1 - w[2]);
      for (int a = 0; a < 3; ++a) {
        std::size_t lo[3] = {q[0], q[1], q[2]}, hi[3] = {q[0], q[1], q[2]};
        if (lo[a] > 0) --lo[a];
        if (hi[a] + 1 < g_.dims[a]) ++hi[a];
        const double diff = (double(g_.at(hi[0], hi[1], hi[2])) - g_.at(lo[0], lo[1], lo[2])) / double(hi[a] - lo[a]);
        gi[a] += wt * diff;
      }
    }
    return inv_t_ * gi;  // grad_world = A^-T grad_index
  }

  // grad_world = A^-T grad_index; for axis-aligned grids the diagonal alone (the products
  // with the zero entries add only zeros: the same numbers)
  Vec3 to_world(const Vec3& gi) const {
    if (diagonal_) return {inv_t_.m[0] * gi[0], inv_t_.m[4] * gi[1], inv_t_.m[8] * gi[2]};
    return inv_t_ * gi;
  }

  // l: unit vector towards the head light, -dir/|dir| (one per ray).
  static Vec3 head_light(const Vec3& wdir) { return (-1.0 / norm(wdir)) * wdir; }
  std::array<double, 3> shade(const std::array<double, 3>& c, const Cell& cell, const Vec3& l) const {
    return shade_with(c, gradient(cell), l);
  }
  // Blinn-Phong with the head light for a world-space gradient g.
  std::array<double, 3> shade_with(const std::array<double, 3>& c, const Vec3& g, const Vec3& l) const {
    const double gl = norm(g);
    if (gl <= gmin_) return c;  // no reliable normal: unshaded
    const Vec3 n = (-1.0 / gl) * g;
    double nl = dot(n, l);
    if (o_.two_sided) nl = std::abs(nl);
    const double diff = std::max(0.0, nl);
    double spec;
    if (spec_int_ == 20) {  // the default exponent: the loop below unrolled, the same products
      const double b2 = diff * diff, b4 = b2 * b2, b8 = b4 * b4;
      spec = b4 * (b8 * b8);
    } else if (spec_int_ >= 0) {  // integer exponent: by squaring (std::pow dominated the shaded sample)
      spec = 1;
      double b = diff;
      for (int x = spec_int_; x; x >>= 1, b *= b) spec *= x & 1 ? b : 1.0;  // x 1.0 is exact: no branch
    } else {
      spec = std::pow(diff, o_.phong[3]);
    }
    std::array<double, 3> out;
    const double lit = ka_ + kd_ * diff, highlight = ks_ * spec;
    for (int k = 0; k < 3; ++k) out[k] = c[k] * lit + highlight;
    return out;
  }

  // The coarsest skipping level whose node containing p is skippable (0 = the finest), its
  // node in b; -1 when the finest node is not.
  int skippable(const Vec3& p, std::size_t b[3]) const {
    b[0] = b[1] = b[2] = 0;
    std::size_t c[3];
    for (int a = 0; a < 3; ++a) c[a] = index_of(std::clamp(p[a], 0.0, hi_[a]));
    int found = -1;
    for (int L = 0; L < skip_levels_; ++L) {
      const SkipLevel& S = skip_[L];
      std::size_t q[3];
      for (int a = 0; a < 3; ++a) q[a] = std::min(c[a] >> S.shift, S.last[a]);
      if (!S.table[q[0] + S.n0 * (q[1] + S.n1 * q[2])]) break;
      found = L;
      b[0] = q[0], b[1] = q[1], b[2] = q[2];
    }
    return found;
  }

  // skippable() that also classifies the other case: returns true and the coarsest
  // skippable node (level L, node b) when the finest node of p is skippable; else false and
  // the coarsest dense node around p (level 0 at least: the finest node itself).
  bool classify(const Vec3& p, int& L, std::size_t b[3]) const {
    std::size_t c[3];
    for (int a = 0; a < 3; ++a) c[a] = index_of(std::clamp(p[a], 0.0, hi_[a]));
    const auto node = [&](int l, std::size_t q[3]) {
      for (int a = 0; a < 3; ++a) q[a] = std::min(c[a] >> skip_[l].shift, skip_[l].last[a]);
      return q[0] + skip_[l].n0 * (q[1] + skip_[l].n1 * q[2]);
    };
    const bool skip = skip_[0].table[node(0, b)];
    const char* SkipLevel::*table = skip ? &SkipLevel::table : &SkipLevel::dense;
    L = 0;
    for (int l = 1; l < skip_levels_; ++l) {
      std::size_t q[3];
      if (!(skip_[l].*table)[node(l, q)]) break;
      L = l, b[0] = q[0], b[1] = q[1], b[2] = q[2];
    }
    return skip;
  }

  // Ray parameter where the ray leaves the closed box of node b of skipping level L.
  double block_exit(const Vec3& o, const Vec3& d, const std::size_t b[3], int L) const {
    const std::size_t size = std::size_t{1} << (lf_ + L);
    double t = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0) continue;
      const double lo = double(b[a] * size), hi = double(std::min((b[a] + 1) * size, g_.dims[a] - 1));
      t = std::min(t, ((d[a] > 0 ? hi : lo) - o[a]) / d[a]);
    }
    return t;
  }

  // block_exit() with the reciprocal direction (0 where d = 0) computed once per ray: a
  // product instead of a division per axis and node. The exit may differ from
  // block_exit()'s in the last bit; the callers' 1e-9 step margin covers that, and a sample
  // computed that could have been skipped changes nothing.
  double block_exit_inv(const Vec3& o, const double inv_d[3], const std::size_t b[3], int L) const {
    const std::size_t size = std::size_t{1} << (lf_ + L);
    double t = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (inv_d[a] == 0) continue;
      const double lo = double(b[a] * size), hi = double(std::min((b[a] + 1) * size, g_.dims[a] - 1));
      t = std::min(t, ((inv_d[a] > 0 ? hi : lo) - o[a]) * inv_d[a]);
    }
    return t;
  }

  std::size_t segments(double t0, double t1, double dt) const {
    const double n = (t1 - t0) / dt;
    const double r = std::round(n);
    return static_cast<std::size_t>(std::abs(n - r) < 1e-9 ? r : std::ceil(n));
  }

  // dvr() for trilinear samples without pre-integration, unshaded or shaded from the
  // shading volume: the same samples and the same arithmetic, in a different order. The
  // march first schedules up to kBatch samples (the skipping decisions depend on the pyramid
  // only), then fetches, classifies and shades them in separate loops whose iterations are
  // independent, then composites them front to back until early termination. A shaded
  // sample is a chain of ~150 cycles (loads, lerps, exponential, square root, division) but
  // ~400 instructions, more than the processor's reorder window: one sample at a time, the
  // chains ran one after the other; in short loops the processor overlaps them. At most
  // kBatch - 1 samples past a ray's termination are computed and dropped (their stats too).
  void dvr_batched(const Vec3& o, const Vec3& d, const Vec3& wdir, double t0, double t1, double dt, double vox_per_t,
                   double dlen, double jit, std::array<double, 4>& out, double& depth, RenderStats& st) const {
    const std::size_t n = segments(t0, t1, dt);
    double C[3] = {0, 0, 0}, A = 0;
    const Vec3 light = head_light(wdir);
    double opaque_until = -std::numeric_limits<double>::infinity();
    const bool jitter = o_.jitter, shaded = o_.shade;
    double tm_[kBatch], len_[kBatch], f_[kBatch], tau_[kBatch], alpha_[kBatch];
    Vec3 p_[kBatch], gi_[kBatch];
    std::array<double, 3> c_[kBatch];
    std::size_t skipped_[kBatch];  // samples skipped just before each scheduled one
    std::size_t k = 0, skipped = 0;
    double kd = 0;  // double(k), kept exactly (integers) without a conversion per sample
    const double inv_d[3] = {d[0] != 0 ? 1 / d[0] : 0.0, d[1] != 0 ? 1 / d[1] : 0.0, d[2] != 0 ? 1 / d[2] : 0.0};
    const double inv_dt = 1 / dt;
    for (;;) {
      int m = 0;
      for (; m < kBatch && k < n; ++k, kd += 1) {
        const double ta = t0 + kd * dt, tb = k + 1 == n ? t1 : std::min(t0 + (kd + 1) * dt, t1);
        if (tb <= ta) continue;
        const double tm = jitter && (k + 1 < n || tb - ta >= dt) ? ta + jit * dt : 0.5 * (ta + tb);
        const Vec3 p = o + tm * d;
        if (!transparent_.empty() && !(tm < opaque_until)) {  // as in dvr(), products for quotients
          std::size_t b[3];
          int L;
          if (classify(p, L, b)) {
            const double te = block_exit_inv(o, inv_d, b, L) - 1e-9 * dt;
            std::size_t next = k + 1;
            if (te > tm) {
              const double kk = floor_of((te - t0) * inv_dt - 0.5);
              if (kk >= double(k + 1)) next = std::min(n, static_cast<std::size_t>(kk));
            }
            skipped += next - k;
            k = next - 1;
            kd = static_cast<double>(k);
            continue;
          }
          opaque_until = block_exit_inv(o, inv_d, b, L);  // the dense node's exit
        }
        tm_[m] = tm, len_[m] = (tb - ta) * vox_per_t, p_[m] = p, skipped_[m] = skipped;
        skipped = 0;
        ++m;
      }
      if (m == 0) break;
      if (f4_ || i16_) {
        for (int j = 0; j < m; ++j) {
          const Fetched fv = fetch(locate(p_[j]));
          f_[j] = fv.f, gi_[j] = fv.gi;
        }
      } else {
        for (int j = 0; j < m; ++j) f_[j] = trilinear(locate(p_[j]));
      }
      // classification; the samples with tau > 0 (not NaN) listed, the others add nothing
      int visible[kBatch], nv = 0;
      for (int j = 0; j < m; ++j) {
        const auto s = tf_.at(f_[j]);
        tau_[j] = s.tau, c_[j] = s.rgb, alpha_[j] = 0;
        visible[nv] = j;
        nv += s.tau > 0;
      }
      for (int q = 0; q < nv; ++q) {
        const int j = visible[q];
        alpha_[j] = 1 - exp_neg(tau_[j] * len_[j]);
      }
      if (shaded)
        for (int q = 0; q < nv; ++q) {
          const int j = visible[q];
          c_[j] = shade_with(c_[j], to_world(gi_[j]), light);
        }
      for (int j = 0; j < m; ++j) {
        st.skipped += skipped_[j];
        ++st.samples;
        const double alpha = alpha_[j];
        if (!(alpha > 0)) continue;
        const double w = (1 - A) * alpha;
        for (int ch = 0; ch < 3; ++ch) C[ch] += w * c_[j][ch];
        const double before = A;
        A += w;
        if (before < 0.5 && A >= 0.5) depth = tm_[j] * dlen;
        if (A >= o_.ert) {
          ++st.terminated;
          out = {C[0], C[1], C[2], A};
          return;
        }
      }
    }
    st.skipped += skipped;
    out = {C[0], C[1], C[2], A};
  }

  void dvr(const Vec3& o, const Vec3& d, const Vec3& wdir, double t0, double t1, double dt, double vox_per_t, double dlen,
           double jit, std::array<double, 4>& out, double& depth, RenderStats& st) const {
    const std::size_t n = segments(t0, t1, dt);
    double C[3] = {0, 0, 0}, A = 0;
    double prev_v = 0;
    bool have_prev = false;
    const Vec3 light = head_light(wdir);
    double opaque_until = -std::numeric_limits<double>::infinity();
    const bool jitter = o_.jitter;
    double kd = 0;  // double(k), kept exactly (integers) without a conversion per sample
    for (std::size_t k = 0; k < n; ++k, kd += 1) {
      const double ta = t0 + kd * dt, tb = k + 1 == n ? t1 : std::min(t0 + (kd + 1) * dt, t1);
      if (tb <= ta) continue;
      const double len = (tb - ta) * vox_per_t;
      const double tm = jitter && (k + 1 < n || tb - ta >= dt) ? ta + jit * dt : 0.5 * (ta + tb);
      const Vec3 p = o + tm * d;
      if (!transparent_.empty() && !(tm < opaque_until)) {
        std::size_t b[3];
        const int L = skippable(p, b);
        if (L >= 0) {
          // Every sample whose midpoint is inside this node contributes exactly nothing;
          // jump past them (a margin keeps samples on the node's face computed).
          const double te = block_exit(o, d, b, L) - 1e-9 * dt;
          std::size_t next = k + 1;
          if (te > tm) {
            const double kk = std::floor((te - t0) / dt - 0.5);
            if (kk >= double(k + 1)) next = std::min(n, static_cast<std::size_t>(kk));
          }
          st.skipped += next - k;
          k = next - 1;
          kd = static_cast<double>(k);
          have_prev = false;
          continue;
        }
        // Not skippable: neither is any sample before the ray leaves this finest node
        // (computing a sample that could have been skipped changes nothing either).
        std::size_t c[3];
        for (int a = 0; a < 3; ++a)
          c[a] = std::min(index_of(std::clamp(p[a], 0.0, hi_[a])) >> lf_, bn_[0][a] - 1);
        opaque_until = block_exit(o, d, c, 0);
      }
      ++st.samples;
      double alpha;
      std::array<double, 3> c;
      if (o_.preint) {
        const double vf = have_prev ? prev_v : value(o + ta * d), vb = value(o + tb * d);
        prev_v = vb, have_prev = true;
        if (std::abs(vb - vf) < 1e-6 * range_) {
          const auto s = tf_.at(0.5 * (vf + vb));
          alpha = 1 - exp_neg(s.tau * len);
          c = s.rgb;
        } else {
          const double dT = tf_.integral_tau(vb) - tf_.integral_tau(vf);
          alpha = 1 - exp_neg(len / (vb - vf) * dT);
          const auto Kb = tf_.integral_tau_color(vb), Kf = tf_.integral_tau_color(vf);
          if (std::abs(dT) > 0)
            for (int ch = 0; ch < 3; ++ch) c[ch] = (Kb[ch] - Kf[ch]) / dT;
          else
            c = tf_.at(0.5 * (vf + vb)).rgb;
        }
        if (alpha <= 0) continue;
        if (o_.shade) c = shade(c, locate(p), light);
      } else if (o_.nearest) {
        const auto s = tf_.at(value(p));
        if (!(s.tau > 0)) continue;  // alpha = 1 - exp(-0) = 0
        alpha = 1 - exp_neg(s.tau * len);
        c = s.rgb;
        if (alpha <= 0) continue;
        if (o_.shade) c = shade(c, locate(p), light);
      } else {
        const Cell e = locate(p);
        const auto s = tf_.at(trilinear(e));
        if (!(s.tau > 0)) continue;  // alpha = 1 - exp(-0) = 0
        alpha = 1 - exp_neg(s.tau * len);
        c = s.rgb;
        if (alpha <= 0) continue;
        if (o_.shade) c = shade(c, e, light);
      }
      const double w = (1 - A) * alpha;
      for (int ch = 0; ch < 3; ++ch) C[ch] += w * c[ch];
      const double before = A;
      A += w;
      if (before < 0.5 && A >= 0.5) depth = tm * dlen;
      if (A >= o_.ert) {
        ++st.terminated;
        break;
      }
    }
    out = {C[0], C[1], C[2], A};
  }

  void projection(const Vec3& o, const Vec3& d, double t0, double t1, double dt, double dlen, std::array<double, 4>& out,
                  double& depth, RenderStats& st) const {
    const std::size_t n = segments(t0, t1, dt);
    double best = o_.mode == Mode::mip ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    double best_t = t0, sum = 0, total = 0;
    const bool can_skip = pyr_ && o_.skip_empty && o_.mode != Mode::avg;
    for (std::size_t k = 0; k < n; ++k) {
      const double ta = t0 + k * dt, tb = std::min(t0 + (k + 1) * dt, t1);
      if (tb <= ta) continue;
      const double tm = 0.5 * (ta + tb);
      const Vec3 p = o + tm * d;
      if (can_skip && k > 0) {
        // A block whose range cannot beat the current extreme (strictly) changes nothing.
        std::size_t b[3];
        for (int a = 0; a < 3; ++a) {
          const double x = std::clamp(p[a], 0.0, static_cast<double>(g_.dims[a] - 1));
          b[a] = std::min(static_cast<std::size_t>(x) >> lf_, pyr_->nodes(lf_)[a] - 1);
        }
        const bool useless = o_.mode == Mode::mip ? pyr_->max(lf_, b[0], b[1], b[2]) <= best : pyr_->min(lf_, b[0], b[1], b[2]) >= best;
        if (useless) {
          double te = block_exit(o, d, b, 0);
          te -= 1e-9 * dt;
          const double kk = std::floor((te - t0) / dt - 0.5);
          std::size_t next = k + 1;
          if (kk >= double(k + 1)) next = std::min(n, static_cast<std::size_t>(kk));
          st.skipped += next - k;
          k = next - 1;
          continue;
        }
      }
      const double v = value(p);
      ++st.samples;
      if (o_.mode == Mode::mip ? v > best : o_.mode == Mode::minip ? v < best : false) best = v, best_t = tm;
      sum += v * (tb - ta), total += tb - ta;
    }
    if (total <= 0) return;
    const double v = o_.mode == Mode::avg ? sum / total : best;
    std::array<double, 3> c;
    if (o_.window) {
      const double g = std::clamp((v - (*o_.window)[0]) / ((*o_.window)[1] - (*o_.window)[0]), 0.0, 1.0);
      c = {g, g, g};
    } else {
      c = tf_.at(v).rgb;
    }
    out = {c[0], c[1], c[2], 1};
    depth = (o_.mode == Mode::avg ? t0 : best_t) * dlen;
  }

  // --slice-frame: a point of a plane lies on the plane's outline when it is within
  // frame_width (world) of a box face the plane meets (faces parallel to the plane excluded).
  // The world distance from face i = 0 is i / |row i of A^-1|.
  bool on_frame(const Vec3& p, const SliceStack& S) const {
    for (int a = 0; a < 3; ++a) {
      const Vec3 row{inv_.m[3 * a], inv_.m[3 * a + 1], inv_.m[3 * a + 2]};
      const double rl = norm(row);
      if (std::abs(dot(row, S.normal)) >= rl * (1 - 1e-9)) continue;  // face parallel to the plane
      if (std::min(p[a], hi_[a] - p[a]) / rl <= S.frame_width) return true;
    }
    return false;
  }

  // Fig. 4.5b: each plane the ray crosses inside the volume is one layer, front to back:
  // a contour band colour where |v - c_j| <= w/2, else the TF colour and opacity of v.
  void slices(const Ray& wr, const Vec3& o, const Vec3& d, double t0, double t1, double dlen, std::array<double, 4>& out,
              double& depth, RenderStats& st) const {
    const SliceStack& S = o_.slices;
    const double md = dot(S.normal, wr.dir), mo = dot(S.normal, wr.origin);
    if (md == 0) return;
    std::vector<double> ts;
    for (double off : S.offsets) {
      const double t = (off - mo) / md;
      if (t >= t0 && t <= t1) ts.push_back(t);
    }
    std::sort(ts.begin(), ts.end());
    double C[3] = {0, 0, 0}, A = 0;
    for (double t : ts) {
      const double v = value(o + t * d);
      ++st.samples;
      std::array<double, 3> c;
      double alpha;
      const double j = std::round((v - S.c0) / S.dc);
      // --contour-width-world W: the band |v - c_j| <= W |grad f| / 2 is W world units wide
      // across the contour (to first order), whatever the local gradient
      const double width = S.width_world > 0 ? S.width_world * norm(gradient(locate(o + t * d))) : S.width;
      if (S.frame_width > 0 && on_frame(o + t * d, S)) {
        c = {1, 1, 1};
        alpha = 1;
      } else if (j >= 0 && j < S.count && std::abs(v - (S.c0 + j * S.dc)) <= width / 2) {
        c = tf_.at(S.c0 + j * S.dc).rgb;
        alpha = S.contour_alpha;
      } else {
        const auto smp = tf_.at(v);
        c = smp.rgb;
        alpha = 1 - std::exp(-smp.tau * S.tf_unit);
      }
      const double w = (1 - A) * alpha;
      for (int ch = 0; ch < 3; ++ch) C[ch] += w * c[ch];
      if (A < 0.5 && A + w >= 0.5) depth = t * dlen;
      A += w;
    }
    out = {C[0], C[1], C[2], A};
  }

  void iso(const Vec3& o, const Vec3& d, const Vec3& wdir, double t0, double t1, double dt, double dlen,
           std::array<double, 4>& out, double& depth, RenderStats& st) const {
    const std::size_t n = segments(t0, t1, dt);
    double C[3] = {0, 0, 0}, A = 0;
    double ta = t0, va = value(o + t0 * d);
    const Vec3 light = head_light(wdir);
    for (std::size_t k = 0; k < n; ++k) {
      const double tb = std::min(t0 + (k + 1) * dt, t1);
      if (!transparent_.empty()) {
        std::size_t b[3];
        const Vec3 pa = o + ta * d;
        const int L = skippable(pa, b);
        if (L >= 0) {
          // no iso-value inside this node: the samples before its exit see no crossing
          const double te = block_exit(o, d, b, L) - 1e-9 * dt;
          const double kk = std::floor((te - t0) / dt) - 1;
          if (kk >= double(n)) {  // the rest of the ray lies in this block
            st.skipped += n - k;
            break;
          }
          if (kk > double(k)) {
            const std::size_t next = static_cast<std::size_t>(kk);
            st.skipped += next - k;
            ta = t0 + next * dt;
            va = value(o + ta * d);
            k = next - 1;
            continue;
          }
        }
      }
      const double vb = value(o + tb * d);
      ++st.samples;
      // every iso-value crossed in [ta, tb], front to back
      std::vector<std::pair<double, const IsoLayer*>> hits;
      for (const auto& L : o_.isos) {
        if ((va >= L.value) == (vb >= L.value)) continue;
        double lo = ta, hi = tb, flo = va - L.value;
        for (int it = 0; it < 8; ++it) {  // bisection: position error <= step / 256
          const double mid = 0.5 * (lo + hi);
          const double fm = value(o + mid * d) - L.value;
          if ((fm >= 0) == (flo >= 0)) lo = mid, flo = fm;
          else hi = mid;
        }
        hits.emplace_back(0.5 * (lo + hi), &L);
      }
      std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (const auto& [t, L] : hits) {
        const Vec3 p = o + t * d;
        std::array<double, 3> c = L->color ? *L->color : tf_.at(L->value).rgb;
        if (o_.shade) c = shade(c, locate(p), light);
        const double w = (1 - A) * L->alpha;
        for (int ch = 0; ch < 3; ++ch) C[ch] += w * c[ch];
        if (A < 1 && !(depth < std::numeric_limits<double>::infinity()) && L->alpha >= 1) depth = t * dlen;
        A += w;
      }
      if (A >= o_.ert) {
        ++st.terminated;
        break;
      }
      ta = tb, va = vb;
    }
    out = {C[0], C[1], C[2], A};
  }

  const ScalarGrid& g_;
  const MinMaxPyramid* pyr_;
  const TransferFunction& tf_;
  const RenderOptions& o_;
  SurfaceTracer surf_;
  const void* ctx_;
  Mat3 inv_, inv_t_;
  bool diagonal_ = false;                           // inv_t_ has zeros off the diagonal
  double hmin_ = 1, range_ = 1, gmin_ = 0, ka_ = 0, kd_ = 0, ks_ = 0;
  int lf_ = 3;                                      // the pyramid's finest level
  double hi_[3] = {0, 0, 0};                        // dims - 1 (the sample box)
  std::size_t cmax_[3] = {0, 0, 0};                 // dims - 2 (the last cell)
  std::vector<std::vector<char>> transparent_;      // skipping tables, finest level first
  std::vector<std::vector<char>> dense_;            // nodes with no skippable finest node, likewise
  struct SkipLevel {
    const char* table;
    const char* dense;
    std::size_t n0, n1, last[3];
    int shift;
  };
  SkipLevel skip_[kSkipLevels] = {};               // the same tables, flat, for the hot loop
  int skip_levels_ = 0;
  std::vector<std::array<std::size_t, 3>> bn_;      // their nodes per axis
  ShadingVolume own_;                               // built here when the caller gave none
  const std::int16_t* i16_ = nullptr;               // {f, 2 grad f} per sample as int16, or null
  const float* f4_ = nullptr;                       // {f, grad f} per sample as floats, or null
  std::size_t sy4_ = 0, sz4_ = 0;                  // its strides in floats along y and z
  int spec_int_ = -1;
};

}  // namespace

namespace {
// n elements of T on 2 MiB boundaries with MADV_HUGEPAGE (where the kernel offers
// transparent huge pages on request); plain pages elsewhere. Throws std::bad_alloc.
template <typename T>
T* huge_page_array(std::size_t n) {
  constexpr std::size_t kHuge = std::size_t{1} << 21;
  const std::size_t bytes = (n * sizeof(T) + kHuge - 1) / kHuge * kHuge;
  void* p = std::aligned_alloc(kHuge, bytes);
  if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  madvise(p, bytes, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
#endif
  return static_cast<T*>(p);
}

// Central differences, one-sided at the border: (f[up] - f[down]) / (up - down), for every
// sample of one x row: out(i, f, 2 fi, 2 fj, 2 fk) with the doubled differences as doubles
// (exact: they are differences of floats, times 1 or 2).
template <typename Out>
void difference_row(const ScalarGrid& g, std::size_t j, std::size_t k, const Out& out) {
  const auto& d = g.dims;
  const std::size_t sy = d[0], sz = d[0] * d[1];
  const float* f = &g.values[g.index(0, j, k)];
  const std::ptrdiff_t dy0 = j > 0 ? -std::ptrdiff_t(sy) : 0, dy1 = j + 1 < d[1] ? std::ptrdiff_t(sy) : 0;
  const std::ptrdiff_t dz0 = k > 0 ? -std::ptrdiff_t(sz) : 0, dz1 = k + 1 < d[2] ? std::ptrdiff_t(sz) : 0;
  const double hy = double((dy1 - dy0) / std::ptrdiff_t(sy)), hz = double((dz1 - dz0) / std::ptrdiff_t(sz));
  for (std::size_t i = 0; i < d[0]; ++i) {
    const std::ptrdiff_t x = std::ptrdiff_t(i), dx0 = i > 0 ? -1 : 0, dx1 = i + 1 < d[0] ? 1 : 0;
    out(i, f[i], (double(f[x + dx1]) - f[x + dx0]) / double(dx1 - dx0), (double(f[x + dy1]) - f[x + dy0]) / hy,
        (double(f[x + dz1]) - f[x + dz0]) / hz);
  }
}

bool fits_int16(double v) { return v >= -32768.0 && v <= 32767.0 && v == double(static_cast<int>(v)); }
}  // namespace

ShadingVolume shading_volume(const ScalarGrid& g, int threads) {
  ShadingVolume sv;
  const auto& d = g.dims;
  sv.samples = g.size();
  // exact as int16: integer samples in [lo, hi] with 2 (hi - lo) <= 32767, so that every
  // doubled difference (|f+ - f-| or 2 |f+ - f| at the border) fits too
  std::vector<char> exact(d[2], 1);
  std::vector<float> lo(d[2], 0), hi(d[2], 0);
  parallel_for(d[2], threads, [&](std::size_t k) {
    const float* f = &g.values[g.index(0, 0, k)];
    float l = f[0], h = f[0];
    bool ok = true;
    for (std::size_t q = 0; q < d[0] * d[1]; ++q) {
      ok = ok && fits_int16(f[q]);
      l = std::min(l, f[q]), h = std::max(h, f[q]);
    }
    exact[k] = ok, lo[k] = l, hi[k] = h;
  });
  const float all_lo = *std::min_element(lo.begin(), lo.end()), all_hi = *std::max_element(hi.begin(), hi.end());
  if (2 * (double(all_hi) - all_lo) > 32767) std::fill(exact.begin(), exact.end(), 0);
  if (std::all_of(exact.begin(), exact.end(), [](char e) { return e != 0; })) {
    sv.data16.reset(huge_page_array<std::int16_t>(4 * sv.samples));
    std::int16_t* data = sv.data16.get();
    parallel_for(d[2], threads, [&](std::size_t k) {
      for (std::size_t j = 0; j < d[1]; ++j) {
        std::int16_t* out = data + 4 * g.index(0, j, k);
        difference_row(g, j, k, [&](std::size_t i, float f, double gi, double gj, double gk) {
          std::int16_t* o = out + 4 * i;
          o[0] = static_cast<std::int16_t>(f), o[1] = static_cast<std::int16_t>(2 * gi);
          o[2] = static_cast<std::int16_t>(2 * gj), o[3] = static_cast<std::int16_t>(2 * gk);
        });
      }
    });
    return sv;
  }
  sv.data.reset(huge_page_array<float>(4 * sv.samples));
  float* data = sv.data.get();
  parallel_for(d[2], threads, [&](std::size_t k) {
    for (std::size_t j = 0; j < d[1]; ++j) {
      float* out = data + 4 * g.index(0, j, k);
      difference_row(g, j, k, [&](std::size_t i, float f, double gi, double gj, double gk) {
        float* o = out + 4 * i;
        o[0] = f, o[1] = static_cast<float>(gi), o[2] = static_cast<float>(gj), o[3] = static_cast<float>(gk);
      });
    }
  });
  return sv;
}

double sample_trilinear(const ScalarGrid& g, double x, double y, double z) {
  const double p[3] = {x, y, z};
  std::size_t c[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    const double q = std::clamp(p[a], 0.0, static_cast<double>(g.dims[a] - 1));
    c[a] = std::min(static_cast<std::size_t>(q), g.dims[a] - 2);
    w[a] = q - c[a];
  }
  const std::size_t sx = 1, sy = g.dims[0], sz = g.dims[0] * g.dims[1];
  const float* b = &g.values[g.index(c[0], c[1], c[2])];
  const double c00 = b[0] + w[0] * (double(b[sx]) - b[0]);
  const double c10 = b[sy] + w[0] * (double(b[sy + sx]) - b[sy]);
  const double c01 = b[sz] + w[0] * (double(b[sz + sx]) - b[sz]);
  const double c11 = b[sz + sy] + w[0] * (double(b[sz + sy + sx]) - b[sz + sy]);
  const double c0 = c00 + w[1] * (c10 - c00), c1 = c01 + w[1] * (c11 - c01);
  return c0 + w[2] * (c1 - c0);
}

bool clip_to_grid(const ScalarGrid& g, const Ray& wr, double& t0, double& t1) {
  const Mat3 inv = inverse(g.axes);
  return clip_index(g, inv * (wr.origin - g.origin), inv * wr.dir, t0, t1);
}

namespace {
bool clip_index(const ScalarGrid& g, const Vec3& o, const Vec3& d, double& t0, double& t1) {
  t0 = -std::numeric_limits<double>::infinity();
  t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double hi = static_cast<double>(g.dims[a] - 1);
    if (d[a] == 0) {
      if (o[a] < 0 || o[a] > hi) return false;
      continue;
    }
    double ta = (0 - o[a]) / d[a], tb = (hi - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}
}  // namespace

RenderedImage render(const ScalarGrid& grid, const MinMaxPyramid* pyramid, const TransferFunction& tf, const Camera& cam,
                     const RenderOptions& o, SurfaceTracer surface, const void* ctx, const ShadingVolume* shading) {
  if (!(o.step > 0)) throw std::invalid_argument("step must be positive");
  if (o.spp != 1 && o.spp != 4 && o.spp != 9 && o.spp != 16) throw std::invalid_argument("spp must be 1, 4, 9 or 16");
  if (o.mode == Mode::iso && o.isos.empty()) throw std::invalid_argument("iso mode needs at least one iso-value");
  if (o.mode == Mode::slices && (o.slices.offsets.empty() || !(o.slices.dc > 0) || norm(o.slices.normal) == 0))
    throw std::invalid_argument("slices mode needs planes, a positive contour spacing and a normal");
  if (grid.dims[0] < 2 || grid.dims[1] < 2 || grid.dims[2] < 2) throw std::invalid_argument("volume needs 2 samples along every axis");
  const int W = cam.width, H = cam.height;
  if (!o.pixel_mask.empty() && o.pixel_mask.size() != static_cast<std::size_t>(W) * H)
    throw std::invalid_argument("pixel mask does not match the image size");
  RenderedImage img;
  img.width = W, img.height = H;
  img.rgba.assign(static_cast<std::size_t>(W) * H * 4, 0.0f);
  img.depth.assign(static_cast<std::size_t>(W) * H, std::numeric_limits<float>::infinity());
  const int tiles_x = (W + kTile - 1) / kTile, tiles_y = (H + kTile - 1) / kTile;
  std::vector<RenderStats> tile_stats(static_cast<std::size_t>(tiles_x) * tiles_y);
  if (shading && shading->samples != grid.size()) throw std::invalid_argument("shading volume does not match the grid");
  const Caster caster(grid, pyramid, tf, o, surface, ctx, shading);
  const int sub = o.spp == 16 ? 4 : o.spp == 9 ? 3 : o.spp == 4 ? 2 : 1;
  ProgressCounter tiles_done(o.progress, tile_stats.size());
  parallel_for(tile_stats.size(), o.threads, [&](std::size_t tile) {
    const int tx = static_cast<int>(tile % tiles_x), ty = static_cast<int>(tile / tiles_x);
    RenderStats& st = tile_stats[tile];
    for (int j = ty * kTile; j < std::min(H, (ty + 1) * kTile); ++j)
      for (int i = tx * kTile; i < std::min(W, (tx + 1) * kTile); ++i) {
        std::array<double, 4> acc{0, 0, 0, 0};
        double depth = std::numeric_limits<double>::infinity();
        const bool cast = o.pixel_mask.empty() || o.pixel_mask[static_cast<std::size_t>(j) * W + i];
        for (int s = 0; s < (cast ? sub * sub : 0); ++s) {
          const double x = i + (s % sub + 0.5) / sub, y = j + (s / sub + 0.5) / sub;
          std::array<double, 4> c;
          double dd;
          caster.cast(cam.ray(x, y), o.jitter ? pixel_hash(i, j, s) : 0.5, c, dd, st);
          for (int k = 0; k < 4; ++k) acc[k] += c[k];
          if (s == 0) depth = dd;
        }
        for (auto& v : acc) v /= sub * sub;
        float* px = &img.rgba[(static_cast<std::size_t>(j) * W + i) * 4];
        if (o.keep_alpha) {
          for (int k = 0; k < 3; ++k) px[k] = static_cast<float>(acc[3] > 0 ? acc[k] / acc[3] : 0.0);
          px[3] = static_cast<float>(acc[3]);
        } else {
          for (int k = 0; k < 3; ++k) px[k] = static_cast<float>(acc[k] + (1 - acc[3]) * o.background[k]);
          px[3] = 1.0f;
        }
        img.depth[static_cast<std::size_t>(j) * W + i] = static_cast<float>(depth);
      }
    tiles_done.step();
  });
  tiles_done.finish();
  for (const auto& s : tile_stats) {
    img.stats.rays += s.rays, img.stats.samples += s.samples, img.stats.skipped += s.skipped, img.stats.terminated += s.terminated;
  }
  return img;
}

}  // namespace fest::raycast
