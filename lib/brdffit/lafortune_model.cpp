#include "brdffit/lafortune_model.hpp"

#include <algorithm>
#include <cmath>

#include "brdffit/lobe_albedo.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

namespace {

int per_channel(const ModelSpec& s) { return 1 + 3 * s.lobes; }

void check(const ModelSpec& s) {
  if (s.lobes < 1 || s.lobes > 3) throw usage_error("Lafortune lobe count {} is outside 1..3", s.lobes);
}

double clampd(double x, double lo, double hi) { return std::min(hi, std::max(lo, x)); }

// pow(B, N) with its derivatives by B-linear coefficients and by log N (docs/brdffit.md §3): zero where
// the base is not positive (the max(0, .) clamp).
struct LobeTerm {
  double value = 0, d_base = 0, d_logn = 0;
};
LobeTerm lobe_term(double base, double log_n) {
  LobeTerm t;
  if (!(base > 0)) return t;
  const double n = std::exp(log_n);
  const double log_b = std::log(base);
  t.value = std::exp(n * log_b);
  t.d_base = n * t.value / base;
  t.d_logn = t.value * log_b * n;
  return t;
}

// log of the factor (<= 1) by which the lobe's albedo must shrink to meet the bound: 0
// when it does (in logs: a runaway lobe's factor, 1.3^-10000, underflows). A lobe's
// albedo is at most max(|Cxy|, |Cz|)^N 2 pi / (N + 1) (its integral without the cosine),
// which spares the quadrature for the lobes of ordinary fits.
double log_albedo_excess(double cxy, double cz, double n, double bound) {
  if (!(bound > 0)) return 0;
  const double m = std::max(std::abs(cxy), std::abs(cz));
  const double log_bound = std::log(bound);
  if (!(m > 0) || n * std::log(m) + std::log(2 * M_PI / (n + 1)) <= log_bound) return 0;
  return std::min(0.0, log_bound - lobe_log_max_albedo(cxy, cz, n));
}

}  // namespace

int parameter_count(const ModelSpec& s) {
  check(s);
  return s.shared ? 3 + 5 * s.lobes : 3 * per_channel(s);
}

void clamp_to_bounds(const ModelSpec& s, Eigen::VectorXd& p) {
  const double lo = std::log(kMinExponent), hi = std::log(kMaxExponent);
  if (!s.shared) {
    const int m = per_channel(s);
    for (int c = 0; c < 3; ++c) {
      double* q = p.data() + c * m;
      q[0] = std::max(0.0, q[0]);
      for (int k = 0; k < s.lobes; ++k) {
        q[1 + 3 * k] = clampd(q[1 + 3 * k], -kMaxCoefficient, kMaxCoefficient);
        q[2 + 3 * k] = clampd(q[2 + 3 * k], -kMaxCoefficient, kMaxCoefficient);
        q[3 + 3 * k] = clampd(q[3 + 3 * k], lo, hi);
        // Physically plausible lobes only. Without this bound a lobe that is zero at every
        // sample but huge where nothing was sampled (e.g. Cz = 1.3, N = 10^4: a spike of
        // 1.3^10000 at light = view = normal) costs the fit nothing and wrecks every
        // rendering from an unsampled direction. The lobe is homogeneous of degree N in
        // (Cxy, Cz), so scaling both by excess^(1/N) brings its albedo onto the bound.
        const double n = std::exp(q[3 + 3 * k]);
        const double excess = log_albedo_excess(q[1 + 3 * k], q[2 + 3 * k], n, s.max_lobe_albedo);
        if (excess < 0) {
          const double scale = std::exp(excess / n);
          q[1 + 3 * k] *= scale;
          q[2 + 3 * k] *= scale;
        }
      }
    }
    return;
  }
  for (int c = 0; c < 3; ++c) p[c] = std::max(0.0, p[c]);
  for (int k = 0; k < s.lobes; ++k) {
    double* q = p.data() + 3 + 5 * k;
    for (int c = 0; c < 3; ++c) q[c] = clampd(q[c], 0.0, kMaxCoefficient);
    q[3] = clampd(q[3], -kMaxCoefficient, kMaxCoefficient);
    q[4] = clampd(q[4], lo, hi);
    // The lobe of channel c is rho_s,c max(0, Cxy xy + z)^N: its albedo is rho_s,c times
    // that of the unit-scale lobe, so the bound caps rho_s,c.
    const double largest = std::max({q[0], q[1], q[2]});
    if (largest > 0 && s.max_lobe_albedo > 0) {
      const double excess = log_albedo_excess(q[3], 1.0, std::exp(q[4]), s.max_lobe_albedo / largest);
      for (int c = 0; c < 3; ++c) q[c] = std::min(q[c], largest * std::exp(excess));
    }
  }
}

