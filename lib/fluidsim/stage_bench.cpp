#include "fluidsim/stage_bench.hpp"

#include <ctime>
#include <map>
#include <string>

#include <omp.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/stopwatch.hpp"
#include "fluidsim/simulator.hpp"

namespace fest::fluidsim {

using nlohmann::json;

void time_stages(const StageBenchOptions& o, const std::function<void(const nlohmann::json&)>& emit) {
  using Clock = SteadyClock;
  // (size, solver, stage) -> ms at the first thread count, for the speed-ups.
  std::map<std::string, double> base;
  for (int n : o.sizes)
    for (const PoissonSolver solver : o.poisson) {
      const std::string solver_name = poisson_name(solver);
      SimOptions so;
      so.projection.solver = solver;
      if (solver == PoissonSolver::gs) so.stam03 = true;  // Stam 2003 semantics: 20 Gauss-Seidel sweeps
      so.projection.iters = solver == PoissonSolver::jacobi ? 40 : 20;
      so.projection.tol = 1e-8;
      for (int t : o.threads) {
        omp_set_num_threads(t);
        Scene sc;
        sc.dims = {n, n, n};
        sc.viscosity = o.nu;
        Source src;
        src.shape = Source::Shape::sphere;
        src.centre = {0.5 * (n + 1), 0.5 * (n + 1), 0.2 * (n + 1)};
        src.radius = 0.1 * n;
        src.rate = 10.0;
        src.jet = true;
        src.velocity = {0, 0, 0.5};
        add_plume(sc, src);
        const auto t_setup = Clock::now();
        const Simulator sim(sc, so);
        const double setup_ms = ms_since(t_setup);
        State st = sim.initial_state();
        sim.step(st, 0.04);  // warm-up (diffusion bases are built on first use)
        std::map<std::string, double> ms;
        double max_div_rel = 0.0;
        const State before = st;
        // Process CPU time as well as wall time: on a shared, loaded machine the CPU time
        // of a 1-thread run is the figure that does not depend on the other processes.
        auto cpu_now = [] {
          timespec ts{};
          clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
          return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
        };
        double cpu_ms = 0.0;
        for (int k = 0; k < o.steps; ++k) {
          const double c0 = cpu_now();
          const auto t0 = Clock::now();
          const StepStats ss = sim.step(st, 0.04);
          ms["step"] += ms_since(t0);
          cpu_ms += cpu_now() - c0;
          ms["advect"] += ss.ms_advect;
          ms["diffuse"] += ss.ms_diffuse;
          ms["project"] += ss.ms_project;
          ms["scalars"] += ss.ms_scalars;
          ms["force"] += ss.ms_force;
          if (ss.projection.max_div_before > 0)
            max_div_rel = std::max(max_div_rel, ss.projection.max_div_after / ss.projection.max_div_before);
        }
        // One interpolated frame per step, into buffers kept from frame to frame as
        // `fluidsim run` keeps them (the first blend allocates them, untimed).
        State mid;
        blend(before, st, 0.4, mid);
        const auto t0 = Clock::now();
        for (int k = 0; k < o.steps; ++k) blend(before, st, 0.1 + 0.8 * k / o.steps, mid);
        ms["interp_frame"] = ms_since(t0);
        ms["step_nu0"] = ms["step"] - ms["diffuse"];
        for (auto& [stage, total] : ms) {
          const double mean = total / o.steps;
          const std::string key = fmt::format("{}/{}/{}", n, solver_name, stage);
          if (!base.count(key)) base[key] = mean;
          json line = {{"bench", "fluidsim"}, {"size", n}, {"nu", o.nu},    {"threads", t},  {"solver", solver_name},
                       {"stage", stage},      {"ms", mean},   {"speedup", base[key] / mean},
                       {"max_div_rel", max_div_rel}, {"setup_ms", setup_ms}};
          if (stage == "step") line["cpu_ms"] = cpu_ms / o.steps;
          if (solver == PoissonSolver::gs) line["anchor"] = "stam03 order, 20 Gauss-Seidel sweeps";
          if (solver == PoissonSolver::jacobi) line["anchor"] = "40 Jacobi sweeps (taichi semantics)";
          emit(line);
        }
      }
    }
}


}  // namespace fest::fluidsim
