#include "fluidsim/advection.hpp"

#include <omp.h>

namespace fest::fluidsim {

namespace {

// Velocity in index units per second at a position.
std::array<double, 3> velocity_at(const Layout& L, const Velocity& vel, const std::array<double, 3>& p) noexcept {
  const Corners c = corners(L, p);
  std::array<double, 3> v{0, 0, 0};
  for (int a = 0; a < L.dim; ++a) v[a] = c.apply(vel[a]) / L.h;
  return v;
}

}  // namespace

std::array<double, 3> trace_back(const Layout& L, const Velocity& vel, int i, int j, int k, double dt,
                                 int substeps) noexcept {
  std::array<double, 3> x{double(i), double(j), double(k)};
  const double h = -dt / substeps;  // backwards in time
  for (int s = 0; s < substeps; ++s) {
    auto at = [&](const std::array<double, 3>& k1, double f) {
      std::array<double, 3> p = x;
      for (int a = 0; a < 3; ++a) p[a] += f * h * k1[a];
      return p;
    };
    const auto k1 = velocity_at(L, vel, x);
    const auto k2 = velocity_at(L, vel, at(k1, 0.5));
    const auto k3 = velocity_at(L, vel, at(k2, 0.5));
    const auto k4 = velocity_at(L, vel, at(k3, 1.0));
    for (int a = 0; a < 3; ++a) x[a] += h / 6.0 * (k1[a] + 2.0 * k2[a] + 2.0 * k3[a] + k4[a]);
    x = confine(L, x);
  }
  return x;
}

void advect(const Layout& L, const Velocity& vel, double dt, int substeps, const std::vector<const Field*>& in,
            const std::vector<Field*>& out) {
  const std::size_t nf = in.size();
  const int rows = L.size[1] * L.size[2];
  // About four chunks per thread, as the seed found necessary for saturation.
  const int chunk = std::max(1, rows / (4 * omp_get_max_threads()));
#pragma omp parallel for schedule(dynamic, chunk) if (L.count() >= kParallelNodes)
  for (int r = 0; r < rows; ++r) {
    const int j = r % L.size[1], k = r / L.size[1];
    for (int i = 0; i < L.size[0]; ++i) {
      const Corners c = corners(L, trace_back(L, vel, i, j, k, dt, substeps));
      const std::size_t n = L.index(i, j, k);
      for (std::size_t f = 0; f < nf; ++f) (*out[f])[n] = c.apply(*in[f]);
    }
  }
}

}  // namespace fest::fluidsim
