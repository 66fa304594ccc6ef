#include "trace_inputs.hpp"

#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

namespace fest::lemtrace_tool {
namespace {

// --split none: the first cell that is not a tetrahedron is refused here, naming the flag
// (build_tet_mesh refuses it too, in its own terms). A cell with a point id out of range
// stops the scan: build_tet_mesh reports that first.
void refuse_unsplit_cells(const RawCells& cells, std::size_t points) {
  const auto n_points = static_cast<int64_t>(points);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (int64_t i = cells.offsets[c]; i < cells.offsets[c + 1]; ++i)
      if (cells.ids[static_cast<std::size_t>(i)] < 0 || cells.ids[static_cast<std::size_t>(i)] >= n_points) return;
    const int type = cells.types[c];
    if (type != static_cast<int>(CellShape::tetra))
      throw bad_input("cell {} is a VTK type {} cell and --split none accepts only tetrahedra", c, type);
  }
}

void add_seed(Seeds& s, const Vec3& x, double t0, double id) {
  s.x.push_back(x);
  s.t0.push_back(t0);
  s.id.push_back(id);
}

}  // namespace

Loaded load_grid(const GridArgs& a, bool force_all) {
  Loaded out;
  auto t0 = SteadyClock::now();
  const formats::Input in = formats::load_input(a.grid);
  if (formats::kind_of(in.format) != formats::Kind::dataset)
    throw bad_input("{}", with_location(fmt::format("the grid is a {} file, not a VTK dataset",
                                                    formats::format_name(in.format)), in.name));
  Dataset ds = formats::parse(in, formats::read_dataset);
  out.read_s = seconds_since(t0);
  t0 = SteadyClock::now();
  try {
    out.source = grid_from_dataset(ds, a.vectors);
    ds = Dataset();  // the grid's memory is not needed while the mesh is built
    BuildOptions bo;
    bo.split = a.split == CellSplit::conforming;
    if (!bo.split && out.source.points.size() <= INT32_MAX) refuse_unsplit_cells(out.source.cells, out.source.points.size());
    TetMesh mesh = build_tet_mesh(out.source.points, out.source.vectors, out.source.cells, bo, &out.report);
    out.source.points.clear();
    out.source.vectors.clear();
    out.source.cells = RawCells{};
    out.build_s = seconds_since(t0);
    ClassifyParams cp;
    cp.eps_parallel = a.eps_parallel;
    cp.eps_relative = a.eps_mode == EpsMode::rel;
    const Precompute mode = force_all ? Precompute::all : a.precompute;
    t0 = SteadyClock::now();
    out.grid = std::make_unique<FieldGrid>(std::move(mesh), cp, mode, resolve_threads(a.threads));
    out.precompute_s = seconds_since(t0);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), in.name));
  }
  return out;
}

Seeds load_seeds(const TraceArgs& a) {
  Seeds s;
  if (!a.seeds.empty()) {
    if (a.seeds == "-" && a.grid.grid == "-")
      throw usage_error("the grid and the seeds cannot both come from standard input");
    std::string bytes = read_input(a.seeds);
    if (bytes.find_first_not_of(" \t\r\n") != std::string::npos) {
      const formats::Input in = formats::recognise(std::move(bytes), a.seeds);
      const formats::Kind kind = formats::kind_of(in.format);
      if (kind == formats::Kind::table) {
        const Table table = formats::parse(in, formats::read_table);
        const std::size_t cx = table.find("x"), cy = table.find("y"), cz = table.find("z");
        if (cx == Table::npos || cy == Table::npos || cz == Table::npos)
          throw bad_input("{}", with_location("the seed table needs columns x, y and z", in.name));
        const std::size_t cid = table.find("id"), ct = table.find("t0");
        for (std::size_t r = 0; r < table.rows(); ++r)
          add_seed(s, Vec3(table.columns[cx][r], table.columns[cy][r], table.columns[cz][r]),
                   ct == Table::npos ? 0.0 : table.columns[ct][r],
                   cid == Table::npos ? static_cast<double>(r) : table.columns[cid][r]);
      } else if (kind == formats::Kind::dataset) {
        const Dataset ds = formats::parse(in, formats::read_dataset);
        for (const Vec3& p : points_of(ds)) add_seed(s, p, 0.0, static_cast<double>(s.x.size()));
      } else {
        throw bad_input("{}", with_location(fmt::format("seeds must be CSV or VTK points, not {}",
                                                        formats::format_name(in.format)), in.name));
      }
    }
  }
  for (const auto& p : a.seed_points) add_seed(s, Vec3(p[0], p[1], p[2]), 0.0, static_cast<double>(s.x.size()));
  for (const SeedLine& l : a.seed_lines) {
    const auto& p0 = l.from;
    const auto& p1 = l.to;
    const int n = l.n;
    for (int i = 0; i < n; ++i) {
      const double f = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
      add_seed(s, Vec3(p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1]), p0[2] + f * (p1[2] - p0[2])), 0.0,
               static_cast<double>(s.x.size()));
    }
  }
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (!s.x[i].allFinite() || !std::isfinite(s.t0[i])) throw bad_input("seed {} has a non-finite value", i);
  return s;
}

TraceOptions trace_options(const TraceArgs& a) {
  TraceOptions o;
  o.method = a.method;
  o.exit.paper_newton = a.root == RootSolver::newton;
  o.exit.eps_newton = a.eps_newton;
  o.direction = a.direction;
  o.max_steps = a.max_steps;
  if (a.max_length > 0) o.max_length = a.max_length;
  if (a.max_time > 0) o.max_time = a.max_time;
  o.terminal_speed = a.terminal_speed;
  o.step = a.step;
  o.step_unit = a.step_unit;
  o.tolerance = a.tolerance;
  o.samples_per_cell = a.samples_per_cell;
  return o;
}

void check_numbers(const std::vector<Polyline>& lines) {
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (std::size_t i = 0; i < lines[l].x.size(); ++i)
      if (!lines[l].x[i].allFinite() || !std::isfinite(lines[l].t[i]))
        throw runtime_failure("line {} produced a non-finite point in cell {}", l, lines[l].cell[i]);
}

}  // namespace fest::lemtrace_tool
