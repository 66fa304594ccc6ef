#pragma once
// The stage timings of `fluidsim bench` and of the lean bench_fluidsim (the binary that
// is carried to a many-core machine with only FFTW, OpenMP and the C++ runtime beside
// it): one plume scene per (size, solver), stepped at each thread count, every stage's
// mean milliseconds and its speed-up over the first thread count (docs/fluidsim.md §7).

#include <functional>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fluidsim/projection.hpp"

namespace fest::fluidsim {

struct StageBenchOptions {
  std::vector<int> sizes{31, 64};
  std::vector<int> threads{1, 2};
  int steps = 5;
  double nu = 1e-4;
  std::vector<PoissonSolver> poisson{PoissonSolver::fdm, PoissonSolver::fft, PoissonSolver::mg, PoissonSolver::gs};
};

// Calls `line` with one JSON object per (size, solver, threads, stage), as soon as it is
// measured: bench, size, nu, threads, solver, stage, ms, speedup, max_div_rel, setup_ms
// (cpu_ms on the "step" line; an anchor note for gs and jacobi). Sets OpenMP's team size.
void time_stages(const StageBenchOptions& options, const std::function<void(const nlohmann::json&)>& line);

}  // namespace fest::fluidsim
