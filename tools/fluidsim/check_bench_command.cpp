// fluidsim check (analytic cases -> JSON report) and fluidsim bench (stage timings ->
// JSON lines).
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>

#include <omp.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/resources.hpp"
#include "core/threads.hpp"
#include "fluidsim/checks.hpp"
#include "fluidsim/simulator.hpp"

namespace fest::fluidsim_tool {

using namespace fest::fluidsim;
using nlohmann::json;

int omp_threads() { return omp_get_max_threads(); }

void set_threads(int threads) { omp_set_num_threads(fest::resolve_threads(threads)); }

double peak_rss_mb() { return peak_rss_kb() / 1024.0; }

int check_command(const CheckOptions& o) {
  set_threads(o.threads);
  fluidsim::CheckOptions co;
  co.n = o.n;
  co.dt = o.dt;
  co.nu = o.nu;
  json report;
  const std::string& w = o.which;
  auto run_one = [&](const std::string& name) {
    if (name == "projection") return check_projection(co);
    if (name == "taylor-green") return check_taylor_green(co);
    if (name == "abc") return check_abc(co);
    if (name == "mass") return check_mass(co);
    if (name == "stability") return check_stability(co);
    return check_interp(co);
  };
  if (w == "all") {
    report = {{"check", "all"}, {"cases", json::array()}};
    bool pass = true;
    for (const char* name : {"projection", "taylor-green", "abc", "mass", "stability", "interp"}) {
      json r = run_one(name);
      pass = pass && r["pass"].get<bool>();
      report["cases"].push_back(r);
    }
    report["pass"] = pass;
  } else {
    report = run_one(w);
  }
  const std::string text = report.dump(2) + "\n";
  if (!o.report.empty()) write_output(o.report, text);
  write_output("-", text);
  return report["pass"].get<bool>() ? 0 : 1;
}

int bench_command(const BenchOptions& o) {
  using Clock = std::chrono::steady_clock;
  // (size, solver, stage) -> ms at the first thread count, for the speed-ups.
  std::map<std::string, double> base;
  for (int n : o.sizes)
    for (const std::string& solver_name : o.poisson) {
      SimOptions so;
      so.projection.solver = parse_poisson(solver_name);
      if (solver_name == "gs") so.stam03 = true;  // Stam 2003 semantics: 20 Gauss-Seidel sweeps
      so.projection.iters = solver_name == "jacobi" ? 40 : 20;
      so.projection.tol = 1e-8;
      for (int t : o.threads) {
        omp_set_num_threads(t);
        Scene sc;
        sc.dims = {n, n, n};
        sc.viscosity = o.nu;
        ScalarSpec s;
        Source src;
        src.shape = Source::Shape::sphere;
        src.centre = {0.5 * (n + 1), 0.5 * (n + 1), 0.2 * (n + 1)};
        src.radius = 0.1 * n;
        src.rate = 10.0;
        src.jet = true;
        src.velocity = {0, 0, 0.5};
        s.sources = {src};
        sc.scalars = {s};
        Force f;
        f.type = Force::Type::buoyancy;
        f.scalar = "density";
        f.beta = 1.0;
        sc.forces = {f};
        const auto t_setup = Clock::now();
        const Simulator sim(sc, so);
        const double setup_ms = std::chrono::duration<double, std::milli>(Clock::now() - t_setup).count();
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
          ms["step"] += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
          cpu_ms += cpu_now() - c0;
          ms["advect"] += ss.ms_advect;
          ms["diffuse"] += ss.ms_diffuse;
          ms["project"] += ss.ms_project;
          ms["scalars"] += ss.ms_scalars;
          ms["force"] += ss.ms_force;
          if (ss.projection.max_div_before > 0)
            max_div_rel = std::max(max_div_rel, ss.projection.max_div_after / ss.projection.max_div_before);
        }
        const auto t0 = Clock::now();
        const State mid = blend(before, st, 0.4);
        ms["interp_frame"] = std::chrono::duration<double, std::milli>(Clock::now() - t0).count() * o.steps;
        (void)mid;
        ms["step_nu0"] = ms["step"] - ms["diffuse"];
        for (auto& [stage, total] : ms) {
          const double mean = total / o.steps;
          const std::string key = fmt::format("{}/{}/{}", n, solver_name, stage);
          if (!base.count(key)) base[key] = mean;
          json line = {{"bench", "fluidsim"}, {"size", n}, {"nu", o.nu},    {"threads", t},  {"solver", solver_name},
                       {"stage", stage},      {"ms", mean},   {"speedup", base[key] / mean},
                       {"max_div_rel", max_div_rel}, {"setup_ms", setup_ms}};
          if (stage == "step") line["cpu_ms"] = cpu_ms / o.steps;
          if (solver_name == "gs") line["anchor"] = "stam03 order, 20 Gauss-Seidel sweeps";
          if (solver_name == "jacobi") line["anchor"] = "40 Jacobi sweeps (taichi semantics)";
          std::printf("%s\n", line.dump().c_str());
          std::fflush(stdout);
        }
      }
    }
  return 0;
}

}  // namespace fest::fluidsim_tool
