#include "sampling/kernel_formulas.hpp"

#include <cmath>

namespace fest::sampling {

namespace {
constexpr double pi = 3.14159265358979323846;
}

double sinc(double x) {
  if (x == 0.0) return 1.0;
  const double px = pi * x;
  return std::sin(px) / px;
}

double mitchell_netravali(double b, double c, double x) {
  const double t = std::fabs(x);
  if (t < 1.0)
    return ((12 - 9 * b - 6 * c) * t * t * t + (-18 + 12 * b + 6 * c) * t * t + (6 - 2 * b)) / 6;
  if (t < 2.0)
    return ((-b - 6 * c) * t * t * t + (6 * b + 30 * c) * t * t + (-12 * b - 48 * c) * t +
            (8 * b + 24 * c)) /
           6;
  return 0.0;
}

double lanczos(double a, double x) {
  if (std::fabs(x) >= a) return 0.0;
  return sinc(x) * sinc(x / a);
}

double blackman_harris(double width, double x) {
  if (std::fabs(x) >= width / 2) return 0.0;
  // The textbook window runs over n/N in [0, 1]; centring it (n/N = x/w + 1/2) flips the
  // signs of the odd cosine terms, which makes every term positive here.
  const double p = 2 * pi * x / width;
  return 0.35875 + 0.48829 * std::cos(p) + 0.14128 * std::cos(2 * p) + 0.01168 * std::cos(3 * p);
}

double kaiser(double a, double beta, double x) {
  const double t = std::fabs(x) / a;
  if (t >= 1.0) return 0.0;
  return sinc(x) * std::cyl_bessel_i(0.0, beta * std::sqrt(1 - t * t)) / std::cyl_bessel_i(0.0, beta);
}

double truncated_gaussian(double sigma, double x) {
  if (std::fabs(x) >= 3 * sigma) return 0.0;
  return std::exp(-x * x / (2 * sigma * sigma));
}

}  // namespace fest::sampling
