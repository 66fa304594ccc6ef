// The solver (docs/lbmsim.md 2.3-2.4, 2.9): setup of the link tables from the node
// classes, the fused pull stream-collide over row segments, and the per-step boundary,
// periodic and halo work.
#include "lbm/solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "lbm/collide.hpp"

namespace fest::lbm {

std::array<double, 2> relaxation_rates(const Collision& c) {
  const double wp = 1.0 / c.tau;
  if (c.model == CollisionModel::bgk) return {wp, wp};
  const double wm = 1.0 / (0.5 + c.lambda / (c.tau - 0.5));
  return {wp, wm};
}

namespace {

// A run of nodes in one row: bulk nodes x0..x1-1 (rec < 0) or one boundary node (rec).
struct Segment {
  int x0, x1;
  int rec;
};

struct BoundaryNode {
  std::size_t n;
  std::uint32_t bounce;  // bit i: population i comes from a solid (bounce back)
  int coef = -1;         // offset of Q moving-wall coefficients 6 w_i (c_i . u_w), or -1
  int q = -1;            // offset of Q link fractions (interpolated bounce-back), or -1
};

struct ForceLink {
  std::size_t n;
  int layer;   // local layer of the last axis
  int i;       // incoming direction (bounced)
  int rec;     // boundary node record
  std::uint8_t id;
};

struct NeeNode {
  std::size_t b, n;  // boundary ghost node and its fluid neighbour
  bool inlet;
  bool has_neighbour;
  double u[3];
  double rho;
};

template <class L, class Real>
class SolverT final : public Solver {
  static constexpr int Q = L::Q;
  static constexpr int D = L::D;

 public:
  explicit SolverT(const SolverSetup& s) : c_(*s.c), ex_(s.exchange ? s.exchange : &local_) {
    const int S = D - 1;
    global_ = c_.size;
    lo_ = s.slab_lo;
    const int hi = s.slab_hi < 0 ? global_[S] : s.slab_hi;
    if (lo_ < 0 || hi > global_[S] || hi <= lo_) throw bad_input("slab {}..{} does not fit {} layers", lo_, hi, global_[S]);
    n_ = global_;
    n_[S] = hi - lo_;
    for (int a = 0; a < 3; ++a) p_[a] = a < D ? n_[a] + 2 : 1;
    N_ = static_cast<std::size_t>(p_[0]) * p_[1] * p_[2];
    for (int i = 0; i < Q; ++i)
      off_[i] = static_cast<std::ptrdiff_t>(L::c[i][0]) + static_cast<std::ptrdiff_t>(L::c[i][1]) * p_[0] +
                static_cast<std::ptrdiff_t>(L::c[i][2]) * p_[0] * p_[1];
    const auto rates = relaxation_rates(c_.collision);
    par_.omega_p = static_cast<Real>(rates[0]);
    par_.omega_m = static_cast<Real>(rates[1]);
    for (int a = 0; a < 3; ++a) par_.force[a] = static_cast<Real>(c_.force[a]);
    inc_ = c_.collision.incompressible;
    compressible_ = inc_ ? Real(0) : Real(1);
    force_on_ = c_.force[0] != 0 || c_.force[1] != 0 || c_.force[2] != 0;
    trt_ = c_.collision.model == CollisionModel::trt;
    build(*s.flags);
    a_.assign(N_ * Q, Real(0));
    b_.assign(N_ * Q, Real(0));
    initialise(s.init);
  }

  void step() override {
    Real* A = a_.data();
    Real* B = b_.data();
    const int rows = static_cast<int>(row_begin_.size()) - 1;
    if (inc_) sweep_for<true>(A, B, rows);
    else sweep_for<false>(A, B, rows);
    finish(B);
    a_.swap(b_);
    ++steps_;
  }

  long step_count() const override { return steps_; }

