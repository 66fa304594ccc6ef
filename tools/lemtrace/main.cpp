// lemtrace: streamlines of a vector field on an unstructured grid with the locally exact
// method (one closed-form step per tetrahedron), plus cell classification, a benchmark
// against Runge-Kutta at equal step count, and synthetic grids (docs/lemtrace.md).
//
// Wiring only: this file maps flags onto commands.hpp.

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

namespace {

using namespace fest::lemtrace_tool;
namespace lt = fest::lemtrace;

const std::vector<std::pair<std::string, CellSplit>> kSplits{{"conforming", CellSplit::conforming}, {"none", CellSplit::none}};
const std::vector<std::pair<std::string, EpsMode>> kEpsModes{{"abs", EpsMode::abs}, {"rel", EpsMode::rel}};
const std::vector<std::pair<std::string, lt::Precompute>> kPrecompute{
    {"all", lt::Precompute::all}, {"lazy", lt::Precompute::lazy}, {"none", lt::Precompute::none}};
const std::vector<std::pair<std::string, RootSolver>> kRoots{{"bracket", RootSolver::bracket}, {"newton", RootSolver::newton}};
const std::vector<std::pair<std::string, Extraordinary>> kExtraordinary{{"expm", Extraordinary::expm}};
const std::vector<std::pair<std::string, lt::Direction>> kDirections{
    {"forward", lt::Direction::forward}, {"backward", lt::Direction::backward}, {"both", lt::Direction::both}};
const std::vector<std::pair<std::string, lt::StepUnit>> kStepUnits{
    {"time", lt::StepUnit::time}, {"length", lt::StepUnit::length}, {"cell", lt::StepUnit::cell}};
const std::vector<std::pair<std::string, LineFormat>> kLineFormats{
    {"csv", LineFormat::csv}, {"vtp", LineFormat::vtp}, {"vtk", LineFormat::vtk}, {"json", LineFormat::json}};
const std::vector<std::pair<std::string, lt::Method>> kMethods{{"lem", lt::Method::lem},   {"euler", lt::Method::euler},
                                                               {"heun", lt::Method::heun}, {"rk3", lt::Method::rk3},
                                                               {"rk4", lt::Method::rk4},   {"rk45", lt::Method::rk45}};
const std::vector<std::pair<std::string, GridFormat>> kGridFormats{{"vtu", GridFormat::vtu}, {"vtk", GridFormat::vtk}};

// The texts of the repeatable number-carrying flags, parsed into TraceArgs when the
// command runs (usage errors then name the flag).
struct NumberTexts {
  std::vector<std::string> seed_points, seed_lines;
  void parse_into(TraceArgs& t) const {
    for (const auto& p : seed_points) t.seed_points.push_back(parse_seed_point(p));
    for (const auto& l : seed_lines) t.seed_lines.push_back(parse_seed_line(l));
  }
};

void add_grid_options(CLI::App* cmd, GridArgs& g, bool with_precompute) {
  cmd->add_option("--vectors", g.vectors, "Point vector array (default: active vectors, else the only 3-component one)");
  fest::cli::enum_words(cmd->add_option("--split", g.split, "Non-tetrahedral cells: conforming split, or none to reject them"), kSplits);
  cmd->add_option("--eps-parallel", g.eps_parallel, "epsilon_P: eigenvalue threshold for parallel cells")
      ->check(fest::cli::positive);
  fest::cli::enum_words(cmd->add_option("--eps-mode", g.eps_mode, "abs: |lambda| < eps (the paper's); rel: |lambda| tau_T < eps"), kEpsModes);
  if (with_precompute)
    fest::cli::enum_words(cmd->add_option("--precompute", g.precompute, "Per-cell records: all, lazy (first visit) or none (every visit)"), kPrecompute);
  fest::cli::add_threads(*cmd, g.threads);
}

void add_trace_options(CLI::App* cmd, TraceArgs& t, NumberTexts& numbers, bool seeds_required) {
  add_grid_options(cmd, t.grid, true);
  cmd->add_option("grid", t.grid.grid, "Grid: .vtu .vtk .vti .vts, or - for legacy .vtk on standard input")->required();
  auto* seeds = cmd->add_option("seeds", t.seeds, "Seeds: CSV x,y,z[,id][,t0] or .vtp/.vtk points; - = standard input");
  if (seeds_required) seeds->required();
  cmd->add_option("--seed-point", numbers.seed_points, "A seed x,y,z (repeatable)")->allow_extra_args(false);
  cmd->add_option("--seed-line", numbers.seed_lines, "n seeds on a segment: x0,y0,z0:x1,y1,z1:n (repeatable)")
      ->allow_extra_args(false);
  fest::cli::enum_words(cmd->add_option("--root", t.root, "Exit-time solver: bracket (safe) or newton (the paper's, validated)"), kRoots);
  cmd->add_option("--eps-newton", t.eps_newton, "Root tolerance relative to the cell's transit time")
      ->check(fest::cli::positive);
  fest::cli::enum_words(cmd->add_option("--extraordinary", t.extraordinary, "Extraordinary cells: expm (generic closed form)"), kExtraordinary);
  fest::cli::enum_words(cmd->add_option("--direction", t.direction, "forward, backward or both"), kDirections);
  cmd->add_option("--max-steps", t.max_steps, "Cells (LEM) or steps (RK) per line")->check(fest::cli::positive);
  cmd->add_option("--max-length", t.max_length, "Stop after this arc length")->check(fest::cli::positive);
  cmd->add_option("--max-time", t.max_time, "Stop after this integration time")->check(fest::cli::positive);
  cmd->add_option("--terminal-speed", t.terminal_speed, "Stop below this speed (default 1e-12 x max vertex speed)")
      ->check(fest::cli::non_negative);
  cmd->add_option("--step", t.step, "Step of the RK methods")->check(fest::cli::positive);
  fest::cli::enum_words(cmd->add_option("--step-unit", t.step_unit, "time, length or cell (fraction of h_T/|v|)"), kStepUnits);
  cmd->add_option("--tol", t.tolerance, "RK45 error tolerance per step")->check(fest::cli::positive);
  cmd->add_option("--samples-per-cell", t.samples_per_cell, "Closed-form points per cell (LEM; 0 = exits only)")
      ->check(fest::cli::range(0, 1000));
  cmd->add_option("-o,--output", t.output, "Output file (.csv .vtp .vtk .json), - = standard output");
  fest::cli::enum_words(cmd->add_option("--to", t.to, "Output format: csv, vtp, vtk or json"), kLineFormats);
  cmd->add_option("--report", t.report, "JSON summary: cell types, reasons, timings, memory");
}

}  // namespace

