// resample kernel / chain1d / mipkernel: numbers about filters, printed as JSON or CSV.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"
#include "core/file_io.hpp"
#include "sampling/chain1d.hpp"
#include "sampling/frequency_response.hpp"
#include "sampling/kernel_analysis.hpp"
#include "sampling/mip_kernel.hpp"

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

int run_chain1d(const ChainArgs& a) {
  if (!a.edge.empty()) {
    if (a.edge.size() > 2) throw usage_error("--edge takes x0 or x0,x1");
    const auto crossings = with_rewording({{"edge experiment:", "chain1d --edge:"}}, [&] {
      return edge_experiment(a.edge[0], a.edge.size() == 2 ? std::optional<double>(a.edge[1]) : std::nullopt);
    });
    nlohmann::json j{{"experiment", "fig10.2"}, {"prefilter", "box:width=2"}, {"recon", "tent:width=2"},
                     {"threshold", 0.5}, {"edges", a.edge}, {"recovered", crossings}};
    print(j.dump() + "\n");
    return 0;
  }
  const Kernel &p = a.prefilter, &r = a.recon;
  if (r.nearest) throw usage_error("chain1d: the display filter cannot be point sampling");
  nlohmann::json results = nlohmann::json::array();
  for (double f : a.freq) {
    const ChainResult c = analyse_chain(p, r, f, a.terms);
    nlohmann::json aliases = nlohmann::json::array();
    for (int k = -2; k <= 2; ++k)
      if (k != 0) aliases.push_back({{"k", k}, {"freq", f - k}, {"R", frequency_response(r, f - k)},
                                     {"amplitude", c.amplitude_at(k)}});
    results.push_back({{"f", f}, {"P", c.prefilter}, {"A0", c.survived}, {"alias_rms", c.alias_rms}, {"mse", c.mse},
                       {"aliases", aliases}});
  }
  nlohmann::json j{{"prefilter", p.name}, {"recon", r.name}, {"terms", a.terms}, {"results", results}};
  print(j.dump() + "\n");
  return 0;
}

int run_mipkernel(const MipKernelArgs& a) {
  const MipBuild build = a.build;
  if (a.pos.empty()) throw usage_error("mipkernel needs --pos");
  if (a.dims == 1) {
    std::vector<std::vector<double>> w;
    for (double x : a.pos) w.push_back(mip_kernel_1d(a.level, x, build));
    std::string out = "i";
    for (double x : a.pos) out += fmt::format(",w_{}", x);
    out += "\n";
    for (std::size_t i = 0; i < w[0].size(); ++i) {
      bool any = false;
      for (const auto& col : w) any = any || std::fabs(col[i]) > 1e-15;
      if (!any) continue;
      out += fmt::format("{}", i);
      for (const auto& col : w) out += fmt::format(",{:.9g}", col[i]);
      out += "\n";
    }
    print(out);
    return 0;
  }
  if (a.dims != 2) throw usage_error("--dims must be 1 or 2");
  if (a.pos.size() != 2) throw usage_error("mipkernel --dims 2 takes --pos X,Y");
  // Separable: the 2-D lookup is bilinear over four blocks, the product of two 1-D kernels.
  const auto wx = mip_kernel_1d(a.level, a.pos[0], build), wy = mip_kernel_1d(a.level, a.pos[1], build);
  std::string out = "i,j,w\n";
  for (std::size_t j = 0; j < wy.size(); ++j)
    for (std::size_t i = 0; i < wx.size(); ++i)
      if (std::fabs(wx[i] * wy[j]) > 1e-15) out += fmt::format("{},{},{:.9g}\n", i, j, wx[i] * wy[j]);
  print(out);
  return 0;
}

}  // namespace fest::resample_tool
