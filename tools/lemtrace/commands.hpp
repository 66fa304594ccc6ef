#pragma once
// lemtrace's subcommands (docs/lemtrace.md), each taking its typed options: the flags'
// words are enums here, their numbers parsed in main.cpp.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lemtrace/field_grid.hpp"
#include "lemtrace/tracer.hpp"

namespace fest::lemtrace_tool {

// --to of trace and probes; unset = from the output file's extension.
enum class LineFormat { unset, csv, vtp, vtk, json };
const char* line_format_name(LineFormat f);
// --root: the exit-time solver.
enum class RootSolver { bracket, newton };
// --extraordinary: how extraordinary cells are solved (one way so far).
enum class Extraordinary { expm };
// --to of gen; unset = from the output file's extension.
enum class GridFormat { unset, vtu, vtk };
// --split: non-tetrahedral cells split conformingly, or refused.
enum class CellSplit { conforming, none };
// --eps-mode: |lambda| < eps (abs, the paper's) or |lambda| tau_T < eps (rel).
enum class EpsMode { abs, rel };

struct GridArgs {
  std::string grid;
  std::string vectors;
  CellSplit split = CellSplit::conforming;
  double eps_parallel = 1e-4;
  EpsMode eps_mode = EpsMode::rel;
  lemtrace::Precompute precompute = lemtrace::Precompute::lazy;
  int threads = 0;
};

// --seed-line x0,y0,z0:x1,y1,z1:n
struct SeedLine {
  std::array<double, 3> from{}, to{};
  int n = 1;
};

struct TraceArgs {
  GridArgs grid;
  std::string seeds;
  std::vector<std::array<double, 3>> seed_points;
  std::vector<SeedLine> seed_lines;
  lemtrace::Method method = lemtrace::Method::lem;
  RootSolver root = RootSolver::bracket;
  double eps_newton = 1e-12;
  Extraordinary extraordinary = Extraordinary::expm;
  lemtrace::Direction direction = lemtrace::Direction::forward;
  int64_t max_steps = 100000;
  double max_length = -1, max_time = -1;
  double terminal_speed = -1;
  double step = 0.2;
  lemtrace::StepUnit step_unit = lemtrace::StepUnit::cell;
  double tolerance = 1e-6;
  int samples_per_cell = 0;
  std::string output = "-";
  LineFormat to = LineFormat::unset;
  std::string report;
  std::string command_line;
  bool progress = false;  // --progress (trace): seeds traced so far
};

// --sweep-parallel FROM:TO: count parallel cells for eps = FROM, 10 FROM, ... TO.
struct ParallelSweep {
  double from = 0, to = 0;
};

struct ClassifyArgs {
  GridArgs grid;
  std::optional<ParallelSweep> sweep;
  std::string output;
  bool progress = false;  // --progress: cells classified (once, then once per sweep decade)
};

struct BenchArgs {
  TraceArgs trace;
  int repeat = 1;
};

struct GenArgs {
  std::string kind;
  int n = 40;
  int tets = 6;
  double jitter = 0;
  uint64_t seed = 1;
  bool hex = false;
  std::string output = "-";
  GridFormat to = GridFormat::unset;
};

// Particle probes (seed ch. 4.3): stream ribbons, tubes and glyphs from the seeds, as a
// triangle mesh with per-vertex scalars (PLY or VTP).
struct ProbesArgs {
  TraceArgs trace;
  double ribbon_width = 0;   // > 0: a ribbon per seed, the neighbour line this far off
  double tube_radius = 0;    // > 0: a tube per seed
  int sides = 12;
  bool glyphs = false;       // an arrow at every seed
  double glyph_scale = 0;    // arrow length per unit speed (0: a tenth of the grid's size / max speed)
  std::string color = "speed";  // glyph and tube colour: speed or a point array
};

// The flag values with numbers inside, parsed once by main.cpp; usage errors name the flag.
std::array<double, 3> parse_seed_point(const std::string& text);  // "x,y,z"
SeedLine parse_seed_line(const std::string& text);                 // "x0,y0,z0:x1,y1,z1:n"
ParallelSweep parse_parallel_sweep(const std::string& text);       // "1e-7:1e-1"

int run_trace(const TraceArgs& args);
int run_probes(const ProbesArgs& args);
int run_classify(const ClassifyArgs& args);
int run_bench(const BenchArgs& args);
int run_gen(const GenArgs& args);

}  // namespace fest::lemtrace_tool
