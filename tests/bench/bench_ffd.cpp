// ffd's speed targets (docs/ffd.md): 1 M points deformed by a 4^3 and an 8^3 Bernstein
// lattice and a 16^3 B-spline lattice, with --threads 1 and 2. The anchor measured in the
// same run is the plain Sederberg-Parry sum sum_ijk B_i B_j B_k P_ijk written directly
// (std::pow and binomials per term, single thread), i.e. what a straightforward port of
// PyGeM's loop does; its result also checks ours (max difference printed).
//
//   bench_ffd [POINTS]      one JSON line per case

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#include "ffd/lattice.hpp"

namespace {

using namespace fest::ffd;
using Clock = std::chrono::steady_clock;

// Process CPU time (all threads): on a loaded shared machine wall time mostly measures
// the neighbours; cpu / threads is the wall time on an idle machine.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

double binom(int n, int k) { return std::tgamma(n + 1.0) / (std::tgamma(k + 1.0) * std::tgamma(n - k + 1.0)); }

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? static_cast<std::size_t>(std::atol(argv[1])) : 1000000;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 0.05);
  std::vector<Eigen::Vector3d> pts(n);
  for (auto& p : pts) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
  struct Case { Basis b; int d; };
  for (const Case c : {Case{Basis::bernstein, 4}, Case{Basis::bernstein, 8}, Case{Basis::bspline, 16}}) {
    Lattice l;
    l.dims = {c.d, c.d, c.d};
    l.basis.fill(c.b);
    l.displacement.resize(l.size());
    for (auto& d : l.displacement) d = Eigen::Vector3d(g(rng), g(rng), g(rng));
    const Deformer def(l);
    for (const int threads : {1, 2}) {
      std::vector<Eigen::Vector3d> out = pts;
      const auto t0 = Clock::now();
      const double c0 = cpu_ms();
      apply_all(def, out, Outside::none, threads);
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      const double cpu = cpu_ms() - c0;
      double anchor_ms = -1, max_diff = -1;
      if (c.b == Basis::bernstein && threads == 1) {
        // The plain S&P sum on the first 10k points (scaled to n for the figure).
        const std::size_t m = std::min<std::size_t>(n, 10000);
        const int deg = c.d - 1;
        const auto a0 = Clock::now();
        max_diff = 0;
        for (std::size_t p = 0; p < m; ++p) {
          const Eigen::Vector3d& x = pts[p];
          Eigen::Vector3d s = Eigen::Vector3d::Zero();
          for (int i = 0; i <= deg; ++i)
            for (int j = 0; j <= deg; ++j)
              for (int k = 0; k <= deg; ++k) {
                const double w = binom(deg, i) * std::pow(x[0], i) * std::pow(1 - x[0], deg - i) * binom(deg, j) *
                                 std::pow(x[1], j) * std::pow(1 - x[1], deg - j) * binom(deg, k) * std::pow(x[2], k) *
                                 std::pow(1 - x[2], deg - k);
                s += w * (l.rest_point(i, j, k) + l.displacement[l.index(i, j, k)]);
              }
          max_diff = std::max(max_diff, (s - out[p]).norm());
        }
        anchor_ms = std::chrono::duration<double, std::milli>(Clock::now() - a0).count() * static_cast<double>(n) / static_cast<double>(m);
      }
      std::printf("{\"case\":\"%s_%d\",\"points\":%zu,\"threads\":%d,\"ms\":%.1f,\"cpu_ms\":%.1f,\"plain_sum_ms\":%.1f,\"max_diff_vs_plain_sum\":%.3g}\n",
                  basis_name(c.b), c.d, n, threads, ms, cpu, anchor_ms, max_diff);
      std::fflush(stdout);
    }
  }
  return 0;
}
