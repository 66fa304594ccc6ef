#include "sampling/weight_table.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace fest::sampling {

namespace {

// Maps an input index outside [0, n) back inside; -1 for `zero` (the tap is dropped).
int remap(long i, int n, EdgeMode edge) {
  if (i >= 0 && i < n) return static_cast<int>(i);
  switch (edge) {
    case EdgeMode::clamp:
      return i < 0 ? 0 : n - 1;
    case EdgeMode::wrap:
      return static_cast<int>(((i % n) + n) % n);
    case EdgeMode::reflect: {
      if (n == 1) return 0;
      const long period = 2 * static_cast<long>(n - 1);
      long m = ((i % period) + period) % period;
      if (m >= n) m = period - m;
      return static_cast<int>(m);
    }
    case EdgeMode::zero:
      return -1;
  }
  return -1;
}

}  // namespace

WeightTable make_weight_table(int n_in, int n_out, const Kernel& k, double shift, EdgeMode edge) {
  if (n_in <= 0 || n_out <= 0) throw usage_error("weight table: sizes {} -> {} must be positive", n_in, n_out);
  if (!std::isfinite(shift) || std::fabs(shift) > 1e9) throw usage_error("shift {} is not plausible", shift);
  if (!k.nearest && (!k.spatial || !std::isfinite(k.radius) || k.radius <= 0))
    throw usage_error("kernel '{}' has no finite support: resize cannot use it (yet)", k.name);
  const double scale = static_cast<double>(n_out) / n_in;
  const double stretch = std::max(1.0, 1.0 / scale);
  const double reach = k.radius * stretch;

  WeightTable t;
  t.n_in = n_in;
  t.n_out = n_out;
  t.offset.reserve(static_cast<std::size_t>(n_out) + 1);
  t.offset.push_back(0);
  std::vector<std::pair<long, double>> taps;
  std::vector<std::pair<int, double>> mapped;
  for (int o = 0; o < n_out; ++o) {
    const double u = (o + 0.5) / scale - 0.5 + shift;
    taps.clear();
    if (k.nearest) {
      taps.emplace_back(static_cast<long>(std::floor(u + 0.5)), 1.0);
    } else {
      const long lo = static_cast<long>(std::floor(u - reach)), hi = static_cast<long>(std::ceil(u + reach));
      double sum = 0;
      for (long n = lo; n <= hi; ++n) {
        const double w = k((static_cast<double>(n) - u) / stretch);
        if (w != 0) taps.emplace_back(n, w);
        sum += w;
      }
      // Every catalogue kernel is positive near 0 and the stretched support spans at least
      // one sample, so sum > 0; the guard keeps a pathological kernel from dividing by 0.
      if (!(std::fabs(sum) > 1e-300)) {
        taps.assign(1, {static_cast<long>(std::floor(u + 0.5)), 1.0});
        sum = 1;
      }
      for (auto& tap : taps) tap.second /= sum;
    }
    // Edge handling after normalisation: `zero` then loses the outside weight on purpose.
    mapped.clear();
    for (const auto& [n, w] : taps) {
      const int i = remap(n, n_in, edge);
      // Weights of ~1e-16 (sin(πn) at sinc's zeros) only cost time; dropping them keeps the
      // identity resize an exact copy.
      if (i >= 0 && std::fabs(w) > 1e-12) mapped.emplace_back(i, w);
    }
    // Clamp and reflect send several taps to one sample: merge them in double precision
    // (sorted by index, so the summation order is fixed), then store floats.
    std::sort(mapped.begin(), mapped.end());
    std::size_t kept = 0;
    for (std::size_t j = 0; j < mapped.size(); ++j) {
      if (kept > 0 && mapped[kept - 1].first == mapped[j].first)
        mapped[kept - 1].second += mapped[j].second;
      else
        mapped[kept++] = mapped[j];
    }
    for (std::size_t j = 0; j < kept; ++j) {
      t.index.push_back(mapped[j].first);
      t.weight.push_back(static_cast<float>(mapped[j].second));
    }
    t.offset.push_back(t.index.size());
  }
  return t;
}

}  // namespace fest::sampling
