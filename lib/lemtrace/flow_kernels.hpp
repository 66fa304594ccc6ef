#pragma once
// The closed form of a normal cell in eigen coordinates (docs/lemtrace.md §2) as inline kernels, so
// that the predicted exit (exit_search.cpp) evaluates it without a call, and without the
// math library in the common case: one cell's step is short (|lambda s| <= 0.25 on the
// fast path), where e^x - 1 and sin/cos are short Taylor polynomials whose first omitted
// term is below 1e-17 relative. Larger arguments use expm1 and sincos.

#include <cmath>

#include "lemtrace/cell_field.hpp"

namespace fest::lemtrace {

// phi1(x) = (e^x - 1) / x = sum_k x^k / (k + 1)!  (phi1(0) = 1), for |x| <= 0.25. The degree
// follows |x|: the first omitted term x^{K+1} / (K + 2)! is at most 1.2e-18 (|x| <= 2^-10,
// K = 4), 4.0e-18 (|x| <= 1/16, K = 8) and 9.6e-18 (|x| <= 1/4, K = 11).
inline double phi1_small(double x) {
  const double ax = std::abs(x);
  if (ax <= 0x1p-10) return 1 + x * (1.0 / 2 + x * (1.0 / 6 + x * (1.0 / 24 + x * (1.0 / 120))));
  if (ax <= 0.0625)
    return 1 + x * (1.0 / 2 + x * (1.0 / 6 + x * (1.0 / 24 + x * (1.0 / 120 + x * (1.0 / 720 + x * (1.0 / 5040 +
           x * (1.0 / 40320 + x * (1.0 / 362880))))))));
  return 1 + x * (1.0 / 2 + x * (1.0 / 6 + x * (1.0 / 24 + x * (1.0 / 120 + x * (1.0 / 720 + x * (1.0 / 5040 +
         x * (1.0 / 40320 + x * (1.0 / 362880 + x * (1.0 / 3628800 + x * (1.0 / 39916800 + x * (1.0 / 479001600)))))))))));
}

// phi1 for any x: the polynomial where it holds, else expm1(x) / x.
inline double phi1(double x) { return std::abs(x) <= 0.25 ? phi1_small(x) : std::expm1(x) / x; }

// e^{l s} and psi(l, s) = (e^{l s} - 1) / l = s phi1(l s) (psi(0, s) = s), without
// cancellation for small l s.
inline void exp_and_psi(double l, double s, double& e, double& p) {
  const double x = l * s, f = phi1(x);
  p = s * f;
  e = 1.0 + x * f;
}

// sin and cos of a small angle by their Taylor series (|t| <= 0.5: the first omitted
// term is below 2e-20 relative); one cell's half angle is nearly always this small.
// Larger angles use sincos.
inline void small_sincos(double t, double* sn, double* cs) {
  if (!(std::abs(t) <= 0.5)) {
    *sn = std::sin(t);
    *cs = std::cos(t);
    return;
  }
  const double u = t * t;
  if (u <= 1.0 / 256) {
    // |t| <= 1/16: sin to t^9 and cos to t^10 leave out terms below 1e-19 relative.
    *sn = t * (1 + u * (-1.0 / 6 + u * (1.0 / 120 + u * (-1.0 / 5040 + u * (1.0 / 362880)))));
    *cs = 1 + u * (-0.5 + u * (1.0 / 24 + u * (-1.0 / 720 + u * (1.0 / 40320 + u * (-1.0 / 3628800)))));
    return;
  }
  // Horner in t^2 with the coefficients 1/n! (sin: odd n to 15, cos: even n to 16).
  *sn = t * (1 + u * (-1.0 / 6 + u * (1.0 / 120 + u * (-1.0 / 5040 + u * (1.0 / 362880 + u * (-1.0 / 39916800 +
            u * (1.0 / 6227020800 + u * (-1.0 / 1307674368000))))))));
  *cs = 1 + u * (-0.5 + u * (1.0 / 24 + u * (-1.0 / 720 + u * (1.0 / 40320 + u * (-1.0 / 3628800 +
            u * (1.0 / 479001600 + u * (-1.0 / 87178291200 + u * (1.0 / 20922789888000))))))));
}

// The complex pair's block of the flow over time s:
// (z0, z1) <- e^{a s} R(b s) (z0, z1) + Psi_c (c0, c1), R = [[cs, sn], [-sn, cs]],
// Psi_c = M2^{-1} (e^{a s} R - I), M2^{-1} = [[a, -b], [b, a]] / (a^2 + b^2); one sincos of
// the half angle gives sin, cos and cos - 1 without cancellation for small s.
inline void complex_pair_flow(double a, double b, double s, const double z0[2], const double c[2], double z[2]) {
  double sh, ch;
  small_sincos(0.5 * b * s, &sh, &ch);
  const double sn = 2.0 * sh * ch, cs = 1.0 - 2.0 * sh * sh;
  const double as = a * s, em1 = as * phi1(as);
  const double ea = 1.0 + em1;
  const double d11 = em1 * cs - 2.0 * sh * sh;  // e^{a s} R - I, first row
  const double d12 = ea * sn;
  const double inv_n2 = 1.0 / (a * a + b * b);
  const double p11 = (a * d11 + b * d12) * inv_n2, p12 = (a * d12 - b * d11) * inv_n2;
  z[0] = ea * (cs * z0[0] + sn * z0[1]) + p11 * c[0] + p12 * c[1];
  z[1] = ea * (-sn * z0[0] + cs * z0[1]) - p12 * c[0] + p11 * c[1];
}

// z(s) of a normal record from z(0) = z0 (see eigen_flow in closed_form.hpp).
inline void eigen_flow_inline(const CellRecord& r, const double z0[3], double s, double z[3]) {
  if (r.type == CellType::normal_real) {
    for (int i = 0; i < 3; ++i) {
      double e, p;
      exp_and_psi(r.lam[i], s, e, p);
      z[i] = e * z0[i] + p * r.c[i];
    }
    return;
  }
  complex_pair_flow(r.lam[0], r.lam[1], s, z0, r.c, z);
  double e3, p3;
  exp_and_psi(r.lam[2], s, e3, p3);
  z[2] = e3 * z0[2] + p3 * r.c[2];
}

}  // namespace fest::lemtrace
