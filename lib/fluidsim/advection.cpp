#include "fluidsim/advection.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>

#include <omp.h>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace fest::fluidsim {

namespace {

// Trilinear interpolation set up once per position and applied to several fields: the
// base node, the offsets to its neighbours along each axis (a periodic wrap makes the
// offset negative) and the fractions. Nested lerps need 7 multiply-adds per field.
struct Lerp3 {
  std::size_t base = 0;
  std::ptrdiff_t off[3] = {0, 0, 0};
  double t[3] = {0, 0, 0};
  bool bad = false;

  Lerp3(const Layout& L, const std::array<double, 3>& q) noexcept {
    std::ptrdiff_t stride = 1;
    for (int a = 0; a < 3; ++a) {
      const int s = L.size[a];
      if (s == 1) {
        stride *= s;
        continue;
      }
      double p = q[a];
      if (!std::isfinite(p)) {
        bad = true;
        return;
      }
      int i0;
      if (L.bc[a] == Boundary::closed) {
        p = p < 0.0 ? 0.0 : (p > s - 1.0 ? s - 1.0 : p);
        i0 = static_cast<int>(p);
        if (i0 > s - 2) i0 = s - 2;
        off[a] = stride;
      } else {
        p = std::fmod(p, static_cast<double>(s));
        if (p < 0.0) p += s;
        i0 = static_cast<int>(p);
        if (i0 >= s) i0 = s - 1;
        off[a] = i0 + 1 == s ? -static_cast<std::ptrdiff_t>(s - 1) * stride : stride;
      }
      t[a] = p - i0;
      base += static_cast<std::size_t>(i0) * stride;
      stride *= s;
    }
  }

  double operator()(const double* f) const noexcept {
    if (bad) return std::numeric_limits<double>::quiet_NaN();
    const double* p = f + base;
    auto lerp = [](double a, double b, double s) { return a + s * (b - a); };
    const double x00 = lerp(p[0], p[off[0]], t[0]);
    const double x10 = lerp(p[off[1]], p[off[1] + off[0]], t[0]);
    const double y0 = lerp(x00, x10, t[1]);
    if (off[2] == 0) return y0;
    const double* r = p + off[2];
    const double x01 = lerp(r[0], r[off[0]], t[0]);
    const double x11 = lerp(r[off[1]], r[off[1] + off[0]], t[0]);
    return lerp(y0, lerp(x01, x11, t[1]), t[2]);
  }

  Lerp3() = default;
};

// The common case, made cheap: on a 3-D grid almost every back-traced position lies
// inside the node box, where no axis needs clamping (closed) or wrapping (periodic) and
// the cell index and weights follow from one truncation per axis (capped at the last
// cell, so a position on a closed axis's far wall node is inside too). The general
// Lerp3 constructor gives the same base, offsets and weights there (fmod of a position
// in [0, s) is the position itself), so results do not change; positions beyond a wall,
// in a periodic axis's wrap cell, and NaN (every comparison false) take the general path.
struct InteriorBox {
  bool usable = false;  // dim 3 with at least two nodes on every axis
  double hi[3] = {0, 0, 0};  // largest position inside: s - 1 (closed), just below it (periodic)
  int last[3] = {0, 0, 0};   // s - 2: the first node of the last cell
  std::ptrdiff_t stride[3] = {1, 0, 0};

  explicit InteriorBox(const Layout& L) noexcept {
    usable = L.dim == 3 && L.size[0] > 1 && L.size[1] > 1 && L.size[2] > 1;
    std::ptrdiff_t st = 1;
    for (int a = 0; a < 3; ++a) {
      hi[a] = L.size[a] - 1.0;
      if (L.bc[a] != Boundary::closed) hi[a] = std::nextafter(hi[a], 0.0);
      last[a] = L.size[a] - 2;
      stride[a] = st;
      st *= L.size[a];
    }
  }

  bool contains(const std::array<double, 3>& p) const noexcept {
    return usable && p[0] >= 0.0 && p[0] <= hi[0] && p[1] >= 0.0 && p[1] <= hi[1] && p[2] >= 0.0 && p[2] <= hi[2];
  }

