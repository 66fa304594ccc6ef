#include "lemtrace/exit_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "lemtrace/flow_kernels.hpp"

namespace fest::lemtrace {
namespace {

constexpr double kDetect = 1e-12;   // beta below -kDetect counts as outside
constexpr double kValid = 1e-10;    // tolerance of the validation of an exit

struct Sample {
  double tau;
  Eigen::Vector4d beta;
  Eigen::Vector4d rate;  // d beta / d tau
  Vec3 x, v;
};

template <class Geo>
Sample sample(const Geo& g, const CellPath& path, double tau, int& evals) {
  Sample s;
  s.tau = tau;
  path.eval(tau, s.x, s.v);
  s.beta = g.bary(s.x);
  s.rate = g.bary_rate(s.v);
  ++evals;
  return s;
}

// At tau = 0 the closed form is the entry point itself.
template <class Geo>
Sample entry_sample(const Geo& g, const CellPath& path, const EntryValues* known) {
  Sample s;
  s.tau = 0;
  s.x = path.entry();
  s.beta = known ? known->beta : g.bary(s.x);
  if constexpr (std::is_same_v<Geo, TetGeometry>) s.v = path.entry_velocity(known ? known->field : g.interpolate(s.beta));
  else s.v = path.entry_velocity(known ? known->field : path.entry_field());
  s.rate = g.bary_rate(s.v);
  return s;
}

// Root of beta_k in [lo, hi] with beta_k(lo) >= 0 > beta_k(hi) = fhi: safeguarded
// Newton from the secant point. Returns the sample at the root (its position is the
// closed form at the returned time, so the exit point needs no further evaluation).
// First guess for the root of beta_k in [a, b]: the root of the cubic Hermite
// interpolant of beta_k and its rate at both ends (a few Newton steps on the cubic, no
// evaluation of the path), which for the gently curved paths inside one cell is close
// enough that one or two Newton steps on the path finish the job. Falls back to the
// secant point when the cubic misbehaves.
double hermite_guess(const Sample& a, const Sample& b, int k) {
  const double h = b.tau - a.tau;
  const double f0 = a.beta[k], f1 = b.beta[k], d0 = a.rate[k] * h, d1 = b.rate[k] * h;
  double u = f0 / (f0 - f1);  // secant, in [0, 1]
  const double secant = u;
  for (int it = 0; it < 8; ++it) {
    const double u2 = u * u, u3 = u2 * u;
    const double p = (2 * u3 - 3 * u2 + 1) * f0 + (u3 - 2 * u2 + u) * d0 + (-2 * u3 + 3 * u2) * f1 + (u3 - u2) * d1;
    const double dp = (6 * u2 - 6 * u) * f0 + (3 * u2 - 4 * u + 1) * d0 + (-6 * u2 + 6 * u) * f1 + (3 * u2 - 2 * u) * d1;
    if (dp == 0) break;
    u -= p / dp;
    if (!(u > 0 && u < 1)) return a.tau + secant * h;
  }
  return a.tau + u * h;
}

template <class Geo>
Sample refine_root(const Geo& g, const CellPath& path, int k, const Sample& left, const Sample& right,
                   double tol, int& evals) {
  double lo = left.tau, hi = right.tau, flo = left.beta[k], fhi = right.beta[k];
  bool hermite = true;
  if (flo <= kDetect) {
    hermite = false;
    // The bracket starts on the face (the entry face, or a face the path touches): a
    // path that enters and curves back out within the bracket is positive in between.
    // Look for that positive stretch towards lo before calling the exit immediate.
    bool found = false;
    for (int j = 1; j <= 50 && !found; ++j) {
      const double m = lo + (hi - lo) * std::ldexp(1.0, -j);
      const Sample s = sample(g, path, m, evals);
      const double fm = s.beta[k];
      if (fm > kDetect) {
        lo = m;
        flo = fm;
        found = true;
      } else if (fm < -kDetect) {
        hi = m;
        fhi = fm;
      }
    }
    if (!found) return sample(g, path, lo, evals);
  }
  double tau = hermite ? hermite_guess(left, right, k) : lo + (hi - lo) * flo / (flo - fhi);
  Sample s;
  for (int it = 0; it < 60; ++it) {
    s = sample(g, path, tau, evals);
    const double f = s.beta[k], df = s.rate[k];
    // |beta| at round-off: the point is on the face to within 1e-15 of the cell size.
    if (std::abs(f) <= 1e-15) return s;
    if (f > 0) lo = tau;
    else hi = tau;
    double next = df != 0 ? tau - f / df : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = std::abs(next - tau);
    tau = next;
    if (step < tol || hi - lo < tol) break;
  }
  return sample(g, path, tau, evals);
}

// A path can cross a face and come back within one sampling step (it grazes the face):
// beta_k is positive at both ends but its rate turns from negative to positive. Find the
// minimum of beta_k there (bisection on the rate); if it is negative, the step is cut at
// that point so that the caller sees the crossing.
template <class Geo>
void dip_below(const Geo& g, const CellPath& path, const Sample& prev, Sample& cur, int& evals) {
  // Rates at round-off of the cell's (a path in a face's plane) cannot take beta_k
  // below -kDetect within a step: no search for them.
  const double tiny = 1e-13 * g.v_max / g.h_min;
  for (int k = 0; k < 4; ++k) {
    if (!(prev.rate[k] < -tiny && cur.rate[k] > tiny && cur.beta[k] >= -kDetect)) continue;
    double a = prev.tau, b = cur.tau;
    const double width = b - a;
    for (int it = 0; it < 40 && b - a > 1e-6 * width; ++it) {
      const double m = 0.5 * (a + b);
      Sample s = sample(g, path, m, evals);
      if (s.beta[k] < -kDetect) {
        cur = s;
        return;
      }
      if (s.rate[k] < 0) a = m;
      else b = m;
    }
  }
}

// A search that ends inside the cell (stalled or trapped) at the sample `at`.
ExitResult ended(ExitResult::Kind kind, const Sample& at, int evals) {
  ExitResult r;
  r.kind = kind;
  r.tau = at.tau;
  r.x = at.x;
  r.evaluations = evals;
  return r;
}

template <class Geo>
ExitResult finish(const Geo& g, const Sample& at, int face, int evals) {
  ExitResult r;
  r.kind = ExitResult::exit;
  r.tau = at.tau;
  r.face = face;
  r.evaluations = evals;
  Eigen::Vector4d beta = at.beta;  // every sample holds g.bary(at.x)
  // Snap onto the face: beta_face = 0, the others clamped at 0 and renormalised.
  beta[face] = 0;
  for (int k = 0; k < 4; ++k) beta[k] = std::max(beta[k], 0.0);
  const double sum = beta.sum();
  if (sum > 0) beta /= sum;
  r.beta = beta;
  r.x = g.point(beta);
  return r;
}

template <class Geo>
bool validates(const Geo& g, const CellPath& path, double tau, int& evals) {
  for (double f : {0.25, 0.5, 0.75, 1.0}) {
    ++evals;
    if (g.bary(path.position(f * tau)).minCoeff() < -kValid) return false;
  }
  return true;
}

// Smallest root tau > 0 of c + r tau + q tau^2 / 2 (infinity if none), in the form that
// does not cancel.
double quadratic_root(double c, double r, double q) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (q == 0) return r < 0 && c >= 0 ? -c / r : inf;
  const double disc = r * r - 2 * q * c;
  if (disc < 0) return inf;
  const double s = -(r + std::copysign(std::sqrt(disc), r));
  const double t1 = s / q, t2 = s != 0 ? 2 * c / s : inf;
  double best = inf;
  if (t1 > 0) best = std::min(best, t1);
  if (t2 > 0) best = std::min(best, t2);
  return best;
}

// Predicted exit (the fast path of the bracket search). Inside a cell the field is
// linear, so every time derivative of the path at the entry is a product with A, which
// the precomputed eigen form applies without a transcendental function: beta_k(tau) is
// predicted by its Taylor cubic, whose first root is a guess at the exit good to about
// (rate tau)^3 / 24 of tau. ONE closed-form evaluation there gives beta_k and its first
// two derivatives, a Halley correction delta, and the exit point by the Taylor
// polynomial x + v delta + a delta^2 / 2, whose error |x'''| |delta|^3 / 6 must be below
// round-off of the cell size (else one more evaluation at the corrected time). The
// result is kept only under the bracket search's own safety rules (a step shorter than
// 0.25 / rate, no other face below zero, no face whose rate turned from negative to
// positive); otherwise the caller falls back to the bracket search.
template <class Geo>
bool predicted_exit(const Geo& g, const CellPath& path, const Sample& entry, double cap, int& evals,
                    ExitResult& out) {
  Vec3 a0, j0;
  path.apply_A2(entry.v, a0, j0);
  const Eigen::Vector4d q = g.bary_rate(a0), jr = g.bary_rate(j0);
  const double speed = entry.v.norm(), jerk = j0.norm();
  const double tiny = 1e-13 * g.v_max / g.h_min;  // a rate of beta at round-off
  double tau = std::numeric_limits<double>::infinity();
  int face = -1;
  for (int k = 0; k < 4; ++k) {
    const double c = entry.beta[k], r = entry.rate[k];
    // On a face (entry face, edge, vertex) the path must clearly move inwards, or move
    // within the face's plane (a path in a grid plane: beta_k and its first three
    // derivatives vanish; the check at the end rejects it if it leaves after all).
    if (c <= 1e-9 && std::abs(r) <= tiny && std::abs(q[k]) * g.h_min <= tiny * speed &&
        std::abs(jr[k]) * g.h_min * g.h_min <= tiny * speed * speed)
      continue;
    if (c <= 1e-9 && !(r * g.h_min > 1e-6 * speed)) return false;
    // A face the path moves away from with non-negative curvature has no positive
    // root of its Taylor quadratic: skip it without a square root.
    if (r >= 0 && q[k] >= 0) continue;
    const double t = quadratic_root(c, r, q[k]);
    if (t < tau) {
      tau = t;
      face = k;
    }
  }
  if (face < 0) return false;
  {
    // Two Newton steps on the Taylor cubic of the chosen face; kept while positive.
    const int k = face;
    const double c = entry.beta[k], r = entry.rate[k];
    for (int it = 0; it < 2; ++it) {
      const double f = c + tau * (r + tau * (0.5 * q[k] + tau * jr[k] / 6));
      const double df = r + tau * (q[k] + 0.5 * tau * jr[k]);
      if (df == 0) break;
      const double next = tau - f / df;
      if (!(next > 0)) break;
      tau = next;
    }
  }
  if (face < 0 || !(tau < cap)) return false;
  for (int it = 0; it < 3; ++it) {
    Sample s;
    Vec3 a;
    s.tau = tau;
    path.eval(tau, s.x, s.v, a);
    s.beta = g.bary(s.x);
    s.rate = g.bary_rate(s.v);
    ++evals;
    if (!s.x.allFinite()) return false;
    const double f = s.beta[face], df = s.rate[face], d2f = g.bary_rate(a)[face];
    if (!(df < 0)) return false;
    double delta = -f / df;
    delta = -f / (df + 0.5 * d2f * delta);
    const double next = tau + delta;
    if (!(next > 0 && next < cap)) return false;
    // |x'''| along a step shorter than 0.25 / rate stays within a small factor of its
    // value at the entry (j0); 2 |j0| bounds it without one more product with A.
    const double err = 2 * jerk * std::abs(delta * delta * delta) / 6;
    if (err > 1e-15 * g.h_min || std::abs(delta) > 1e-3 * tau) {
      tau = next;
      continue;
    }
    Sample e;
    e.tau = next;
    e.x = s.x + delta * (s.v + 0.5 * delta * a);
    e.beta = g.bary(e.x);
    const Eigen::Vector4d& beta = e.beta;
    const Eigen::Vector4d rate = g.bary_rate(s.v + delta * a);
    for (int k = 0; k < 4; ++k) {
      if (k == face) continue;
      if (beta[k] < -kDetect) return false;                // an earlier exit elsewhere
      if (entry.rate[k] < -tiny && rate[k] > tiny) return false;  // a face grazed in between
    }
    out = finish(g, e, face, evals);
    return true;
  }
  return false;
}

template <class Geo>
ExitResult find_exit_in(const Geo& g, const CellPath& path, const ExitParams& params, const EntryValues* entry) {
  int evals = 0;
  const double tauT = g.transit_time();
  const double rate = path.rate();
  if (!std::isfinite(tauT)) {
    ExitResult r;
    r.kind = ExitResult::stalled;
    return r;
  }
  const double tol = params.eps_newton * tauT;

  if (params.paper_newton) {
    const Sample s0 = sample(g, path, 0, evals);
    double best = std::numeric_limits<double>::infinity();
    int best_face = -1;
    for (int k = 0; k < 4; ++k) {
      if (s0.beta[k] <= kDetect && s0.rate[k] >= 0) continue;  // entry face
      double tau = 0, f = s0.beta[k], df = s0.rate[k];
      bool converged = false;
      for (int it = 0; it < 30 && df != 0; ++it) {
        const double step = -f / df;
        tau += step;
        if (std::abs(step) < tol) {
          converged = true;
          break;
        }
        Sample s = sample(g, path, tau, evals);
        f = s.beta[k];
        df = s.rate[k];
      }
      if (converged && tau > 0 && tau < best && validates(g, path, tau, evals)) {
        best = tau;
        best_face = k;
      }
    }
    if (best_face >= 0) return finish(g, sample(g, path, best, evals), best_face, evals);
  }

  // Bracket search. The first step is a little beyond the exit of the straight ray
  // x0 + tau v0 (where a nearly straight path leaves), the later ones double; no step is
  // longer than 0.25/rate, over which the path turns by at most about 0.25 rad, so a
  // face cannot be crossed three times inside one step.
  Sample prev = entry_sample(g, path, entry);
  for (int k = 0; k < 4; ++k) prev.beta[k] = std::max(prev.beta[k], 0.0);
  const double delta_cap = rate > 0 ? 0.25 / rate : std::numeric_limits<double>::infinity();
  if (params.predict) {
    ExitResult fast;
    if (predicted_exit(g, path, prev, std::min(delta_cap, 64 * tauT), evals, fast)) return fast;
  }
  double ray = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k)
    if (prev.rate[k] < 0) ray = std::min(ray, prev.beta[k] / -prev.rate[k]);
  double delta = std::isfinite(ray) && ray > 1e-3 * tauT ? 1.1 * ray : tauT / 4;
  delta = std::min(delta, delta_cap);
  for (int j = 1; j <= params.max_samples; ++j) {
    Sample cur = sample(g, path, prev.tau + delta, evals);
    if (!cur.x.allFinite()) break;
    dip_below(g, path, prev, cur, evals);
    if (cur.beta.minCoeff() < -kDetect) {
      Sample best;
      best.tau = std::numeric_limits<double>::infinity();
      int best_face = -1;
      for (int k = 0; k < 4; ++k) {
        if (cur.beta[k] >= -kDetect) continue;
        const Sample root = refine_root(g, path, k, prev, cur, tol, evals);
        if (root.tau < best.tau) {
          best = root;
          best_face = k;
        }
      }
      return finish(g, best, best_face, evals);
    }
    // A path that has come to rest (a sink inside the cell) is trapped.
    if (cur.v.norm() <= 1e-12 * g.v_max) return ended(ExitResult::stalled, cur, evals);
    prev = cur;
    delta = std::min(2 * delta, std::max(delta, delta_cap));
  }
  return ended(ExitResult::trapped, prev, evals);
}

}  // namespace

