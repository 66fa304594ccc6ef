#pragma once
// What trace, probes, classify and bench start from: the grid (read, split into
// tetrahedra, classified), the seeds, and the tracer's options from the typed flags.

#include <memory>
#include <vector>

#include "commands.hpp"
#include "dataset_bridge.hpp"

namespace fest::lemtrace_tool {

struct Loaded {
  std::unique_ptr<FieldGrid> grid;
  LoadedGrid source;
  MeshReport report;
  double read_s = 0, build_s = 0, precompute_s = 0;
};

// Reads the grid file and builds the field grid; force_all precomputes every cell record
// (classify, bench) whatever --precompute says.
Loaded load_grid(const GridArgs& a, bool force_all);

struct Seeds {
  std::vector<Vec3> x;
  std::vector<double> t0;
  std::vector<double> id;
};

// The seeds of the SEEDS file, then --seed-point, then --seed-line, in that order.
Seeds load_seeds(const TraceArgs& a);

TraceOptions trace_options(const TraceArgs& a);

// A runtime failure naming the first line with a non-finite point.
void check_numbers(const std::vector<Polyline>& lines);

}  // namespace fest::lemtrace_tool