  // The interpolation set-up at a position for which contains() holds.
  Lerp3 lerp_at(const std::array<double, 3>& p) const noexcept {
    Lerp3 s;
    const int i = std::min(static_cast<int>(p[0]), last[0]), j = std::min(static_cast<int>(p[1]), last[1]),
              k = std::min(static_cast<int>(p[2]), last[2]);
    s.t[0] = p[0] - i;
    s.t[1] = p[1] - j;
    s.t[2] = p[2] - k;
    s.off[0] = stride[0];
    s.off[1] = stride[1];
    s.off[2] = stride[2];
    s.base = static_cast<std::size_t>(i * stride[0] + j * stride[1] + k * stride[2]);
    return s;
  }

  Lerp3 lerp_any(const Layout& L, const std::array<double, 3>& p) const noexcept {
    return contains(p) ? lerp_at(p) : Lerp3(L, p);
  }
};

// The velocity the back-trace samples: one float32 lane quadruple (x, y, z, 0) per node,
// in index units per second. All three components share the 8 corners of a sample, so
// one 16-byte load per corner serves them and one vector lerp does the work of three
// scalar ones (SSE2, the x86-64 baseline; other targets get the same code through the
// compiler's generic vector lowering). The state is kept in float32 (docs/fluidsim.md §2); float32
// sampling moves a departure point by about 1e-7 cells, far below the scheme's error,
// while the fields themselves are still sampled and stored in double.
using Float4 = float __attribute__((vector_size(16)));

// Uninitialised storage (new[] of a vector type leaves it so): a std::vector would be
// zero-filled by one thread before the team fills it, a serial pass over N x 16 bytes.
std::unique_ptr<Float4[]> pack_velocity(const Layout& L, const Velocity& vel) {
  const std::size_t N = L.count();
  std::unique_ptr<Float4[]> packed(new Float4[N]);
  const double inv_h = 1.0 / L.h;
  if (L.dim == 3) {  // the common case without the per-lane loop
    const double *u = vel[0].data(), *v = vel[1].data(), *w = vel[2].data();
#pragma omp parallel for schedule(static) if (N >= kParallelNodes)
    for (std::size_t n = 0; n < N; ++n)
      packed[n] = Float4{static_cast<float>(u[n] * inv_h), static_cast<float>(v[n] * inv_h),
                         static_cast<float>(w[n] * inv_h), 0.0f};
    return packed;
  }
#pragma omp parallel for schedule(static) if (N >= kParallelNodes)
  for (std::size_t n = 0; n < N; ++n) {
    Float4 v = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int a = 0; a < L.dim; ++a) v[a] = static_cast<float>(vel[a][n] * inv_h);
    packed[n] = v;
  }
  return packed;
}

inline std::array<double, 3> velocity_at(const Layout& L, const InteriorBox& box, const Float4* packed,
                                         const std::array<double, 3>& p) noexcept {
  const Lerp3 s = box.lerp_any(L, p);
  if (s.bad) return {NAN, NAN, NAN};
  const Float4* q = packed + s.base;
  const std::ptrdiff_t o0 = s.off[0], o1 = s.off[1], o2 = s.off[2];
  auto splat = [](double t) {
    const float f = static_cast<float>(t);
    return Float4{f, f, f, f};
  };
  const Float4 t0 = splat(s.t[0]), t1 = splat(s.t[1]), t2 = splat(s.t[2]);
  auto lerp = [](Float4 a, Float4 b, Float4 t) { return a + t * (b - a); };
  // o2 == 0 on a 2-D grid: the second layer repeats the first and the z lerp returns it.
  const Float4* w = q + o2;
  const Float4 y0 = lerp(lerp(q[0], q[o0], t0), lerp(q[o1], q[o1 + o0], t0), t1);
  const Float4 y1 = lerp(lerp(w[0], w[o0], t0), lerp(w[o1], w[o1 + o0], t0), t1);
  const Float4 v = lerp(y0, y1, t2);
  return {double(v[0]), double(v[1]), double(v[2])};
}

