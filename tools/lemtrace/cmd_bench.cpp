// lemtrace bench: the LEM against Euler/Heun/RK3/RK4 at equal step count (Table 9.4).

#include "commands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/stopwatch.hpp"
#include "trace_inputs.hpp"

namespace fest::lemtrace_tool {

int run_bench(const BenchArgs& a) {
  const Seeds seeds = load_seeds(a.trace);
  if (seeds.x.empty()) throw usage_error("bench needs seeds (SEEDS, --seed-point or --seed-line)");
  const int threads = 1;  // the table compares per-core cost, as the paper's single CPU
  GridArgs ga = a.trace.grid;
  Loaded loaded = load_grid(ga, true);
  const FieldGrid& all = *loaded.grid;
  all.locator();
  TraceOptions base = trace_options(a.trace);
  base.method = Method::lem;
  const bool analytic = loaded.source.linear;
  const LinearField field = loaded.source.field;

  // The chapter's Table 9.4 (§9.4.4): every method takes the same number of steps over
  // the same path. The LEM crosses S cells in time T on a line; each RK method then takes
  // S steps of h = T / S on that line. Besides the time, the table gives the cost per
  // step and the evaluations per step (closed-form evaluations for the LEM, field
  // evaluations - point location plus interpolation - for RK), and how many lines fell
  // short of the LEM's step count (an RK line that drifted out of the grid).
  struct Row {
    std::string method;
    double seconds = 0;
    int64_t steps = 0, locator_calls = 0, evaluations = 0, short_lines = 0;
    double max_err = 0, mean_err = 0;
  };
  std::vector<Polyline> reference(seeds.x.size());
  for (std::size_t i = 0; i < seeds.x.size(); ++i) reference[i] = trace(all, seeds.x[i], seeds.t0[i], base);
  auto measure = [&](const std::string& name, const FieldGrid& grid, auto&& run_one) {
    Row row;
    row.method = name;
    row.seconds = std::numeric_limits<double>::infinity();
    std::vector<Polyline> lines(seeds.x.size());
    for (int rep = 0; rep < a.repeat; ++rep) {
      auto t0 = SteadyClock::now();
      for (std::size_t i = 0; i < seeds.x.size(); ++i) lines[i] = run_one(grid, i);
      row.seconds = std::min(row.seconds, seconds_since(t0));
    }
    double sum = 0;
    int64_t count = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      row.steps += lines[i].cells;
      row.locator_calls += lines[i].locator_calls;
      row.evaluations += lines[i].evaluations;
      row.short_lines += lines[i].cells < reference[i].cells;
      if (!analytic) continue;
      for (std::size_t k = 0; k < lines[i].x.size(); ++k) {
        const double e = (lines[i].x[k] - linear_flow(field, seeds.x[i], lines[i].t[k] - seeds.t0[i])).norm();
        row.max_err = std::max(row.max_err, e);
        sum += e;
        ++count;
      }
    }
    row.mean_err = count ? sum / static_cast<double>(count) : 0.0;
    if (!analytic) row.max_err = row.mean_err = std::numeric_limits<double>::quiet_NaN();
    return row;
  };
  (void)threads;
  std::vector<Row> rows;
  rows.push_back(measure("lem_precomputed", all, [&](const FieldGrid& g, std::size_t i) {
    return trace(g, seeds.x[i], seeds.t0[i], base);
  }));
  // The same, with the bracket search alone (no predicted exit): what the prediction saves.
  rows.push_back(measure("lem_bracket", all, [&](const FieldGrid& g, std::size_t i) {
    TraceOptions o = base;
    o.exit.predict = false;
    return trace(g, seeds.x[i], seeds.t0[i], o);
  }));
  // RK methods: as many steps per line as the LEM crossed cells, over the same time.
  auto equal_steps = [&](Method m, bool cell_search) {
    return [&, m, cell_search](const FieldGrid& g, std::size_t i) {
      TraceOptions o = base;
      o.method = m;
      o.rk_cell_search = cell_search;
      const Polyline& ref = reference[i];
      const double T = ref.t.empty() ? 0.0 : std::abs(ref.t.back() - seeds.t0[i]);
      o.max_steps = std::max<int64_t>(1, ref.cells);
      o.step_unit = StepUnit::time;
      o.step = ref.cells > 0 && T > 0 ? T / static_cast<double>(ref.cells) : 1e-3;
      o.max_time = T > 0 ? T : o.max_time;
      return trace(g, seeds.x[i], seeds.t0[i], o);
    };
  };
  for (Method m : {Method::euler, Method::heun, Method::rk3, Method::rk4})
    rows.push_back(measure(method_name(m), all, equal_steps(m, false)));
  // The integrators as the chapter's §9.2.1 loop writes them (Table 9.4's baseline): a
  // cell search (the bin grid, as fast as VTK's vtkStaticCellLocator, see
  // bench_lemtrace_locate) for every evaluation instead of the neighbour walk.
  for (Method m : {Method::euler, Method::heun, Method::rk3, Method::rk4})
    rows.push_back(measure(std::string(method_name(m)) + "_cell_search", all, equal_steps(m, true)));
  {
    ClassifyParams cp = all.params();
    TetMesh copy = all.mesh();
    FieldGrid fly(std::move(copy), cp, Precompute::none, 1);
    fly.locator();
    rows.push_back(measure("lem_on_the_fly", fly, [&](const FieldGrid& g, std::size_t i) {
      return trace(g, seeds.x[i], seeds.t0[i], base);
    }));
  }
  std::string out =
      "method,total_s,steps,locator_calls,max_err,mean_err,ns_per_step,evals_per_step,short_lines\n";
  for (const Row& r : rows) {
    const double steps = static_cast<double>(std::max<int64_t>(1, r.steps));
    out += fmt::format("{},{:.6f},{},{},{:.3g},{:.3g},{:.1f},{:.3f},{}\n", r.method, r.seconds, r.steps,
                       r.locator_calls, r.max_err, r.mean_err, 1e9 * r.seconds / steps,
                       static_cast<double>(r.evaluations) / steps, r.short_lines);
  }
  write_output("-", out);
  return 0;
}

}  // namespace fest::lemtrace_tool
