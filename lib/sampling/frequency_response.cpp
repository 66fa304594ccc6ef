#include "sampling/frequency_response.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::sampling {

double frequency_response(const Kernel& k, double f) {
  if (k.response) return k.response(f);
  return numerical_response(k, f);
}

double numerical_response(const Kernel& k, double f, double step) {
  if (!k.spatial || !std::isfinite(k.radius) || k.radius <= 0)
    throw usage_error("kernel '{}' has no finite spatial form to integrate", k.name);
  // An even number of intervals that puts ±radius on nodes: kernels that jump at their
  // edge (kaiser) then lose nothing to a half-covered interval.
  long n = static_cast<long>(std::ceil(2 * k.radius / step));
  if (n % 2) ++n;
  const double h = 2 * k.radius / static_cast<double>(n);
  const double w = 2 * 3.14159265358979323846 * f;
  double area = 0, transform = 0;  // kernels are even: the sine part vanishes
  for (long i = 0; i <= n; ++i) {
    const double x = -k.radius + static_cast<double>(i) * h;
    const double simpson = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double v = simpson * k.spatial(x);
    area += v;
    transform += v * std::cos(w * x);
  }
  return transform / area;
}

}  // namespace fest::sampling