double channel_value(const ModelSpec& s, const Eigen::VectorXd& p, int c, double xy, double z, int* idx,
                     double* grad, int* n_grad) {
  int g = 0;
  double f;
  if (!s.shared) {
    const int base_index = c * per_channel(s);
    const double* q = p.data() + base_index;
    f = q[0] / M_PI;
    idx[g] = base_index;
    grad[g++] = 1 / M_PI;
    for (int k = 0; k < s.lobes; ++k) {
      const LobeTerm t = lobe_term(q[1 + 3 * k] * xy + q[2 + 3 * k] * z, q[3 + 3 * k]);
      f += t.value;
      idx[g] = base_index + 1 + 3 * k;
      grad[g++] = t.d_base * xy;
      idx[g] = base_index + 2 + 3 * k;
      grad[g++] = t.d_base * z;
      idx[g] = base_index + 3 + 3 * k;
      grad[g++] = t.d_logn;
    }
  } else {
    f = p[c] / M_PI;
    idx[g] = c;
    grad[g++] = 1 / M_PI;
    for (int k = 0; k < s.lobes; ++k) {
      const int o = 3 + 5 * k;
      const double rho_s = p[o + c];
      const LobeTerm t = lobe_term(p[o + 3] * xy + z, p[o + 4]);
      f += rho_s * t.value;
      idx[g] = o + c;
      grad[g++] = t.value;
      idx[g] = o + 3;
      grad[g++] = rho_s * t.d_base * xy;
      idx[g] = o + 4;
      grad[g++] = rho_s * t.d_logn;
    }
  }
  *n_grad = g;
  return f;
}

double channel_value(const ModelSpec& s, const Eigen::VectorXd& p, int c, double xy, double z) {
  int idx[kMaxChannelParams];
  double grad[kMaxChannelParams];
  int n = 0;
  return channel_value(s, p, c, xy, z, idx, grad, &n);
}

ModelEvaluator::ModelEvaluator(const ModelSpec& s, const Eigen::VectorXd& p) {
  lobes_ = s.lobes;
  const int m = per_channel(s);
  for (int c = 0; c < 3; ++c) {
    index_rho_[c] = s.shared ? c : c * m;
    diffuse_[c] = p[index_rho_[c]] / M_PI;
    for (int k = 0; k < s.lobes; ++k) {
      Lobe& l = lobe_[k][c];
      if (!s.shared) {
        const int o = c * m + 1 + 3 * k;
        l = {p[o], p[o + 1], std::exp(p[o + 2]), 1.0, o, o + 1, o + 2, -1};
      } else {
        const int o = 3 + 5 * k;
        l = {p[o + 3], 1.0, std::exp(p[o + 4]), p[o + c], o + 3, -1, o + 4, o + c};
      }
    }
  }
}

reflectance::LafortuneBrdf to_brdf(const ModelSpec& s, const Eigen::VectorXd& p) {
  check(s);
  reflectance::LafortuneBrdf b;
  b.lobes.resize(static_cast<std::size_t>(s.lobes));
  if (!s.shared) {
    const int m = per_channel(s);
    for (int c = 0; c < 3; ++c) {
      b.rho_d[c] = p[c * m];
      for (int k = 0; k < s.lobes; ++k) {
        b.lobes[k].cxy[c] = p[c * m + 1 + 3 * k];
        b.lobes[k].cz[c] = p[c * m + 2 + 3 * k];
        b.lobes[k].n[c] = std::exp(p[c * m + 3 + 3 * k]);
      }
    }
    return b;
  }
  for (int c = 0; c < 3; ++c) b.rho_d[c] = p[c];
  for (int k = 0; k < s.lobes; ++k) {
    const int o = 3 + 5 * k;
    const double n = std::exp(p[o + 4]);
    for (int c = 0; c < 3; ++c) {
      const double scale = std::pow(std::max(0.0, p[o + c]), 1 / n);
      b.lobes[k].cxy[c] = scale * p[o + 3];
      b.lobes[k].cz[c] = scale;
      b.lobes[k].n[c] = n;
    }
  }
  return b;
}

Eigen::VectorXd from_brdf(const ModelSpec& s, const reflectance::LafortuneBrdf& b) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(parameter_count(s));
  const auto lobes = std::min<std::size_t>(b.lobes.size(), static_cast<std::size_t>(s.lobes));
  if (!s.shared) {
    const int m = per_channel(s);
    for (int c = 0; c < 3; ++c) {
      p[c * m] = b.rho_d[c];
      for (int k = 0; k < s.lobes; ++k) {
        const bool have = static_cast<std::size_t>(k) < lobes;
        p[c * m + 1 + 3 * k] = have ? b.lobes[k].cxy[c] : 0;
        p[c * m + 2 + 3 * k] = have ? b.lobes[k].cz[c] : 0;
        p[c * m + 3 + 3 * k] = std::log(have ? b.lobes[k].n[c] : 1.0);
      }
    }
    return p;
  }
  for (int c = 0; c < 3; ++c) p[c] = b.rho_d[c];
  for (int k = 0; k < s.lobes; ++k) {
    const int o = 3 + 5 * k;
    if (static_cast<std::size_t>(k) >= lobes) continue;
    const reflectance::LafortuneLobe& l = b.lobes[k];
    const double n = l.n[0];
    for (int c = 0; c < 3; ++c) p[o + c] = l.cz[c] > 0 ? std::pow(l.cz[c], n) : 0;
    p[o + 3] = l.cz[0] != 0 ? l.cxy[0] / l.cz[0] : 0;
    p[o + 4] = std::log(n);
  }
  return p;
}

}  // namespace fest::brdffit