  void moments(std::vector<double>& rho, std::vector<double>& u) const override {
    const std::size_t cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
    rho.assign(cells, 1.0);
    u.assign(3 * cells, 0.0);
    const Real* A = a_.data();
    const int rows = static_cast<int>(row_begin_.size()) - 1;
#pragma omp parallel for schedule(static) if (N_ > 16384)
    for (int r = 0; r < rows; ++r) {
      const int y = D == 2 ? r : r % n_[1];
      const int z = D == 2 ? 0 : r / n_[1];
      for (int s = row_begin_[r]; s < row_begin_[r + 1]; ++s) {
        const Segment& g = segs_[s];
        for (int x = g.x0; x < g.x1; ++x) {
          const std::size_t n = index(x, y, z);
          // Post-collision populations of time t carry the moments of time t: the
          // collision keeps rho and adds F to the momentum, so u = (sum c g* - F/2)/rho.
          Real f[Q];
          for (int i = 0; i < Q; ++i) f[i] = A[i * N_ + n];
          CollideParams<Real> back = par_;
          for (int a = 0; a < 3; ++a) back.force[a] = -par_.force[a];
          Real rr, uu[3];
          if (force_on_) {
            if (inc_) node_moments<L, Real, true, true>(f, back, rr, uu);
            else node_moments<L, Real, true>(f, back, rr, uu);
          } else {
            if (inc_) node_moments<L, Real, false, true>(f, back, rr, uu);
            else node_moments<L, Real, false>(f, back, rr, uu);
          }
          const std::size_t k = static_cast<std::size_t>(x) + static_cast<std::size_t>(n_[0]) * (y + static_cast<std::size_t>(n_[1]) * z);
          rho[k] = 1.0 + static_cast<double>(rr);
          for (int a = 0; a < 3; ++a) u[3 * k + a] = uu[a];
        }
      }
    }
  }

  std::vector<double> layer_mass() const override {
    const int S = D - 1;
    std::vector<double> m(n_[S], 0.0);
    const Real* A = a_.data();
    const int rows = static_cast<int>(row_begin_.size()) - 1;
    std::vector<double> row_sum(rows, 0.0);
#pragma omp parallel for schedule(static) if (N_ > 16384)
    for (int r = 0; r < rows; ++r) {
      const int y = D == 2 ? r : r % n_[1];
      const int z = D == 2 ? 0 : r / n_[1];
      double sum = 0;
      long count = 0;
      for (int s = row_begin_[r]; s < row_begin_[r + 1]; ++s)
        for (int x = segs_[s].x0; x < segs_[s].x1; ++x) {
          const std::size_t n = index(x, y, z);
          for (int i = 0; i < Q; ++i) sum += A[i * N_ + n];
          ++count;
        }
      row_sum[r] = sum + static_cast<double>(count);  // shifted populations: rho = 1 + sum g
    }
    const int per_layer = D == 2 ? 1 : n_[1];
    for (int r = 0; r < rows; ++r) m[r / per_layer] += row_sum[r];
    return m;
  }

  std::vector<double> layer_force(std::uint8_t id) const override {
    const int S = D - 1;
    std::vector<double> f(3 * static_cast<std::size_t>(n_[S]), 0.0);
    const Real* A = a_.data();
    for (const ForceLink& l : links_) {
      if (l.id != id) continue;
      const BoundaryNode& b = bnodes_[l.rec];
      const int o = L::opp[l.i];
      double extra = 0;
      if (b.coef >= 0) {
        double rho = 1;
        if (!c_.collision.incompressible)
          for (int i = 0; i < Q; ++i) rho += A[i * N_ + b.n];
        extra = coefs_[b.coef + l.i] * rho;
      }
      // Momentum given to the solid: c_o (f_o* + f_i(t+1)), with c_o = -c_i and f = g + w.
      double m = 2.0 * (A[o * N_ + b.n] + L::w[o]) + extra;
      if (b.q >= 0) m = A[o * N_ + b.n] + L::w[o] + incoming(A, b, b.n, l.i, Real(1)) + L::w[l.i];
      for (int a = 0; a < 3; ++a) f[3 * l.layer + a] -= L::c[l.i][a] * m;
    }
    return f;
  }

  std::array<int, 3> local_size() const override { return n_; }
  int slab_lo() const override { return lo_; }
  std::size_t fluid_nodes() const override { return fluid_; }
  double bytes_per_update() const override { return 3.0 * Q * sizeof(Real); }

  std::vector<double> populations() const override {
    const std::size_t cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
    std::vector<double> out(cells * Q);
    for (int z = 0; z < n_[2]; ++z)
      for (int y = 0; y < n_[1]; ++y)
        for (int x = 0; x < n_[0]; ++x) {
          const std::size_t k = static_cast<std::size_t>(x) + static_cast<std::size_t>(n_[0]) * (y + static_cast<std::size_t>(n_[1]) * z);
          for (int i = 0; i < Q; ++i) out[i * cells + k] = a_[i * N_ + index(x, y, z)] + L::w[i];
        }
    return out;
  }

