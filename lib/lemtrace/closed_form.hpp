#pragma once
// The path through one cell in closed form (docs/lemtrace.md §2): x(tau) from the entry point x0.
//
// normal_real:    z_i(s) = e^{lambda_i s} z_i(0) + psi(lambda_i, s) c_i,  x = S z
// normal_complex: (z1, z2)(s) = e^{alpha s} R(beta s) z(0) + M2^{-1}(e^{alpha s} R(beta s) - I) c
// parallel:       x(s) = x0 + d u(s),  u(s) = s(x0) psi(mu, s)   (ray with exact timing)
// extraordinary:  [x(s); 1] = exp(s [[A, b], [0, 0]]) [x0; 1]      (Pade scaling-and-squaring)
// with s = dir * tau (dir = -1 traces backward) and psi(lambda, s) = expm1(lambda s)/lambda.

#include "lemtrace/cell_field.hpp"

namespace fest::lemtrace {

// (e^{lambda s} - 1) / lambda, accurate for small lambda s and equal to s at lambda = 0.
double psi(double lambda, double s);

// The closed form of a normal cell in eigen coordinates: z(s) from z(0) = z0 (s = dir tau),
// with no change of basis (the caller applies S when it needs a position).
void eigen_flow(const CellRecord& record, const double z0[3], double s, double z[3]);

class CellPath {
 public:
  CellPath(const CellRecord& record, const Vec3& x0, double dir);
  // Position at time tau after entry, and the velocity dx/dtau there.
  void eval(double tau, Vec3& x, Vec3& v) const;
  // The same and the acceleration a = dir A v there (normal cells: from the eigen-space
  // derivative eval has at hand, one product with S instead of apply_A's two).
  void eval(double tau, Vec3& x, Vec3& v, Vec3& a) const;
  Vec3 position(double tau) const {
    Vec3 x, v;
    eval(tau, x, v);
    return x;
  }
  const Vec3& entry() const noexcept { return x0_; }
  // dx/dtau at the entry from the interpolated field there (parallel cells move along d).
  Vec3 entry_velocity(const Vec3& field) const;
  // The cell's linear field at the entry, A x0 + b, from the eigen form (normal cells:
  // S (Lambda z0 + c), no vertex data needed).
  Vec3 entry_field() const;
  // Largest rate of the cell's dynamics (1/time): bounds the sampling step.
  double rate() const;
  // The derivative along the path of a quantity w that moves with the flow's linear
  // part: dir * A w. Applied to the velocity it gives the acceleration (x'' = dir A x'),
  // applied twice the jerk. Uses the precomputed eigen form, no transcendental function.
  Vec3 apply_A(const Vec3& w) const;
  // A w and A A w (dir included in each application) with one change of basis.
  void apply_A2(const Vec3& w, Vec3& Aw, Vec3& AAw) const;

 private:
  // Position, velocity and, when `a` is given, acceleration at time tau.
  void eval_impl(double tau, Vec3& x, Vec3& v, Vec3* a) const;

  const CellRecord& rec_;
  Vec3 x0_;
  Vec3 z0_;       // S^{-1} x0 (normal cells)
  double s0_ = 0; // parallel: speed at x0
  double dir_;
};

}  // namespace fest::lemtrace
