// resample kernel: a kernel's frequency and step response, printed as JSON or CSV.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "sampling/frequency_response.hpp"
#include "sampling/kernel_analysis.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

namespace {

void print(const std::string& text) { write_output("-", text); }

std::string csv_of(const Curve& c, const char* xname, const char* yname) {
  std::string out = fmt::format("{},{}\n", xname, yname);
  for (std::size_t i = 0; i < c.x.size(); ++i) out += fmt::format("{:.6f},{:.9g}\n", c.x[i], c.y[i]);
  return out;
}

// S(x) = ∫_{-r}^{x} k / ∫k, tabulated at the kernel curve's points.
Curve step_curve(const Kernel& k) {
  Curve c = kernel_curve(k, 401);
  Curve s;
  double run = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    if (i > 0) {
      // Fine trapezoids between the tabulated points, so that jumps are resolved.
      const int sub = 200;
      const double h = (c.x[i] - c.x[i - 1]) / sub;
      for (int j = 0; j < sub; ++j) run += 0.5 * h * (k.spatial(c.x[i - 1] + j * h) + k.spatial(c.x[i - 1] + (j + 1) * h));
    }
    s.x.push_back(c.x[i]);
    s.y.push_back(run);
  }
  for (auto& v : s.y) v /= run;
  return s;
}

}  // namespace

int run_kernel(const KernelArgs& a) {
  const Kernel& k = a.filter;
  if (a.csv) {
    if (a.response) return print(csv_of(response_curve(k), "f", "K")), 0;
    if (a.step) return print(csv_of(step_curve(k), "x", "S")), 0;
    return print(csv_of(kernel_curve(k), "x", "k")), 0;
  }
  const KernelAnalysis r = analyse_kernel(k);
  nlohmann::json j{{"filter", k.name}};
  if (k.nearest) {
    j["note"] = "point sampling has no prefilter: every frequency passes";
  } else {
    j["radius"] = std::isfinite(k.radius) ? nlohmann::json(k.radius) : nlohmann::json(nullptr);
    j["K_0.25"] = r.k_quarter;
    j["K_0.5"] = r.k_half;
    j["stop_max"] = r.stop_max;
    if (r.has_spatial) {
      j["overshoot"] = r.overshoot;
      j["undershoot"] = r.undershoot;
    }
    if (a.response) {
      const Curve c = response_curve(k, 2.0, 81);
      j["response"] = {{"f", c.x}, {"K", c.y}};
    }
    if (a.step && r.has_spatial) {
      const Curve c = step_curve(k);
      j["step"] = {{"x", c.x}, {"S", c.y}};
    }
  }
  print(j.dump() + "\n");
  return 0;
}

}  // namespace fest::resample_tool
