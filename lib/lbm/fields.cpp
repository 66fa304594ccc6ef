// Derived fields (docs/lbmsim.md 2.7).
#include "lbm/fields.hpp"

#include <cmath>

#include "core/closest_word.hpp"
#include "core/error.hpp"
#include "lbm/case_json.hpp"

namespace fest::lbm {

const std::vector<std::string>& field_names() {
  static const std::vector<std::string> names{"density",   "velocity",      "pressure",   "speed",
                                              "vorticity", "vorticity_mag", "qcriterion", "flags"};
  return names;
}

void check_field_names(const std::vector<std::string>& names, const std::string& where) {
  for (const std::string& n : names) {
    bool ok = false;
    for (const std::string& k : field_names()) ok = ok || k == n;
    if (ok) continue;
    const std::string hint = closest_word(n, field_names());
    throw bad_input("field \"{}\" is unknown{} ({})", n, hint.empty() ? "" : " (did you mean \"" + hint + "\"?)", where);
  }
}

namespace {

// Velocity gradient g[3*a + b] = d u_a / d x_b at every node.
std::vector<double> velocity_gradient(const Case& c, const Flags& flags, const std::vector<double>& u) {
  const std::size_t N = c.cells();
  std::vector<double> g(9 * N, 0.0);
  const int nx = c.size[0], ny = c.size[1], nz = c.size[2];
  auto fluid_at = [&](int p[3], std::size_t& k) {
    for (int a = 0; a < c.dim; ++a) {
      if (p[a] >= 0 && p[a] < c.size[a]) continue;
      if (!c.periodic(a)) return false;
      p[a] = (p[a] + c.size[a]) % c.size[a];
    }
    k = flags.index(p[0], p[1], p[2]);
    return flags.id[k] == 0;
  };
#pragma omp parallel for schedule(static)
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const std::size_t k0 = flags.index(x, y, z);
        if (flags.id[k0] != 0) continue;
        for (int b = 0; b < c.dim; ++b) {
          int pm[3] = {x, y, z}, pp[3] = {x, y, z};
          pm[b] -= 1;
          pp[b] += 1;
          std::size_t km = 0, kp = 0;
          const bool m = fluid_at(pm, km), p = fluid_at(pp, kp);
          for (int a = 0; a < 3; ++a) {
            double d = 0;
            if (m && p) d = 0.5 * (u[3 * kp + a] - u[3 * km + a]);
            else if (p) d = u[3 * kp + a] - u[3 * k0 + a];
            else if (m) d = u[3 * k0 + a] - u[3 * km + a];
            g[9 * k0 + 3 * a + b] = d;
          }
        }
      }
  return g;
}

}  // namespace

std::vector<Field> derived_fields(const std::vector<std::string>& names, const Case& c, const Flags& flags,
                                  const std::vector<double>& rho, const std::vector<double>& u,
                                  double pressure_scale, double spacing) {
  const std::size_t N = c.cells();
  std::vector<double> grad;
  auto need_grad = [&] {
    if (grad.empty()) {
      grad = velocity_gradient(c, flags, u);
      if (spacing != 1.0)
        for (double& g : grad) g /= spacing;
    }
  };
  std::vector<Field> out;
  for (const std::string& name : field_names()) {
    bool wanted = false;
    for (const std::string& n : names) wanted = wanted || n == name;
    if (!wanted) continue;
    Field f;
    f.name = name;
    if (name == "density") {
      f.values = rho;
    } else if (name == "velocity") {
      f.components = 3;
      f.values = u;
    } else if (name == "pressure") {
      f.values.resize(N);
      for (std::size_t k = 0; k < N; ++k) f.values[k] = flags.id[k] ? 0.0 : (rho[k] - 1.0) / 3.0 * pressure_scale;
    } else if (name == "speed") {
      f.values.resize(N);
      for (std::size_t k = 0; k < N; ++k)
        f.values[k] = std::sqrt(u[3 * k] * u[3 * k] + u[3 * k + 1] * u[3 * k + 1] + u[3 * k + 2] * u[3 * k + 2]);
    } else if (name == "vorticity" || name == "vorticity_mag") {
      need_grad();
      const bool vec = c.dim == 3 && name == "vorticity";
      f.components = vec ? 3 : 1;
      f.values.resize(N * f.components);
      for (std::size_t k = 0; k < N; ++k) {
        const double* G = &grad[9 * k];
        const double w[3] = {G[3 * 2 + 1] - G[3 * 1 + 2], G[3 * 0 + 2] - G[3 * 2 + 0], G[3 * 1 + 0] - G[3 * 0 + 1]};
        if (vec)
          for (int a = 0; a < 3; ++a) f.values[3 * k + a] = w[a];
        else if (name == "vorticity")
          f.values[k] = w[2];
        else
          f.values[k] = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      }
    } else if (name == "qcriterion") {
      need_grad();
      f.values.resize(N);
      for (std::size_t k = 0; k < N; ++k) {
        const double* G = &grad[9 * k];
        double s2 = 0, o2 = 0;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) {
            const double s = 0.5 * (G[3 * a + b] + G[3 * b + a]), o = 0.5 * (G[3 * a + b] - G[3 * b + a]);
            s2 += s * s;
            o2 += o * o;
          }
        f.values[k] = 0.5 * (o2 - s2);
      }
    } else {  // flags
      f.values.resize(N);
      for (std::size_t k = 0; k < N; ++k) f.values[k] = flags.id[k];
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace fest::lbm