std::array<double, 3> trace_packed(const Layout& L, const InteriorBox& box, const Float4* packed, int i, int j,
                                   int k, double dt, int substeps) noexcept {
  // The first RK4 stage of the first substep sits on the node itself: its velocity is
  // the node's value (what the trilinear sample with zero weights returns), no lookup.
  const Float4 at_node = packed[L.index(i, j, k)];
  std::array<double, 3> x{double(i), double(j), double(k)};
  const double h = -dt / substeps;  // backwards in time
  for (int s = 0; s < substeps; ++s) {
    auto at = [&](const std::array<double, 3>& kk, double f) {
      std::array<double, 3> p = x;
      for (int a = 0; a < 3; ++a) p[a] += f * h * kk[a];
      return p;
    };
    const auto k1 = s == 0 ? std::array<double, 3>{double(at_node[0]), double(at_node[1]), double(at_node[2])}
                           : velocity_at(L, box, packed, x);
    const auto k2 = velocity_at(L, box, packed, at(k1, 0.5));
    const auto k3 = velocity_at(L, box, packed, at(k2, 0.5));
    const auto k4 = velocity_at(L, box, packed, at(k3, 1.0));
    for (int a = 0; a < 3; ++a) x[a] += h / 6.0 * (k1[a] + 2.0 * k2[a] + 2.0 * k3[a] + k4[a]);
    if (substeps > 1) x = confine(L, x);
  }
  return x;
}

// The back-trace of a 3-D interior node, kept in float32 vector lanes (x, y, z, 0) from
// start to finish. The position is held as a displacement d from the node: the node's
// integer index is exact, and d (a few cells at most) keeps float32's relative precision,
// about 1e-7 cells, the same as the float32 velocity samples themselves. The cell of a
// sample is node + floor(d), found with one vector truncation; the bounds of the node box
// become per-node bounds on d. While every sample of the RK4 stages and the departure
// point lie inside the node box no clamping or wrapping is needed; otherwise (walls,
// periodic wrap cells, non-finite values) the caller redoes the node with the general
// trace_packed, so the two paths never mix within one node.
using Int4 = int __attribute__((vector_size(16)));

struct FastTrace {
  Float4 hi_base{0, 0, 0, 0};   // largest inside position per axis (as InteriorBox::hi)
  Int4 cap_base{0, 0, 0, 0};    // s - 2: first node of the last cell
  std::ptrdiff_t s1 = 0, s2 = 0;  // strides of y and z
  const Float4* packed = nullptr;

  FastTrace(const Layout& L, const InteriorBox& box, const Float4* velocity) noexcept : packed(velocity) {
    for (int a = 0; a < 3; ++a) {
      hi_base[a] = static_cast<float>(box.hi[a]);
      // A periodic axis's hi is just below s - 1; rounding it to float must not reach it.
      if (static_cast<double>(hi_base[a]) > box.hi[a]) hi_base[a] = std::nextafter(hi_base[a], 0.0f);
      cap_base[a] = box.last[a];
    }
    s1 = L.size[0];
    s2 = static_cast<std::ptrdiff_t>(L.size[0]) * L.size[1];
  }

  // Bounds of one node: d inside [lo, hi] on every axis keeps the sample in the box.
  struct Node {
    Float4 lo, hi;
    Int4 cap;
    std::ptrdiff_t index;
  };
  Node node(int i, int j, int k, std::size_t index) const noexcept {
    const Float4 pos = {float(i), float(j), float(k), 0.0f};
    const Int4 ipos = {i, j, k, 0};
    return {-pos, hi_base - pos, cap_base - ipos, static_cast<std::ptrdiff_t>(index)};
  }

  static bool inside(const Node& n, Float4 d) noexcept {
    const Int4 in = (d >= n.lo) & (d <= n.hi);  // lane 3 (0 within [0, 0]) is always in
#if defined(__SSE__)
    return _mm_movemask_ps(reinterpret_cast<__m128>(in)) == 0xF;
#else
    return (in[0] & in[1] & in[2]) != 0;
#endif
  }