int main(int argc, char** argv) {
  // `lemtrace GRID ...` means `lemtrace trace GRID ...` (trace is the default subcommand).
  std::vector<char*> args(argv, argv + argc);
  static char trace_name[] = "trace";
  if (argc > 1) {
    const std::string first = argv[1];
    const bool known = first == "trace" || first == "probes" || first == "classify" || first == "bench" || first == "gen" ||
                       first == "--help" || first == "-h" || first == "--version";
    if (!known) args.insert(args.begin() + 1, trace_name);
  }
  std::string command_line;
  // The command line the outputs record as provenance; --progress changes nothing in them.
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) != "--progress") command_line += (command_line.empty() ? "" : " ") + std::string(argv[i]);

  CLI::App app{"Streamlines on unstructured grids with the locally exact method: the field is linear in each\n"
               "tetrahedron, the path through it is solved in closed form, one step per cell.",
               "lemtrace"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  TraceArgs trace;
  trace.command_line = command_line;
  auto* trace_cmd = app.add_subcommand("trace", "Trace streamlines from seeds (the default subcommand)");
  NumberTexts trace_numbers;
  add_trace_options(trace_cmd, trace, trace_numbers, false);
  fest::cli::enum_words(trace_cmd->add_option("--method", trace.method, "lem, euler, heun, rk3, rk4 or rk45"), kMethods);
  fest::cli::add_progress(*trace_cmd, trace.progress);

  ProbesArgs probes;
  probes.trace.command_line = command_line;
  auto* probes_cmd = app.add_subcommand("probes", "Stream ribbons, tubes and glyphs at the seeds as a mesh (PLY, VTP)");
  NumberTexts probes_numbers;
  add_trace_options(probes_cmd, probes.trace, probes_numbers, false);
  probes_cmd->add_option("--ribbon", probes.ribbon_width, "Ribbon width: a second line this far off, paired by time");
  probes_cmd->add_option("--tube", probes.tube_radius, "Tube radius around each line");
  probes_cmd->add_option("--sides", probes.sides, "Sides of tubes and arrows")->check(fest::cli::range(3, 64));
  probes_cmd->add_flag("--glyphs", probes.glyphs, "An arrow at every seed along the velocity");
  probes_cmd->add_option("--glyph-scale", probes.glyph_scale, "Arrow length per unit speed (default: 1/10 of the grid per max speed)");
  probes_cmd->add_option("--color", probes.color, "Scalar on tubes and glyphs: speed or a point array of the grid");

  ClassifyArgs classify;
  auto* classify_cmd = app.add_subcommand("classify", "Cell types and their statistics (Tables 9.1/9.2)");
  add_grid_options(classify_cmd, classify.grid, false);
  classify_cmd->add_option("grid", classify.grid.grid, "Grid file")->required();
  std::string sweep;
  classify_cmd->add_option("--sweep-parallel", sweep, "Count parallel cells for eps = 10^a .. 10^b: 1e-7:1e-1");
  classify_cmd->add_option("-o,--output", classify.output, "Write the grid with LemType, Eigenvalues, CriticalPointInside (.vtu)");
  fest::cli::add_progress(*classify_cmd, classify.progress);

  BenchArgs bench;
  bench.trace.command_line = command_line;
  auto* bench_cmd = app.add_subcommand("bench", "LEM against Euler/Heun/RK3/RK4 at equal step count (Table 9.4)");
  NumberTexts bench_numbers;
  add_trace_options(bench_cmd, bench.trace, bench_numbers, false);
  bench_cmd->add_option("--repeat", bench.repeat, "Run each method this many times, report the fastest")
      ->check(fest::cli::range(1, 100));

  GenArgs gen;
  auto* gen_cmd = app.add_subcommand("gen", "Synthetic grid with an analytic field");
  gen_cmd->add_option("kind", gen.kind,
                      "rotation helix saddle node spiral shear uniform jordan sphere-rotation sphere-potential abc")
      ->required();
  gen_cmd->add_option("--n", gen.n, "Cubes per side")->check(fest::cli::range(1, 400));
  gen_cmd->add_option("--tets", gen.tets, "Tetrahedra per cube (6: Kuhn split)")->check(CLI::IsMember({6}));
  gen_cmd->add_option("--jitter", gen.jitter, "Random interior vertex displacement, fraction of the cell size")
      ->check(fest::cli::range(0.0, 0.49));
  gen_cmd->add_option("--seed", gen.seed, "Random seed of the jitter");
  gen_cmd->add_flag("--hex", gen.hex, "Write hexahedra instead of tetrahedra");
  gen_cmd->add_option("-o,--output", gen.output, "Output grid (.vtu or .vtk), - = standard output");
  fest::cli::enum_words(gen_cmd->add_option("--to", gen.to, "Output format: vtu or vtk"), kGridFormats);

  app.footer("Exit status: 0 success (lines that stop early say why), 1 numerical failure, 2 usage error,\n"
             "3 bad input, 4 I/O error. See lemtrace(1).");
  const int n = static_cast<int>(args.size());
  return fest::cli::run(app, n, args.data(), [&] {
    if (trace_cmd->parsed()) {
      trace_numbers.parse_into(trace);
      return run_trace(trace);
    }
    if (probes_cmd->parsed()) {
      probes_numbers.parse_into(probes.trace);
      return run_probes(probes);
    }
    if (classify_cmd->parsed()) {
      if (!sweep.empty()) classify.sweep = parse_parallel_sweep(sweep);
      return run_classify(classify);
    }
    if (bench_cmd->parsed()) {
      bench_numbers.parse_into(bench.trace);
      return run_bench(bench);
    }
    return run_gen(gen);
  });
}