 private:
  std::size_t index(int x, int y, int z) const noexcept {
    return static_cast<std::size_t>(x + 1) +
           static_cast<std::size_t>(p_[0]) * (static_cast<std::size_t>(y + 1) + static_cast<std::size_t>(p_[1]) * (z + (D == 3 ? 1 : 0)));
  }

  // Pre-collision populations of node n: pulled from the neighbours, bounced at solids.
  inline void gather(const Real* A, std::size_t n, int rec, Real* f) const {
    if (rec < 0) {
#pragma GCC unroll 32
      for (int i = 0; i < Q; ++i) f[i] = A[i * N_ + n - off_[i]];
      return;
    }
    const BoundaryNode& b = bnodes_[rec];
    Real rho = 1;  // the density of Ladd's term (rho0 = 1 in the incompressible model)
    if (b.coef >= 0 && !c_.collision.incompressible)
      for (int i = 0; i < Q; ++i) rho += A[i * N_ + n];
    for (int i = 0; i < Q; ++i) {
      if (b.bounce & (1u << i)) {
        f[i] = incoming(A, b, n, i, rho);
      } else {
        f[i] = A[i * N_ + n - off_[i]];
      }
    }
  }

  // Population i arriving at boundary node n from the solid at n - c_i (o = opposite):
  // halfway bounce-back f_i = f_o*, plus Ladd's moving-wall term 6 w_i rho (c_i . u_w);
  // on curved links the linear interpolation of Bouzidi, Firdaouss & Lallemand (2001)
  // with the wall at fraction q of the link: q < 1/2: 2q f_o*(x) + (1-2q) f_o*(x + c_i);
  // q >= 1/2: f_o*(x)/(2q) + (1 - 1/(2q)) f_i*(x).
  inline Real incoming(const Real* A, const BoundaryNode& b, std::size_t n, int i, Real rho) const {
    const int o = L::opp[i];
    if (b.q >= 0) {
      const double q = qs_[b.q + i];
      if (q > 0) {
        if (q < 0.5)
          return static_cast<Real>(2 * q) * A[o * N_ + n] + static_cast<Real>(1 - 2 * q) * A[o * N_ + n + off_[i]];
        return static_cast<Real>(0.5 / q) * A[o * N_ + n] + static_cast<Real>(1 - 0.5 / q) * A[i * N_ + n];
      }
    }
    Real v = A[o * N_ + n];
    if (b.coef >= 0) v += static_cast<Real>(coefs_[b.coef + i]) * rho;
    return v;
  }

  template <bool INC>
  void sweep_for(const Real* A, Real* B, int rows) const {
    if (trt_) {
      if (force_on_) sweep<true, true, INC>(A, B, rows);
      else sweep<true, false, INC>(A, B, rows);
    } else {
      if (force_on_) sweep<false, true, INC>(A, B, rows);
      else sweep<false, false, INC>(A, B, rows);
    }
  }

  template <bool TRT, bool FORCE, bool INC>
  void sweep(const Real* __restrict A, Real* __restrict B, int rows) const {
    const std::size_t N = N_;
#pragma omp parallel for schedule(static) if (N_ > 16384)
    for (int r = 0; r < rows; ++r) {
      const int y = D == 2 ? r : r % n_[1];
      const int z = D == 2 ? 0 : r / n_[1];
      const std::size_t base = index(0, y, z);
      for (int s = row_begin_[r]; s < row_begin_[r + 1]; ++s) {
        const Segment g = segs_[s];
        if (g.rec < 0) {
          // Bulk run: each direction's plane is read at consecutive addresses along x,
          // so the loop vectorises across nodes (same arithmetic per node as the scalar path).
          const Real* src[Q];
          Real* dst[Q];
          for (int i = 0; i < Q; ++i) {
            src[i] = A + i * N + base - off_[i];
            dst[i] = B + i * N + base;
          }
          const CollideParams<Real> par = par_;
#pragma omp simd
          for (int x = g.x0; x < g.x1; ++x) {
            Real f[Q], o[Q];
#pragma GCC unroll 32
            for (int i = 0; i < Q; ++i) f[i] = src[i][x];
            collide<L, Real, TRT, FORCE, INC>(f, o, par);
#pragma GCC unroll 32
            for (int i = 0; i < Q; ++i) dst[i][x] = o[i];
          }
        } else {
          const std::size_t n = base + g.x0;
          Real f[Q], o[Q];
          gather(A, n, g.rec, f);
          collide<L, Real, TRT, FORCE, INC>(f, o, par_);
          for (int i = 0; i < Q; ++i) B[i * N + n] = o[i];
        }
      }
    }
  }