double UnitGeometry::transit_time() const {
  return v_max > 0 ? h_min / v_max : std::numeric_limits<double>::infinity();
}

namespace {

// The four barycentric rates S4 a and S4 b of two eigen-space vectors at once, S4 =
// [-(column sums of S_u); S_u] (beta_0' = -sum): each row of S_u times the pair, one
// vector per SSE2 lane (Array2d), so that the row-major record needs no transpose.
inline void rates2(const double* S, const double a[3], const double b[3], double ra[4], double rb[4]) {
  using Pair = Eigen::Array2d;
  const Pair x(a[0], b[0]), y(a[1], b[1]), z(a[2], b[2]);
  const Pair r1 = S[0] * x + S[1] * y + S[2] * z;
  const Pair r2 = S[3] * x + S[4] * y + S[5] * z;
  const Pair r3 = S[6] * x + S[7] * y + S[8] * z;
  const Pair r0 = -(r1 + r2 + r3);
  ra[0] = r0[0], ra[1] = r1[0], ra[2] = r2[0], ra[3] = r3[0];
  rb[0] = r0[1], rb[1] = r1[1], rb[2] = r2[1], rb[3] = r3[1];
}

}  // namespace

// The predicted exit in eigen coordinates, written out for one crossing per call: dir
// Lambda is folded into one 2x2 block and a scalar (the real case has zeros off the
// diagonal, so both types run the same straight-line code); the barycentric rates of
// two eigen-space vectors are computed together (rates2: one per SSE2 lane); the step
// bound 0.25 / rate is compared squared; the face quadratics take one square root and
// one division each in the form that does not cancel; and the closed form is the inline
// polynomial kernel (|lambda s| <= 0.25 here, so no exp, expm1 or sin/cos).
bool predicted_exit_local(const CellRecord& rec, const Eigen::Vector4d& beta_in, double dir, ExitResult& out) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double* S = rec.S;
  const double* Si = rec.Sinv;
  const double tauT = rec.tau_bary;
  if (!(tauT > 0) || !(tauT < inf)) return false;
  const bool complex_pair = rec.type == CellType::normal_complex;
  const double l0 = dir * rec.lam[0], l1 = dir * rec.lam[1], l2 = dir * rec.lam[2];
  // M = dir Lambda = [[m00, m01, 0], [m10, m11, 0], [0, 0, l2]].
  const double m00 = l0, m01 = complex_pair ? l1 : 0.0, m10 = complex_pair ? -l1 : 0.0, m11 = complex_pair ? l0 : l1;
  // rate^2 of the bracket search (|alpha + i beta|^2 for the pair).
  const double rate2 = complex_pair ? std::max(l0 * l0 + l1 * l1, l2 * l2) : std::max({l0 * l0, l1 * l1, l2 * l2});
  const double dc0 = dir * rec.c[0], dc1 = dir * rec.c[1], dc2 = dir * rec.c[2];
  const double b1 = beta_in[1], b2 = beta_in[2], b3 = beta_in[3];
  // Entry in eigen coordinates and the path's first three derivatives there.
  const double z0[3] = {Si[0] * b1 + Si[1] * b2 + Si[2] * b3, Si[3] * b1 + Si[4] * b2 + Si[5] * b3,
                        Si[6] * b1 + Si[7] * b2 + Si[8] * b3};
  const double w1[3] = {m00 * z0[0] + m01 * z0[1] + dc0, m10 * z0[0] + m11 * z0[1] + dc1, l2 * z0[2] + dc2};
  const double w2[3] = {m00 * w1[0] + m01 * w1[1], m10 * w1[0] + m11 * w1[1], l2 * w1[2]};
  const double w3[3] = {m00 * w2[0] + m01 * w2[1], m10 * w2[0] + m11 * w2[1], l2 * w2[2]};
  // Barycentric rates of all four faces: r = S4 w1 and q = S4 w2 (two lanes), and the
  // third derivatives jr = S4 w3.
  double r[4], q[4], jr[4];
  rates2(S, w1, w2, r, q);
  jr[1] = S[0] * w3[0] + S[1] * w3[1] + S[2] * w3[2];
  jr[2] = S[3] * w3[0] + S[4] * w3[1] + S[5] * w3[2];
  jr[3] = S[6] * w3[0] + S[7] * w3[1] + S[8] * w3[2];
  jr[0] = -(jr[1] + jr[2] + jr[3]);
  const double speed2 = r[1] * r[1] + r[2] * r[2] + r[3] * r[3];
  const double tiny = 1e-13 / tauT;  // a rate of beta at round-off (UnitGeometry: h = 1)
  double c[4];
  for (int k = 0; k < 4; ++k) c[k] = std::max(beta_in[k], 0.0);
  // On a face (the entry face, an edge, a vertex) the path must clearly move inwards, or
  // move within the face's plane (no hop of the edge/vertex rule pending; the general
  // search decides those). A face in whose plane the path moves has no exit.
  bool in_plane[4] = {false, false, false, false};
  for (int k = 0; k < 4; ++k) {
    if (!(c[k] <= 1e-9)) continue;
    const double speed = std::sqrt(speed2), rk = r[k];
    if (rk < -1e-12 * speed) return false;
    if (std::abs(rk) <= tiny && std::abs(q[k]) <= tiny * speed && std::abs(jr[k]) <= tiny * speed2) {
      in_plane[k] = true;
      continue;
    }
    if (!(rk > 1e-6 * speed)) return false;
  }
  // First positive root of each face's Taylor quadratic c + r t + q t^2 / 2 (c >= 0): a face
  // the path moves away from with non-negative curvature has none; an approaching face
  // (r < 0) has 2 c / (sqrt(disc) - r) if disc >= 0; a receding face that curves back
  // (r >= 0 > q) has (r + sqrt(disc)) / -q (disc >= r^2 there).
  double tau = inf;
  int face = -1;
  for (int k = 0; k < 4; ++k) {
    const double ck = c[k], rk = r[k], qk = q[k];
    if (in_plane[k] || (rk >= 0 && qk >= 0)) continue;
    const double disc = rk * rk - 2 * qk * ck;
    double t;
    if (rk < 0) {
      if (disc < 0) continue;
      t = 2 * ck / (std::sqrt(disc) - rk);
    } else {
      t = (rk + std::sqrt(disc)) / -qk;
    }
    if (t < tau) {
      tau = t;
      face = k;
    }
  }
  if (face < 0) return false;
  {
    // One Newton step on the Taylor cubic of the chosen face, kept if positive (a second
    // one changed neither the evaluations per cell nor the exits: the Halley correction
    // after the evaluation absorbs what it would have moved).
    const double cf = c[face], rf = r[face], qf = q[face], jf = jr[face];
    const double f = cf + tau * (rf + tau * (0.5 * qf + tau * jf * (1.0 / 6)));
    const double df = rf + tau * (qf + 0.5 * tau * jf);
    if (df != 0) {
      const double next = tau - f / df;
      if (next > 0) tau = next;
    }
  }
  // The bracket search's step bound, 0.25 / rate (compared squared), and its horizon 64 tau_T.
  const double horizon = 64 * tauT;
  auto within_cap = [&](double t) { return t < horizon && t * t * rate2 < 0.0625; };
  if (!within_cap(tau)) return false;
  // Row k of S4: a row of S_u, or minus the column sums for beta_0.
  auto row_of = [S](int k, double out3[3]) {
    if (k > 0) {
      out3[0] = S[3 * k - 3], out3[1] = S[3 * k - 2], out3[2] = S[3 * k - 1];
    } else {
      out3[0] = -(S[0] + S[3] + S[6]), out3[1] = -(S[1] + S[4] + S[7]), out3[2] = -(S[2] + S[5] + S[8]);
    }
  };
  // The chosen face's row (beta_0 has the constant 1 besides, `off`).
  double row[3];
  row_of(face, row);
  const double off = face == 0 ? 1.0 : 0.0;
  const double jerk2 = jr[1] * jr[1] + jr[2] * jr[2] + jr[3] * jr[3];
  // A lower bound of beta_k over [0, T] (T within the step bound): the minimum of its
  // Taylor quadratic there less the bound of the cubic remainder, |D3| T^3 / 6, where D3,
  // the third derivative of beta_k at time t, is row_k . e^{Mt} w3 (M commutes with its
  // exponential). e^{Mt} scales the 2x2 block (rotation times e^{alpha t}, or two real
  // factors) and the third component by at most e^{rate t} <= e^{0.25} < 1.2841, so
  // Cauchy-Schwarz on the block and on the third component bounds |D3|.
  auto graze_bound = [&](int k, double T) {
    const double ck = c[k], rk = r[k], qk = q[k];
    double low = std::min(ck, ck + T * (rk + 0.5 * T * qk));
    if (qk > 0 && -rk < qk * T) low = std::min(low, ck - rk * rk / (2 * qk));
    double rk4[3];
    row_of(k, rk4);
    const double block = std::sqrt((rk4[0] * rk4[0] + rk4[1] * rk4[1]) * (w3[0] * w3[0] + w3[1] * w3[1]));
    const double d3 = 1.2841 * (block + std::abs(rk4[2] * w3[2]));
    return low - d3 * T * T * T / 6;
  };
  for (int it = 0; it < 3; ++it) {
    double z[3];
    eigen_flow_inline(rec, z0, dir * tau, z);
    const double dz[3] = {m00 * z[0] + m01 * z[1] + dc0, m10 * z[0] + m11 * z[1] + dc1, l2 * z[2] + dc2};
    const double d2z[3] = {m00 * dz[0] + m01 * dz[1], m10 * dz[0] + m11 * dz[1], l2 * dz[2]};
    const double f = off + row[0] * z[0] + row[1] * z[1] + row[2] * z[2];
    const double df = row[0] * dz[0] + row[1] * dz[1] + row[2] * dz[2];
    const double d2f = row[0] * d2z[0] + row[1] * d2z[1] + row[2] * d2z[2];
    if (!std::isfinite(f) || !(df < 0)) return false;
    // Halley: -f / (df - d2f f / (2 df)), written with one division.
    const double delta = -f * df / (df * df - 0.5 * d2f * f);
    const double next = tau + delta;
    if (!(next > 0) || !within_cap(next)) return false;
    // The third derivative along the step stays within a small factor of its entry
    // value: 2 |jerk| bounds the Taylor step's error, 2 |jerk| |delta|^3 / 6 <= 1e-15
    // (compared squared).
    const double d3 = delta * delta * delta;
    if (jerk2 * d3 * d3 > 9e-30 || std::abs(delta) > 1e-3 * tau) {
      tau = next;
      continue;
    }
    double ze[3], we[3];
    for (int i = 0; i < 3; ++i) {
      ze[i] = z[i] + delta * (dz[i] + 0.5 * delta * d2z[i]);
      we[i] = dz[i] + delta * d2z[i];
    }
    double beta[4], rate_e[4];
    rates2(S, ze, we, beta, rate_e);
    beta[0] += 1.0;
    for (int k = 0; k < 4; ++k) {
      if (k == face) continue;
      if (beta[k] < -kDetect) return false;  // an earlier exit elsewhere
      // A face approached at the entry and left behind at the exit was grazed in
      // between: kept only where a lower bound proves that the path stayed in front of it.
      if (r[k] < -tiny && rate_e[k] > tiny && !(graze_bound(k, next) >= 0)) return false;
    }
    // Snap onto the face as finish() does.
    beta[face] = 0;
    double sum = 0;
    for (int k = 0; k < 4; ++k) sum += (beta[k] = std::max(beta[k], 0.0));
    const double inv = sum > 0 ? 1.0 / sum : 1.0;
    out.kind = ExitResult::exit;
    out.tau = next;
    out.face = face;
    out.evaluations = it + 1;
    for (int k = 0; k < 4; ++k) out.beta[k] = beta[k] * inv;
    out.x = Vec3(out.beta[1], out.beta[2], out.beta[3]);
    return true;
  }
  return false;
}

ExitResult find_exit(const TetGeometry& g, const CellPath& path, const ExitParams& params,
                     const EntryValues* entry) {
  return find_exit_in(g, path, params, entry);
}

ExitResult find_exit(const UnitGeometry& g, const CellPath& path, const ExitParams& params,
                     const EntryValues* entry) {
  return find_exit_in(g, path, params, entry);
}

}  // namespace fest::lemtrace