  // Cell offset (floor of d, capped at the last cell) and the fractions within the cell.
  static void cell(const Node& n, Float4 d, Int4& c, Float4& t) noexcept {
    Int4 f = __builtin_convertvector(d, Int4);  // truncation towards zero
    f += __builtin_convertvector(f, Float4) > d;  // -1 where truncation rounded up: floor
    f = f < n.cap ? f : n.cap;
    c = f;
    t = d - __builtin_convertvector(f, Float4);
  }

  // Velocity at displacement d (d inside the box).
  Float4 velocity(const Node& n, Float4 d) const noexcept {
    Int4 c;
    Float4 t;
    cell(n, d, c, t);
    const Float4* q = packed + (n.index + c[0] + c[1] * s1 + c[2] * s2);
    const Float4* w = q + s2;
    const Float4 t0 = {t[0], t[0], t[0], t[0]}, t1 = {t[1], t[1], t[1], t[1]}, t2 = {t[2], t[2], t[2], t[2]};
    auto lerp = [](Float4 a, Float4 b, Float4 s) { return a + s * (b - a); };
    const Float4 y0 = lerp(lerp(q[0], q[1], t0), lerp(q[s1], q[s1 + 1], t0), t1);
    const Float4 y1 = lerp(lerp(w[0], w[1], t0), lerp(w[s1], w[s1 + 1], t0), t1);
    return lerp(y0, y1, t2);
  }

  // d itself where it is inside the node's box, else the nearest bound (NaN: the lower
  // one), so that a sample never reads outside the grid.
  static Float4 clamped(const Node& n, Float4 d) noexcept {
    const Float4 c = d >= n.lo ? d : n.lo;
    return c <= n.hi ? c : n.hi;
  }

  // One RK4 step backwards over dt from each of N nodes, stage by stage across the
  // nodes: every stage is a chain of dependent loads, and N independent chains side by
  // side keep the core busy while one waits. ok[q] is false if a sample of node q left
  // the box (its samples were then taken at clamped positions and are discarded).
  template <int N>
  void trace(const Node* n, float dt, Lerp3* out, bool* ok) const noexcept {
    const float h = -dt;
    Float4 k1[N], k2[N], k3[N], k4[N], d[N];
    for (int q = 0; q < N; ++q) {
      k1[q] = packed[n[q].index];
      d[q] = (0.5f * h) * k1[q];
      ok[q] = inside(n[q], d[q]);
    }
    for (int q = 0; q < N; ++q) {
      k2[q] = velocity(n[q], clamped(n[q], d[q]));
      d[q] = (0.5f * h) * k2[q];
      ok[q] &= inside(n[q], d[q]);
    }
    for (int q = 0; q < N; ++q) {
      k3[q] = velocity(n[q], clamped(n[q], d[q]));
      d[q] = h * k3[q];
      ok[q] &= inside(n[q], d[q]);
    }
    for (int q = 0; q < N; ++q) {
      k4[q] = velocity(n[q], clamped(n[q], d[q]));
      d[q] = (h / 6.0f) * (k1[q] + 2.0f * k2[q] + 2.0f * k3[q] + k4[q]);
      ok[q] &= inside(n[q], d[q]);
    }
    for (int q = 0; q < N; ++q) {
      Int4 c;
      Float4 t;
      cell(n[q], clamped(n[q], d[q]), c, t);
      out[q].base = static_cast<std::size_t>(n[q].index + c[0] + c[1] * s1 + c[2] * s2);
      out[q].off[0] = 1;
      out[q].off[1] = s1;
      out[q].off[2] = s2;
      for (int a = 0; a < 3; ++a) out[q].t[a] = t[a];
    }
  }
};

// Lerp3::operator() for a 3-D cell with unit offsets {1, s1, s2} (no wrap), two lanes at
// a time: each x pair of corners is one 16-byte load, the x lerps of the z0 and z1 layers
// run side by side, then the y lerps; the z lerp is scalar. Lane by lane the operations
// are those of operator(), so the result is bit-identical.
using Double2 = double __attribute__((vector_size(16)));