  // After the sweep: periodic ghosts, boundary nodes (non-equilibrium extrapolation),
  // periodic ghosts again (corners of inlets on periodic axes), then the slab halo.
  void finish(Real* B) {
    periodic_copy(B);
    if (!nee_.empty()) {
      fill_nee(B);
      periodic_copy(B);
    }
    halo(B);
  }

  void periodic_copy(Real* B) const {
    for (int a = 0; a < D - 1; ++a) {
      if (!c_.periodic(a)) continue;
      // Every cell of the padded box whose coordinate a is a ghost.
      const std::size_t stride = a == 0 ? 1 : static_cast<std::size_t>(p_[0]);
      const int na = n_[a];
      for (int z = 0; z < p_[2]; ++z)
        for (int y = 0; y < (a == 0 ? p_[1] : 1); ++y)
          for (int x = 0; x < (a == 0 ? 1 : p_[0]); ++x) {
            const std::size_t first = static_cast<std::size_t>(x) + static_cast<std::size_t>(p_[0]) * (y + static_cast<std::size_t>(p_[1]) * z);
            const std::size_t g0 = first, g1 = first + stride * (na + 1);
            const std::size_t s0 = first + stride * na, s1 = first + stride;
            for (int i = 0; i < Q; ++i) {
              B[i * N_ + g0] = B[i * N_ + s0];
              B[i * N_ + g1] = B[i * N_ + s1];
            }
          }
    }
  }

  void fill_nee(Real* B) const {
    for (const NeeNode& e : nee_) {
      Real fn[Q];
      double rho_n = 1, un[3] = {0, 0, 0};
      if (e.has_neighbour) {
        rho_n = 1;
        double j[3] = {0, 0, 0};
        for (int i = 0; i < Q; ++i) {
          fn[i] = B[i * N_ + e.n];
          rho_n += fn[i];
          for (int a = 0; a < 3; ++a) j[a] += L::c[i][a] * static_cast<double>(fn[i]);
        }
        for (int a = 0; a < 3; ++a) un[a] = j[a] / (c_.collision.incompressible ? 1.0 : rho_n);
      }
      const double rho_b = e.inlet ? rho_n : e.rho;
      const double* ub = e.inlet ? e.u : un;
      Real urb[3] = {static_cast<Real>(ub[0]), static_cast<Real>(ub[1]), static_cast<Real>(ub[2])};
      Real urn[3] = {static_cast<Real>(un[0]), static_cast<Real>(un[1]), static_cast<Real>(un[2])};
      for (int i = 0; i < Q; ++i) {
        Real v = equilibrium<L, Real>(i, static_cast<Real>(rho_b - 1), urb, compressible_);
        if (e.has_neighbour) v += fn[i] - equilibrium<L, Real>(i, static_cast<Real>(rho_n - 1), urn, compressible_);
        B[i * N_ + e.b] = v;
      }
    }
  }

  void halo(Real* B) {
    const int S = D - 1;
    const bool periodic = c_.periodic(S);
    const bool lower = periodic || lo_ > 0, upper = periodic || lo_ + n_[S] < global_[S];
    if (!lower && !upper) return;
    const std::size_t layer = D == 2 ? static_cast<std::size_t>(p_[0]) : static_cast<std::size_t>(p_[0]) * p_[1];
    const std::size_t count = up_.size() * layer;
    send_lo_.resize(count);
    send_hi_.resize(count);
    recv_lo_.resize(count);
    recv_hi_.resize(count);
    const std::size_t first = layer, last = layer * n_[S], ghost_lo = 0, ghost_hi = layer * (n_[S] + 1);
    for (std::size_t k = 0; k < up_.size(); ++k) {
      std::memcpy(&send_hi_[k * layer], &B[up_[k] * N_ + last], layer * sizeof(Real));
      std::memcpy(&send_lo_[k * layer], &B[down_[k] * N_ + first], layer * sizeof(Real));
    }
    ex_->exchange(send_lo_.data(), send_hi_.data(), recv_lo_.data(), recv_hi_.data(), count * sizeof(Real), periodic);
    for (std::size_t k = 0; k < up_.size(); ++k) {
      if (lower) std::memcpy(&B[up_[k] * N_ + ghost_lo], &recv_lo_[k * layer], layer * sizeof(Real));
      if (upper) std::memcpy(&B[down_[k] * N_ + ghost_hi], &recv_hi_[k * layer], layer * sizeof(Real));
    }
  }

