// lbmsim bench: MLUPS of a periodic box next to the copy bandwidth measured in the same
// run (the roofline of a streaming kernel), one JSON line per (threads, precision).
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

#include <omp.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/stopwatch.hpp"
#include "lbm/geometry.hpp"
#include "lbm/solver.hpp"

namespace fest::lbmsim_tool {

using nlohmann::json;

namespace {

using Clock = SteadyClock;

// Copy bandwidth (bytes read + written per second) of `threads` threads over 256 MiB.
double copy_bandwidth(int threads) {
  const std::size_t n = (256u << 20) / sizeof(double);
  std::vector<double> a(n, 1.0), b(n, 0.0);
  double best = 0;
  for (int rep = 0; rep < 4; ++rep) {
    const auto t0 = Clock::now();
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n; ++i) b[i] = a[i];
    const double s = seconds_since(t0);
    best = std::max(best, 2.0 * n * sizeof(double) / s);
    a.swap(b);
  }
  return best;
}

}  // namespace

int bench_command(const BenchOptions& o) {
  const bool d3 = o.lattice == lbm::LatticeKind::d3q19;
  const int size = o.size > 0 ? o.size : (d3 ? 128 : 1024);
  lbm::Case c;
  c.dim = d3 ? 3 : 2;
  c.lattice = d3 ? lbm::LatticeKind::d3q19 : lbm::LatticeKind::d2q9;
  c.size = {size, size, d3 ? size : 1};
  c.collision.tau = 0.6;
  c.collision.model = o.collision;
  const lbm::Flags flags = lbm::shape_flags(c);
  const double cells = static_cast<double>(c.cells());
  const int steps = o.steps > 0 ? o.steps : std::max(5, static_cast<int>(2e8 / cells));
  const int Q = d3 ? 19 : 9;
  for (int threads : o.threads) {
    const double bw = copy_bandwidth(threads);
    for (const lbm::Precision prec : o.precision) {
      omp_set_num_threads(threads);
      lbm::SolverSetup s;
      s.c = &c;
      s.flags = &flags;
      s.precision = prec;
      s.init = [&](int x, int y, int, double& rho, std::array<double, 3>& u) {
        rho = 1.0;
        u = {0.01 * std::sin(0.1 * y), 0.01 * std::cos(0.1 * x), 0.0};
      };
      auto solver = lbm::make_solver(s);
      for (int k = 0; k < 10; ++k) solver->step();
      const auto t0 = Clock::now();
      const std::clock_t c0 = std::clock();
      for (int k = 0; k < steps; ++k) solver->step();
      const double sec = seconds_since(t0);
      // Process CPU time (all threads): the robust figure on a shared, loaded machine.
      const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      const double mlups = cells * steps / sec / 1e6;
      const double real = prec == lbm::Precision::f32 ? 4.0 : 8.0;
      json line = {{"lattice", d3 ? "d3q19" : "d2q9"},
                   {"size", size},
                   {"threads", threads},
                   {"precision", precision_name(prec)},
                   {"collision", o.collision == lbm::CollisionModel::trt ? "trt" : "bgk"},
                   {"steps", steps},
                   {"mlups", mlups},
                   {"cpu_seconds", cpu},
                   {"mlups_per_cpu_second", cpu > 0 ? cells * steps / cpu / 1e6 : 0.0},
                   {"bytes_per_lup", 3 * Q * real},
                   {"gbytes_per_s", mlups * 1e6 * 3 * Q * real / 1e9},
                   {"copy_gbytes_per_s", bw / 1e9},
                   {"roofline_mlups", bw / (2 * Q * real) / 1e6},
                   {"fraction_of_roofline", mlups / (bw / (2 * Q * real) / 1e6)}};
      std::printf("%s\n", line.dump().c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace fest::lbmsim_tool