inline Double2 load2(const double* p) noexcept {
  Double2 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline double sample_unwrapped(const Lerp3& s, const double* f) noexcept {
  const double* p = f + s.base;
  const std::ptrdiff_t o1 = s.off[1], o2 = s.off[2];
  const Double2 a00 = load2(p), a10 = load2(p + o1), a01 = load2(p + o2), a11 = load2(p + o1 + o2);
  // (x0 at z0, x0 at z1) and (x1 at z0, x1 at z1) for the y0 and y1 rows.
  const Double2 y0x0 = {a00[0], a01[0]}, y0x1 = {a00[1], a01[1]};
  const Double2 y1x0 = {a10[0], a11[0]}, y1x1 = {a10[1], a11[1]};
  const Double2 t0 = {s.t[0], s.t[0]}, t1 = {s.t[1], s.t[1]};
  auto lerp = [](Double2 a, Double2 b, Double2 t) { return a + t * (b - a); };
  const Double2 y = lerp(lerp(y0x0, y0x1, t0), lerp(y1x0, y1x1, t0), t1);  // (z0, z1)
  return y[0] + s.t[2] * (y[1] - y[0]);
}

}  // namespace

std::array<double, 3> trace_back(const Layout& L, const Velocity& vel, int i, int j, int k, double dt,
                                 int substeps) {
  const std::unique_ptr<Float4[]> packed = pack_velocity(L, vel);
  return trace_packed(L, InteriorBox(L), packed.get(), i, j, k, dt, substeps);
}

void advect(const Layout& L, const Velocity& vel, double dt, int substeps, const std::vector<const Field*>& in,
            const std::vector<Field*>& out) {
  const std::size_t nf = in.size();
  // Raw pointers once, outside the node loop: through the vectors of Field pointers the
  // compiler must reload both after every store (a store may alias them).
  std::vector<const double*> src(nf);
  std::vector<double*> dst(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    src[f] = in[f]->data();
    dst[f] = out[f]->data();
  }
  const double* const* const srcp = src.data();
  double* const* const dstp = dst.data();
  const std::unique_ptr<Float4[]> packed = pack_velocity(L, vel);
  const InteriorBox box(L);
  // The float32 fast path: 3-D grids, one substep (substeps confine between stages).
  std::optional<FastTrace> fast;
  if (box.usable && substeps == 1) fast.emplace(L, box, packed.get());
  const float fdt = static_cast<float>(dt);
  const int rows = L.size[1] * L.size[2];
  // About four chunks per thread, as the seed found necessary for saturation.
  const int chunk = std::max(1, rows / (4 * omp_get_max_threads()));
#pragma omp parallel for schedule(dynamic, chunk) if (L.count() >= kParallelNodes)
  for (int r = 0; r < rows; ++r) {
    const int j = r % L.size[1], k = r / L.size[1];
    const std::size_t row = L.index(0, j, k);
    auto general = [&](int i) {
      const Lerp3 s = box.lerp_any(L, trace_packed(L, box, packed.get(), i, j, k, dt, substeps));
      for (std::size_t f = 0; f < nf; ++f) dstp[f][row + i] = s(srcp[f]);
    };
    int i = 0;
    if (fast) {
      // Nodes in pairs through the fast trace; a node whose samples left the box is
      // redone alone on the general path.
      constexpr int kPair = 2;
      for (; i + kPair <= L.size[0]; i += kPair) {
        FastTrace::Node nodes[kPair];
        Lerp3 s[kPair];
        bool ok[kPair];
        for (int q = 0; q < kPair; ++q) nodes[q] = fast->node(i + q, j, k, row + i + q);
        fast->trace<kPair>(nodes, fdt, s, ok);
        for (int q = 0; q < kPair; ++q) {
          if (!ok[q]) {
            general(i + q);
            continue;
          }
          for (std::size_t f = 0; f < nf; ++f) dstp[f][row + i + q] = sample_unwrapped(s[q], srcp[f]);
        }
      }
    }
    for (; i < L.size[0]; ++i) general(i);
  }
}

}  // namespace fest::fluidsim
