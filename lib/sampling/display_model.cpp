#include "sampling/display_model.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sampling/kernel_params.hpp"

namespace fest::sampling {

double box_gaussian(double sigma, double x) {
  const double s = sigma * std::sqrt(2.0);
  return 0.5 * (std::erf((x + 0.5) / s) - std::erf((x - 0.5) / s));
}

DisplayModel make_display_model(const std::string& spec) {
  const KernelSpelling s = split_kernel_spelling(spec);
  if (s.name == "lcd") {
    if (!s.rest.empty()) throw usage_error("display model 'lcd' takes no parameters");
    const Kernel box = make_kernel("box");
    return {box, box};
  }
  if (s.name == "tent" || s.name == "triangle" || s.name == "bspline" || s.name == "gaussian") {
    const Kernel k = make_kernel(spec);
    return {k, k};
  }
  if (s.name == "crt") {
    const auto p = parse_kernel_params("crt", s.rest, {{"sx", 0.45}, {"sy", 0.35}});
    const double sx = p.at("sx"), sy = p.at("sy");
    if (!(sx > 0 && sx <= 16) || !(sy > 0 && sy <= 16)) throw usage_error("display model 'crt': sx, sy must be in (0, 16]");
    Kernel kx;
    kx.name = fmt::format("crt-x:sx={}", sx);
    kx.radius = 0.5 + 3 * sx;
    kx.spatial = [sx](double x) { return std::fabs(x) < 0.5 + 3 * sx ? box_gaussian(sx, x) : 0.0; };
    // Box ⊗ Gaussian: sinc(f) · exp(−2π²σ²f²).
    kx.response = [sx](double f) {
      const double pf = 3.14159265358979323846 * f;
      return (f == 0 ? 1.0 : std::sin(pf) / pf) * std::exp(-2 * pf * pf * sx * sx);
    };
    return {kx, make_kernel(fmt::format("gaussian:sigma={}", sy))};
  }
  throw usage_error("unknown display model '{}' (lcd, tent, bspline, gaussian:sigma=S, crt[:sx=..,sy=..])", spec);
}

}  // namespace fest::sampling
