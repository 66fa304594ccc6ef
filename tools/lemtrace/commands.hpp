#pragma once
// lemtrace's four subcommands (spec §4), each taking its parsed options.

#include <cstdint>
#include <string>
#include <vector>

namespace fest::lemtrace_tool {

struct GridArgs {
  std::string grid;
  std::string vectors;
  std::string split = "conforming";
  double eps_parallel = 1e-4;
  std::string eps_mode = "rel";
  std::string precompute = "lazy";
  int threads = 0;
};

struct TraceArgs {
  GridArgs grid;
  std::string seeds;
  std::vector<std::string> seed_points;
  std::vector<std::string> seed_lines;
  std::string method = "lem";
  std::string root = "bracket";
  double eps_newton = 1e-12;
  std::string extraordinary = "expm";
  std::string direction = "forward";
  int64_t max_steps = 100000;
  double max_length = -1, max_time = -1;
  double terminal_speed = -1;
  double step = 0.2;
  std::string step_unit = "cell";
  double tolerance = 1e-6;
  int samples_per_cell = 0;
  std::string output = "-";
  std::string to;
  std::string report;
  std::string command_line;
};

struct ClassifyArgs {
  GridArgs grid;
  std::string sweep;
  std::string output;
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
  std::string to;
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

int run_trace(const TraceArgs& args);
int run_probes(const ProbesArgs& args);
int run_classify(const ClassifyArgs& args);
int run_bench(const BenchArgs& args);
int run_gen(const GenArgs& args);

}  // namespace fest::lemtrace_tool
