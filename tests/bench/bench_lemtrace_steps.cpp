// Table 9.4 of the chapter (docs/lemtrace.md §5) in instructions per step: the cost of
// one LEM cell crossing against one step of each Runge-Kutta method at equal step count,
// on `lemtrace gen sphere-rotation --n 20` with 50 seeds on (0.55, 0, 0.13)-(0.8, 0, 0.13)
// over one revolution, exactly as `lemtrace bench` sets the RK steps (h = T / S per line).
//
//   build/bin/bench_lemtrace_steps [--repeat 20]
//       one JSON line per method: steps, CPU seconds (best of --repeat), ns per step
//   valgrind --tool=callgrind --instr-atstart=no build/bin/bench_lemtrace_steps --repeat 1
//       the same, and callgrind dumps one profile per method (part names "lem_precomputed",
//       "euler", ...) whose event totals divided by the steps are the instructions per step
// *_cell_search are the integrators with a bin-grid cell search per evaluation (the
// chapter's §9.2.1 loop, Table 9.4's baseline) instead of the neighbour walk; the search
// costs about what VTK's vtkStaticCellLocator::FindCell does (bench_lemtrace_locate).
//
// Each measured section holds the traces only (grid, records and locator are built
// before; the reference LEM lines that fix the step counts are traced outside).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <valgrind/callgrind.h>

#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/tracer.hpp"
#include "lemtrace_table94.hpp"

namespace {

using namespace fest::lemtrace;

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 20;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));

  LinearField field;
  TetMesh mesh = bench::table94_mesh(&field);
  TetMesh copy = mesh;
  const FieldGrid grid(std::move(mesh), ClassifyParams{}, Precompute::all, 1);
  grid.locator();
  // The chapter's "exact on the fly": every record computed when a path enters the cell.
  const FieldGrid fly(std::move(copy), ClassifyParams{}, Precompute::none, 1);
  fly.locator();

  const std::vector<Vec3> seeds = bench::table94_seeds();
  const TraceOptions lem = bench::table94_lem();
  std::vector<Polyline> reference;
  for (const Vec3& s : seeds) reference.push_back(trace(grid, s, 0.0, lem));

  const struct {
    const char* name;
    Method method;
    bool cell_search;
    const FieldGrid* on;
  } cases[] = {{"lem_precomputed", Method::lem, false, &grid}, {"euler", Method::euler, false, &grid},
               {"heun", Method::heun, false, &grid},           {"rk3", Method::rk3, false, &grid},
               {"rk4", Method::rk4, false, &grid},             {"euler_cell_search", Method::euler, true, &grid},
               {"heun_cell_search", Method::heun, true, &grid}, {"rk3_cell_search", Method::rk3, true, &grid},
               {"rk4_cell_search", Method::rk4, true, &grid},  {"lem_on_the_fly", Method::lem, false, &fly}};
  for (const auto& c : cases) {
    std::vector<TraceOptions> opts;
    for (const Polyline& ref : reference) {
      opts.push_back(bench::equal_step_options(c.method, ref));
      opts.back().rk_cell_search = c.cell_search;
    }
    int64_t steps = 0, evaluations = 0;
    double max_err = 0, best = 1e300;
    for (int rep = 0; rep < repeat; ++rep) {
      std::vector<Polyline> lines(seeds.size());
      const double t0 = cpu_now();
      CALLGRIND_START_INSTRUMENTATION;
      for (std::size_t i = 0; i < seeds.size(); ++i) lines[i] = trace(*c.on, seeds[i], 0.0, opts[i]);
      CALLGRIND_STOP_INSTRUMENTATION;
      best = std::min(best, cpu_now() - t0);
      if (rep > 0) continue;
      CALLGRIND_DUMP_STATS_AT(c.name);
      for (std::size_t i = 0; i < lines.size(); ++i) {
        steps += lines[i].cells;
        evaluations += lines[i].evaluations;
        for (std::size_t k = 0; k < lines[i].x.size(); ++k)
          max_err = std::max(max_err, (lines[i].x[k] - linear_flow(field, seeds[i], lines[i].t[k])).norm());
      }
    }
    std::printf("{\"case\":\"table94\",\"method\":\"%s\",\"steps\":%lld,\"cpu_s\":%.6f,\"ns_per_step\":%.1f,"
                "\"evals_per_step\":%.3f,\"max_err\":%.3g}\n",
                c.name, static_cast<long long>(steps), best, 1e9 * best / static_cast<double>(steps),
                static_cast<double>(evaluations) / static_cast<double>(steps), max_err);
  }
  return 0;
}
