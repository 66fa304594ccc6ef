#include "sampling/chain1d.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "sampling/frequency_response.hpp"

namespace fest::sampling {

ChainResult analyse_chain(const Kernel& prefilter, const Kernel& display, double f, int terms) {
  if (!std::isfinite(f)) throw usage_error("chain1d: frequency {} is not finite", f);
  if (terms < 1 || terms > 10'000'000) throw usage_error("chain1d: {} alias terms is out of range [1, 1e7]", terms);
  ChainResult out;
  out.frequency = f;
  out.terms = terms;
  out.prefilter = frequency_response(prefilter, f);
  out.amplitude.resize(static_cast<std::size_t>(2 * terms + 1));
  double alias_power = 0;
  // Summed from the outside in, so the small tail terms are added before the large ones.
  for (int m = terms; m >= 1; --m) {
    for (int k : {-m, m}) {
      const double a = out.prefilter * frequency_response(display, f - k);
      out.amplitude[static_cast<std::size_t>(k + terms)] = a;
      alias_power += a * a;
    }
  }
  out.survived = out.prefilter * frequency_response(display, f);
  out.amplitude[static_cast<std::size_t>(terms)] = out.survived;
  out.alias_rms = std::sqrt(alias_power);
  out.mse = (1 - out.survived) * (1 - out.survived) + alias_power;
  return out;
}

namespace {

// (s ⊗ box₂)(x) for s = indicator of [a, b]: half the length of [x-1, x+1] ∩ [a, b].
double box2_of_interval(double x, double a, double b) {
  return std::max(0.0, std::min(x + 1, b) - std::max(x - 1, a)) / 2;
}

}  // namespace

std::vector<double> edge_experiment(double x0, std::optional<double> x1) {
  if (!std::isfinite(x0) || (x1 && (!std::isfinite(*x1) || *x1 <= x0)))
    throw usage_error("edge experiment: need finite x0 < x1");
  if (std::fabs(x0) > 1e6 || (x1 && std::fabs(*x1) > 1e6))
    throw usage_error("edge experiment: positions beyond ±1e6 are not plausible");
  // A step is a bar whose far end lies beyond every sample that the box can reach.
  const double last = x1 ? *x1 : x0 + 4;
  const double a = x0, b = x1 ? *x1 : last + 8;
  const long first_n = static_cast<long>(std::floor(x0)) - 2;
  const long last_n = static_cast<long>(std::ceil(last)) + 2;
  std::vector<double> crossings;
  double prev = box2_of_interval(static_cast<double>(first_n), a, b);
  for (long n = first_n + 1; n <= last_n; ++n) {
    const double cur = box2_of_interval(static_cast<double>(n), a, b);
    // Linear interpolation between samples n-1 and n crosses 0.5 once if they straddle it.
    if ((prev < 0.5) != (cur < 0.5))
      crossings.push_back(static_cast<double>(n - 1) + (0.5 - prev) / (cur - prev));
    prev = cur;
  }
  return crossings;
}

}  // namespace fest::sampling