  NodeClass class_at(const Flags& flags, int x, int y, int z) const {
    int g[3] = {x, y, z};
    g[D - 1] += lo_;
    return classify(c_, flags, g[0], g[1], D == 3 ? g[2] : 0);
  }

  void build(const Flags& flags) {
    const int S = D - 1;
    for (int i = 0; i < Q; ++i) {
      if (L::c[i][S] == 1) up_.push_back(i);
      if (L::c[i][S] == -1) down_.push_back(i);
    }
    // Classes of the padded box (local coordinates -1..n).
    using K = NodeClass::Kind;
    std::vector<K> cls(N_);
    const int z0 = D == 3 ? -1 : 0, z1 = D == 3 ? n_[2] + 1 : 1;
    for (int z = z0; z < z1; ++z)
      for (int y = -1; y <= n_[1]; ++y)
        for (int x = -1; x <= n_[0]; ++x) cls[index(x, y, z)] = class_at(flags, x, y, z).kind;
    const int rows = n_[1] * n_[2];
    row_begin_.assign(1, 0);
    for (int r = 0; r < rows; ++r) {
      const int y = r % n_[1], z = r / n_[1];
      int run = -1;
      for (int x = 0; x < n_[0]; ++x) {
        const std::size_t n = index(x, y, z);
        if (cls[n] != K::fluid) {
          if (run >= 0) segs_.push_back({run, x, -1}), run = -1;
          continue;
        }
        ++fluid_;
        BoundaryNode b{n, 0u, -1};
        std::vector<double> coef(Q, 0.0), qv(Q, -1.0);
        bool moving = false, curved = false;
        for (int i = 0; i < Q; ++i) {
          if (cls[n - off_[i]] != K::solid) continue;
          const NodeClass src = class_at(flags, x - L::c[i][0], y - L::c[i][1], z - L::c[i][2]);
          b.bounce |= 1u << i;
          double cu = 0;
          for (int a = 0; a < 3; ++a) cu += L::c[i][a] * src.u[a];
          if (cu != 0) {
            coef[i] = 6.0 * L::w[i] * cu;
            moving = true;
          }
          if (c_.bouzidi && src.id != 0) {
            int g[3] = {x, y, z};
            g[D - 1] += lo_;
            const std::array<double, 3> p{g[0] + 0.5, g[1] + 0.5, D == 3 ? g[2] + 0.5 : 0.0};
            const std::array<double, 3> dir{-1.0 * L::c[i][0], -1.0 * L::c[i][1], -1.0 * L::c[i][2]};
            double q = link_fraction(c_, p, dir);
            // q < 1/2 reads the next node away from the wall: it must be fluid.
            if (q > 0 && q < 0.5 && cls[n + off_[i]] != K::fluid) q = 0.5;
            if (q > 0) {
              qv[i] = q;
              curved = true;
            }
          }
          if (src.id != 0) links_.push_back({n, z * (D == 3 ? 1 : 0) + y * (D == 2 ? 1 : 0), i,
                                             static_cast<int>(bnodes_.size()), src.id});
        }
        if (b.bounce == 0) {
          if (run < 0) run = x;
          continue;
        }
        if (run >= 0) segs_.push_back({run, x, -1}), run = -1;
        if (moving) {
          b.coef = static_cast<int>(coefs_.size());
          coefs_.insert(coefs_.end(), coef.begin(), coef.end());
        }
        if (curved) {
          b.q = static_cast<int>(qs_.size());
          qs_.insert(qs_.end(), qv.begin(), qv.end());
        }
        segs_.push_back({x, x + 1, static_cast<int>(bnodes_.size())});
        bnodes_.push_back(b);
      }
      if (run >= 0) segs_.push_back({run, n_[0], -1});
      row_begin_.push_back(static_cast<int>(segs_.size()));
    }
    // Inlet and outlet ghost nodes; those in an internal halo layer arrive by exchange.
    for (int z = z0; z < z1; ++z)
      for (int y = -1; y <= n_[1]; ++y)
        for (int x = -1; x <= n_[0]; ++x) {
          if (cls[index(x, y, z)] != K::inlet && cls[index(x, y, z)] != K::outlet) continue;
          const NodeClass k = class_at(flags, x, y, z);
          const int s = D == 3 ? z : y;
          if ((s < 0 && lo_ > 0) || (s >= n_[S] && lo_ + n_[S] < global_[S])) continue;
          int p[3] = {x, y, z};
          const int axis = k.face / 2;
          p[axis] += k.face % 2 == 0 ? 1 : -1;
          NeeNode e{index(x, y, z), index(p[0], p[1], p[2]), k.kind == NodeClass::Kind::inlet, false,
                    {k.u[0], k.u[1], k.u[2]}, k.rho};
          e.has_neighbour = cls[e.n] != K::solid;
          nee_.push_back(e);
        }
  }

