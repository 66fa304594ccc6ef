#pragma once
// One node's collision (docs/lbmsim.md 2.2-2.3): moments with the Guo half-force shift,
// the second-order equilibrium, BGK or TRT relaxation, and the Guo forcing term split
// into its symmetric and antisymmetric parts.
//
// Populations are stored shifted, g_i = f_i - w_i (the deviation from the fluid at rest
// with rho = 1): every operation is linear in f, so the scheme is the same, but the
// small deviations keep their digits in single precision (docs/lbmsim.md 2.9).

#include "lbm/lattice.hpp"

namespace fest::lbm {

template <class Real>
struct CollideParams {
  Real omega_p = 1, omega_m = 1;  // omega+ (sets nu) and omega- (TRT; = omega+ for BGK)
  Real force[3] = {0, 0, 0};      // body force density
};

// Density deviation rho - 1 and velocity of shifted populations g (u includes F/2 when
// FORCE). INC: the incompressible model of He & Luo (1997), u = j/rho0 with rho0 = 1.
template <class L, class Real, bool FORCE, bool INC = false>
inline void node_moments(const Real* f, const CollideParams<Real>& p, Real& drho, Real u[3]) {
  Real r = 0, jx = 0, jy = 0, jz = 0;
#pragma GCC unroll 32
  for (int i = 0; i < L::Q; ++i) {
    r += f[i];
    jx += static_cast<Real>(L::c[i][0]) * f[i];
    jy += static_cast<Real>(L::c[i][1]) * f[i];
    if constexpr (L::D == 3) jz += static_cast<Real>(L::c[i][2]) * f[i];
  }
  if constexpr (FORCE) {
    jx += Real(0.5) * p.force[0];
    jy += Real(0.5) * p.force[1];
    jz += Real(0.5) * p.force[2];
  }
  const Real inv = INC ? Real(1) : Real(1) / (Real(1) + r);
  drho = r;
  u[0] = jx * inv;
  u[1] = jy * inv;
  u[2] = jz * inv;
}

// Shifted equilibrium f_i^eq - w_i, with f_i^eq = w_i rho [1 + 3 c.u + 9/2 (c.u)^2 - 3/2 u^2]
// and rho = 1 + drho; with compressible = 0 the incompressible form of He & Luo (1997),
// f_i^eq = w_i [rho + rho0 (3 c.u + 9/2 (c.u)^2 - 3/2 u^2)], rho0 = 1.
template <class L, class Real>
inline Real equilibrium(int i, Real drho, const Real u[3], Real compressible = 1) {
  const Real cu = static_cast<Real>(L::c[i][0]) * u[0] + static_cast<Real>(L::c[i][1]) * u[1] +
                  static_cast<Real>(L::c[i][2]) * u[2];
  const Real usq = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  return static_cast<Real>(L::w[i]) *
         (drho + (Real(1) + compressible * drho) * (Real(3) * cu + Real(4.5) * cu * cu - Real(1.5) * usq));
}

// Collides f (pre-collision, Q values) into out. INC: the incompressible equilibrium
// (He & Luo 1997), a compile-time choice so that the standard kernel is untouched.
template <class L, class Real, bool TRT, bool FORCE, bool INC = false>
inline void collide(const Real* f, Real* out, const CollideParams<Real>& p) {
  Real drho, u[3];
  node_moments<L, Real, FORCE, INC>(f, p, drho, u);
  const Real rho = INC ? Real(1) : Real(1) + drho;  // the density of the momentum terms
  const Real usq15 = Real(1.5) * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  Real uF = 0;
  if constexpr (FORCE) uF = u[0] * p.force[0] + u[1] * p.force[1] + u[2] * p.force[2];
  const Real wp = p.omega_p, wm = p.omega_m;
#pragma GCC unroll 32
  for (int i = 0; i < L::Q; ++i) {
    const Real cx = static_cast<Real>(L::c[i][0]), cy = static_cast<Real>(L::c[i][1]),
               cz = static_cast<Real>(L::c[i][2]);
    const Real w = static_cast<Real>(L::w[i]);
    const Real cu = Real(3) * (cx * u[0] + cy * u[1] + cz * u[2]);
    // Symmetric and antisymmetric parts of the (shifted) equilibrium.
    const Real eqp = w * (drho + rho * (Real(0.5) * cu * cu - usq15));
    const Real eqm = w * rho * cu;
    Real Fp = 0, Fm = 0;
    if constexpr (FORCE) {
      const Real cF = cx * p.force[0] + cy * p.force[1] + cz * p.force[2];
      Fp = w * (Real(3) * cu * cF - Real(3) * uF);  // w [9 (c.u)(c.F) - 3 u.F]
      Fm = w * Real(3) * cF;
    }
    if constexpr (TRT) {
      const int o = L::opp[i];
      const Real fp = Real(0.5) * (f[i] + f[o]), fm = Real(0.5) * (f[i] - f[o]);
      Real r = f[i] - wp * (fp - eqp) - wm * (fm - eqm);
      if constexpr (FORCE) r += (Real(1) - Real(0.5) * wp) * Fp + (Real(1) - Real(0.5) * wm) * Fm;
      out[i] = r;
    } else {
      Real r = f[i] - wp * (f[i] - (eqp + eqm));
      if constexpr (FORCE) r += (Real(1) - Real(0.5) * wp) * (Fp + Fm);
      out[i] = r;
    }
  }
}

}  // namespace fest::lbm
