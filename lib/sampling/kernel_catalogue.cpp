#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sampling/frequency_response.hpp"
#include "sampling/kernel.hpp"
#include "sampling/kernel_formulas.hpp"
#include "sampling/kernel_params.hpp"

namespace fest::sampling {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double infinity = std::numeric_limits<double>::infinity();
// Parameters that set a width are capped so a typo cannot ask for a kernel of millions
// of taps per output pixel.
constexpr double max_width = 64;

// Alias terms summed for the dual prefilter's A_r (the same K as chain1d's default).
constexpr int dual_terms = 2000;

std::string all_names() {
  std::string out;
  for (const auto& n : kernel_names()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

void require_range(std::string_view kernel, const char* key, double v, double lo, double hi) {
  if (!(v > lo && v <= hi))
    throw usage_error("kernel '{}': {} = {} is out of range ({}, {}]", kernel, key, v, lo, hi);
}

void require_no_params(const KernelSpelling& s) {
  if (!s.rest.empty()) throw usage_error("kernel '{}' takes no parameters (got '{}')", s.name, s.rest);
}

// A kernel of the catalogue from its parts; an empty response: frequency_response()
// integrates the spatial form.
Kernel kernel_of(std::string name, double radius, bool interpolating, std::function<double(double)> spatial,
                 std::function<double(double)> response = {}) {
  Kernel k;
  k.name = std::move(name);
  k.radius = radius;
  k.interpolating = interpolating;
  k.spatial = std::move(spatial);
  k.response = std::move(response);
  return k;
}

Kernel box() {
  // Half-open [-0.5, 0.5): at a tie exactly one of two neighbouring samples counts,
  // so an integer box reduction averages whole blocks and nothing else.
  return kernel_of("box", 0.5, true, [](double x) { return (x >= -0.5 && x < 0.5) ? 1.0 : 0.0; },
                   [](double f) { return sinc(f); });
}

Kernel triangle() {
  return kernel_of("triangle", 1, true, [](double x) { return std::max(0.0, 1 - std::fabs(x)); },
                   [](double f) { return std::pow(sinc(f), 2); });  // box ⊗ box
}

Kernel cubic(std::string name, double b, double c) {
  // k(0) = (6 - 2B)/6 and k(1) = B/6: interpolating for B = 0. B = 1, C = 0 is the cubic
  // B-spline β³ = box ⊗ box ⊗ box ⊗ box.
  std::function<double(double)> response;
  if (b == 1 && c == 0) response = [](double f) { return std::pow(sinc(f), 4); };
  return kernel_of(std::move(name), 2, b == 0, [b, c](double x) { return mitchell_netravali(b, c, x); }, response);
}

Kernel gaussian(const KernelSpelling& s) {
  const auto p = parse_kernel_params(s.name, s.rest, {{"sigma", 0.5}});
  const double sigma = p.at("sigma");
  require_range(s.name, "sigma", sigma, 0, max_width / 3);
  // The closed form is the untruncated spot (a CRT display model, docs/resample.md "Display reconstruction"): chain1d treats
  // the display as that ideal Gaussian. The resize kernel is cut at 3σ; its own transform
  // (numerical_response) differs by < 0.005.
  return kernel_of(fmt::format("gaussian:sigma={}", sigma), 3 * sigma, false,
                   [sigma](double x) { return truncated_gaussian(sigma, x); },
                   [sigma](double f) { return std::exp(-2 * pi * pi * sigma * sigma * f * f); });
}

Kernel lanczos_kernel(const KernelSpelling& s, double default_a) {
  const auto p = parse_kernel_params(s.name, s.rest, {{"a", default_a}});
  const double a = p.at("a");
  require_range(s.name, "a", a, 0, max_width / 2);
  return kernel_of(fmt::format("lanczos:a={}", a), a, true, [a](double x) { return lanczos(a, x); });
}

Kernel blackman_harris_kernel(const KernelSpelling& s) {
  const auto p = parse_kernel_params(s.name, s.rest, {{"width", 3}});
  const double w = p.at("width");
  require_range(s.name, "width", w, 0, max_width);
  return kernel_of(fmt::format("blackman-harris:width={}", w), w / 2, false, [w](double x) { return blackman_harris(w, x); });
}

Kernel kaiser_kernel(const KernelSpelling& s) {
  const auto p = parse_kernel_params(s.name, s.rest, {{"a", 3}, {"beta", 6.33}});
  const double a = p.at("a"), beta = p.at("beta");
  require_range(s.name, "a", a, 0, max_width / 2);
  if (!(beta >= 0 && beta <= 700))  // I0(beta) overflows a double beyond ~713
    throw usage_error("kernel '{}': beta = {} is out of range [0, 700]", s.name, beta);
  // A windowed sinc keeps sinc's zeros: interpolating.
  return kernel_of(fmt::format("kaiser:a={},beta={}", a, beta), a, true, [a, beta](double x) { return kaiser(a, beta, x); });
}

Kernel ideal() {
  return kernel_of("sinc", infinity, true, [](double x) { return sinc(x); },
                   [](double f) { return std::fabs(f) < 0.5 ? 1.0 : 0.0; });
}

Kernel point() {
  Kernel k;
  k.name = "point";
  k.radius = 0;
  k.interpolating = true;
  k.nearest = true;
  k.response = [](double) { return 1.0; };  // no prefilter: every frequency passes
  return k;
}

// P_opt = R / A_r with A_r(f) = Σ_k R(f + k)² (docs/resample.md "The 1-D chain and the optimal prefilter"): the L2-optimal prefilter for a
// display whose reconstruction filter is R.
Kernel dual(const KernelSpelling& s) {
  if (s.rest.empty()) throw usage_error("kernel 'dual' needs a reconstruction kernel: dual:box, dual:tent, ...");
  const Kernel r = make_kernel(s.rest);
  if (r.nearest || r.name == "sinc" || r.name.rfind("dual:", 0) == 0)
    throw usage_error("kernel 'dual:{}': the display kernel must be a finite reconstruction filter", s.rest);
  if (r.name == "box") {
    // a_r = δ, so A_r = 1 and the dual of the box is the box itself (docs/resample.md "The 1-D chain and the optimal prefilter"); keeping the
    // spatial form lets resize use it directly.
    Kernel k = box();
    k.name = "dual:box";
    return k;
  }
  Kernel k;
  k.name = "dual:" + r.name;
  k.reconstruction = r.name;
  k.radius = infinity;  // an IIR filter
  k.response = [r](double f) {
    double a = 0;
    for (int i = -dual_terms; i <= dual_terms; ++i) a += std::pow(frequency_response(r, f + i), 2);
    return frequency_response(r, f) / a;
  };
  return k;
}

}  // namespace

std::vector<std::string> kernel_names() {
  return {"point",   "box",      "triangle", "tent",     "gaussian",        "bspline",
          "mitchell", "catrom",  "lanczos",  "lanczos2", "lanczos3",        "blackman-harris",
          "kaiser",  "sinc",     "ideal",    "dual:<kernel>"};
}

Kernel make_kernel(std::string_view spec) {
  const KernelSpelling s = split_kernel_spelling(spec);
  const std::string& n = s.name;
  if (n == "dual") return dual(s);
  if (n == "gaussian") return gaussian(s);
  if (n == "lanczos") return lanczos_kernel(s, 3);
  if (n == "lanczos2" || n == "lanczos3") return lanczos_kernel(s, n == "lanczos2" ? 2 : 3);
  if (n == "blackman-harris") return blackman_harris_kernel(s);
  if (n == "kaiser") return kaiser_kernel(s);
  if (n == "mitchell") {
    const auto p = parse_kernel_params(n, s.rest, {{"b", 1.0 / 3}, {"c", 1.0 / 3}});
    return cubic(fmt::format("mitchell:b={},c={}", p.at("b"), p.at("c")), p.at("b"), p.at("c"));
  }
  require_no_params(s);
  if (n == "point") return point();
  if (n == "box") return box();
  if (n == "triangle" || n == "tent") return triangle();
  if (n == "bspline") return cubic("bspline", 1, 0);
  if (n == "catrom") return cubic("catrom", 0, 0.5);
  if (n == "sinc" || n == "ideal") return ideal();
  throw usage_error("unknown kernel '{}' (known: {})", n, all_names());
}

}  // namespace fest::sampling