  void initialise(const InitFunction& init) {
    const int z0 = D == 3 ? -1 : 0, z1 = D == 3 ? n_[2] + 1 : 1;
    for (int z = z0; z < z1; ++z)
      for (int y = -1; y <= n_[1]; ++y)
        for (int x = -1; x <= n_[0]; ++x) {
          double rho = c_.init.rho;
          std::array<double, 3> u = c_.init.u;
          int g[3] = {x, y, z};
          g[D - 1] += lo_;
          bool inside = true;
          for (int a = 0; a < D; ++a) inside = inside && g[a] >= 0 && g[a] < global_[a];
          if (init && inside) init(g[0], g[1], D == 3 ? g[2] : 0, rho, u);
          // Stored populations are post-collision: collide the equilibrium whose Guo
          // velocity (u_pre + F/(2 rho)) is the wanted u.
          Real ur[3];
          const double rho_m = c_.collision.incompressible ? 1.0 : rho;
          for (int a = 0; a < 3; ++a) ur[a] = static_cast<Real>(u[a] - (force_on_ ? 0.5 * c_.force[a] / rho_m : 0.0));
          const std::size_t n = index(x, y, z);
          Real f[Q], o[Q];
          for (int i = 0; i < Q; ++i) f[i] = equilibrium<L, Real>(i, static_cast<Real>(rho - 1), ur, compressible_);
          if (force_on_) {
            if (trt_ && inc_) collide<L, Real, true, true, true>(f, o, par_);
            else if (trt_) collide<L, Real, true, true>(f, o, par_);
            else if (inc_) collide<L, Real, false, true, true>(f, o, par_);
            else collide<L, Real, false, true>(f, o, par_);
          } else {
            std::memcpy(o, f, sizeof f);
          }
          for (int i = 0; i < Q; ++i) a_[i * N_ + n] = o[i];
        }
    finish(a_.data());
    b_ = a_;
  }

  const Case& c_;
  LocalExchange local_;
  SlabExchange* ex_;
  std::array<int, 3> global_{}, n_{}, p_{};
  int lo_ = 0;
  std::size_t N_ = 0, fluid_ = 0;
  std::ptrdiff_t off_[Q]{};
  CollideParams<Real> par_;
  bool force_on_ = false, trt_ = false, inc_ = false;
  Real compressible_ = 1;  // factor of the density in the equilibrium's momentum terms
  std::vector<Real> a_, b_;
  std::vector<Segment> segs_;
  std::vector<int> row_begin_;
  std::vector<BoundaryNode> bnodes_;
  std::vector<double> coefs_, qs_;
  std::vector<ForceLink> links_;
  std::vector<NeeNode> nee_;
  std::vector<int> up_, down_;
  std::vector<Real> send_lo_, send_hi_, recv_lo_, recv_hi_;
  long steps_ = 0;
};

}  // namespace

std::unique_ptr<Solver> make_solver(const SolverSetup& s) {
  if (!s.c || !s.flags) throw bad_input("solver setup lacks a case or flags");
  if (s.c->lattice == LatticeKind::d2q9) {
    if (s.precision == Precision::f64) return std::make_unique<SolverT<D2Q9, double>>(s);
    return std::make_unique<SolverT<D2Q9, float>>(s);
  }
  if (s.precision == Precision::f64) return std::make_unique<SolverT<D3Q19, double>>(s);
  return std::make_unique<SolverT<D3Q19, float>>(s);
}

}  // namespace fest::lbm
