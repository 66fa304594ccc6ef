#pragma once
// The Lafortune model as a parameter vector for fitting (docs/brdffit.md §2): the
// layout of the variants, their bounds, the model and its analytic derivatives per
// channel, and the conversion to and from reflectance::LafortuneBrdf.
//
// Layouts (exponents are optimised as log N):
//   per channel (default): for c in RGB: [rho_d, (Cxy, Cz, log N) x K]    -> 3 (1 + 3K)
//   shared lobe:           [rho_d x3, (rho_s x3, Cxy, log N) x K]         -> 3 + 5K
// In the shared variant Cz = 1 and a lobe is rho_s,c max(0, Cxy xy + z)^N, which is a
// Lafortune lobe with Cxy,c = rho_s,c^(1/N) Cxy and Cz,c = rho_s,c^(1/N).

#include <cmath>

#include <Eigen/Core>

#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

struct ModelSpec {
  int lobes = 1;        // K, 1..3
  bool shared = false;  // one lobe shape shared by the channels
  // Upper bound of every lobe's directional albedo (lobe_albedo.hpp), 0 = none. Energy
  // conservation gives 1 for radiance calibrated against a white target (docs/brdffit.md §1); without
  // it the bound scales with the light's unknown intensity.
  double max_lobe_albedo = 1.0;
};

// Bounds of docs/brdffit.md §2.
inline constexpr double kMinExponent = 0.5;
inline constexpr double kMaxExponent = 1e4;
inline constexpr double kMaxCoefficient = 1e3;

int parameter_count(const ModelSpec& spec);

// At most this many parameters influence one channel (the gradient buffers' size).
inline constexpr int kMaxChannelParams = 1 + 3 * 3;

// Projects p onto the bounds (rho >= 0, |C| <= 1e3, 0.5 <= N <= 1e4) and scales down
// every lobe whose directional albedo exceeds spec.max_lobe_albedo until it meets it.
void clamp_to_bounds(const ModelSpec& spec, Eigen::VectorXd& p);

// f_c and its gradient: writes the indices and derivatives of the parameters it depends
// on into idx/grad (at most kMaxChannelParams) and returns how many.
double channel_value(const ModelSpec& spec, const Eigen::VectorXd& p, int c, double xy, double z,
                     int* idx, double* grad, int* n_grad);
double channel_value(const ModelSpec& spec, const Eigen::VectorXd& p, int c, double xy, double z);

// The model with exponents and scales resolved, for evaluating many samples of one
// parameter vector (the distances of clustering): two transcendentals per lobe and channel.
class ModelEvaluator {
 public:
  ModelEvaluator(const ModelSpec& spec, const Eigen::VectorXd& p);
  double value(int c, double xy, double z) const {
    double f = diffuse_[c];
    for (int k = 0; k < lobes_; ++k) {
      const Lobe& l = lobe_[k][c];
      const double base = l.cxy * xy + l.cz * z;
      if (base > 0) f += l.scale * std::exp(l.n * std::log(base));
    }
    return f;
  }
  // The value and its gradient, as channel_value() gives them (same indices and order).
  double value(int c, double xy, double z, int* idx, double* grad, int* n_grad) const {
    int g = 0;
    double f = diffuse_[c];
    idx[g] = index_rho_[c];
    grad[g++] = 1 / M_PI;
    for (int k = 0; k < lobes_; ++k) {
      const Lobe& l = lobe_[k][c];
      const double base = l.cxy * xy + l.cz * z;
      double term = 0, d_base = 0, d_logn = 0;
      if (base > 0) {
        const double log_b = std::log(base);
        term = std::exp(l.n * log_b);
        d_base = l.n * term / base;
        d_logn = term * log_b * l.n;
      }
      f += l.scale * term;
      if (l.index_scale >= 0) {  // shared: rho_s, Cxy, log N
        idx[g] = l.index_scale;
        grad[g++] = term;
        idx[g] = l.index_cxy;
        grad[g++] = l.scale * d_base * xy;
      } else {
        idx[g] = l.index_cxy;
        grad[g++] = d_base * xy;
        idx[g] = l.index_cz;
        grad[g++] = d_base * z;
      }
      idx[g] = l.index_logn;
      grad[g++] = l.scale * d_logn;
    }
    *n_grad = g;
    return f;
  }

 private:
  struct Lobe {
    double cxy = 0, cz = 0, n = 1, scale = 0;
    int index_cxy = -1, index_cz = -1, index_logn = -1, index_scale = -1;
  };
  double diffuse_[3] = {0, 0, 0};
  int index_rho_[3] = {0, 0, 0};
  Lobe lobe_[3][3];
  int lobes_ = 0;
};

reflectance::LafortuneBrdf to_brdf(const ModelSpec& spec, const Eigen::VectorXd& p);
// The inverse of to_brdf for the default layout; for the shared layout the lobes of b
// must have the shape it produces (Cz > 0 and Cxy/Cz and N equal across channels): the
// first channel's ratio and exponent are taken.
Eigen::VectorXd from_brdf(const ModelSpec& spec, const reflectance::LafortuneBrdf& b);

}  // namespace fest::brdffit
