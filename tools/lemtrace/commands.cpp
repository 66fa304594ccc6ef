// The subcommands: read with formats/, compute with lib/lemtrace, write with formats/.

#include "commands.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/indexed_ply.hpp"
#include "lemtrace/probes.hpp"
#include "formats/table/table_io.hpp"
#include "dataset_bridge.hpp"
#include "line_stream.hpp"

namespace fest::lemtrace_tool {
namespace {

// Peak resident memory of this process (Linux), in MB; 0 where unknown.
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

struct Loaded {
  std::unique_ptr<FieldGrid> grid;
  LoadedGrid source;
  MeshReport report;
  double read_s = 0, build_s = 0, precompute_s = 0;
};

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
    bo.split = a.split == "conforming";
    if (!bo.split && out.source.points.size() <= INT32_MAX) refuse_unsplit_cells(out.source.cells, out.source.points.size());
    TetMesh mesh = build_tet_mesh(out.source.points, out.source.vectors, out.source.cells, bo, &out.report);
    out.source.points.clear();
    out.source.vectors.clear();
    out.source.cells = RawCells{};
    out.build_s = seconds_since(t0);
    ClassifyParams cp;
    cp.eps_parallel = a.eps_parallel;
    cp.eps_relative = a.eps_mode == "rel";
    Precompute mode = Precompute::lazy;
    if (a.precompute == "all" || force_all) mode = Precompute::all;
    if (a.precompute == "none" && !force_all) mode = Precompute::none;
    t0 = SteadyClock::now();
    out.grid = std::make_unique<FieldGrid>(std::move(mesh), cp, mode, resolve_threads(a.threads));
    out.precompute_s = seconds_since(t0);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), in.name));
  }
  return out;
}

// "x,y,z" -> three numbers; usage error otherwise.
std::vector<double> numbers(const std::string& text, std::size_t count, const char* option) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(v))
      throw usage_error("{} '{}': '{}' is not a number", option, text, item);
    out.push_back(v);
  }
  if (out.size() != count) throw usage_error("{} '{}': expected {} numbers separated by commas", option, text, count);
  return out;
}

struct Seeds {
  std::vector<Vec3> x;
  std::vector<double> t0;
  std::vector<double> id;
};

void add_seed(Seeds& s, const Vec3& x, double t0, double id) {
  s.x.push_back(x);
  s.t0.push_back(t0);
  s.id.push_back(id);
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
  for (const std::string& p : a.seed_points) {
    const auto v = numbers(p, 3, "--seed-point");
    add_seed(s, Vec3(v[0], v[1], v[2]), 0.0, static_cast<double>(s.x.size()));
  }
  for (const std::string& l : a.seed_lines) {
    const std::size_t c1 = l.find(':'), c2 = l.find(':', c1 == std::string::npos ? c1 : c1 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos)
      throw usage_error("--seed-line '{}': expected x0,y0,z0:x1,y1,z1:n", l);
    const auto p0 = numbers(l.substr(0, c1), 3, "--seed-line");
    const auto p1 = numbers(l.substr(c1 + 1, c2 - c1 - 1), 3, "--seed-line");
    const auto nn = numbers(l.substr(c2 + 1), 1, "--seed-line");
    const int n = static_cast<int>(nn[0]);
    if (n < 1 || n != nn[0] || n > 10000000) throw usage_error("--seed-line '{}': n must be a positive integer", l);
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

Method method_from(const std::string& m) {
  if (m == "euler") return Method::euler;
  if (m == "heun") return Method::heun;
  if (m == "rk3") return Method::rk3;
  if (m == "rk4") return Method::rk4;
  if (m == "rk45") return Method::rk45;
  return Method::lem;
}

TraceOptions trace_options(const TraceArgs& a) {
  TraceOptions o;
  o.method = method_from(a.method);
  o.exit.paper_newton = a.root == "newton";
  o.exit.eps_newton = a.eps_newton;
  o.direction = a.direction == "backward" ? Direction::backward
                : a.direction == "both"   ? Direction::both
                                          : Direction::forward;
  o.max_steps = a.max_steps;
  if (a.max_length > 0) o.max_length = a.max_length;
  if (a.max_time > 0) o.max_time = a.max_time;
  o.terminal_speed = a.terminal_speed;
  o.step = a.step;
  o.step_unit = a.step_unit == "time" ? StepUnit::time : a.step_unit == "length" ? StepUnit::length : StepUnit::cell;
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

}  // namespace

int run_trace(const TraceArgs& a) {
  // Decide the output format before the work, so a bad -o fails at once.
  std::string to = a.to;
  if (to.empty() && !is_stdio(a.output)) {
    const std::string ext = a.output.substr(a.output.find_last_of('.') == std::string::npos ? a.output.size()
                                                                                            : a.output.find_last_of('.'));
    if (ext == ".csv") to = "csv";
    else if (ext == ".vtp") to = "vtp";
    else if (ext == ".vtk") to = "vtk";
    else if (ext == ".json") to = "json";
    else throw usage_error("cannot tell the output format from '{}'; use --to csv|vtp|vtk|json", a.output);
  }
  if (to.empty()) to = "csv";

  const Seeds seeds = load_seeds(a);
  Loaded loaded = load_grid(a.grid, false);
  const FieldGrid& grid = *loaded.grid;
  const TraceOptions o = trace_options(a);
  const int threads = resolve_threads(a.grid.threads);
  auto t0 = SteadyClock::now();
  grid.locator();
  const double locator_s = seconds_since(t0);
  // CSV and JSON stream: each chunk of lines is written as it is finished, in seed order
  // (line_stream.hpp). VTK outputs go through a dataset, built from all the lines.
  OutputFile out(a.output);
  LineTotals totals;
  t0 = SteadyClock::now();
  if (to == "csv" || to == "json") {
    totals = stream_lines(grid, StreamSeeds{&seeds.x, &seeds.t0, &seeds.id}, o, threads,
                          to == "csv" ? TextFormat::csv : TextFormat::json, out);
  } else {
    const std::vector<Polyline> lines = trace_all(grid, seeds.x, seeds.t0, o, threads);
    check_numbers(lines);
    for (const Polyline& l : lines) totals.add(l);
    LineSet set{&lines, &seeds.id, a.command_line};
    const Dataset poly = polylines_to_dataset(grid, set);
    out.write(formats::write_dataset(poly, to == "vtp" ? formats::Format::vtp : formats::Format::vtk));
  }
  const double trace_s = seconds_since(t0);

  if (!a.report.empty()) {
    nlohmann::json report = {
        {"seeds", seeds.x.size()},
        {"method", a.method},
        {"tetrahedra", grid.mesh().tets.size()},
        {"points", grid.mesh().points.size()},
        {"input_cells", loaded.report.input_cells},
        {"split_cells", loaded.report.split_cells},
        {"flipped_cells", loaded.report.flipped},
        {"boundary_faces", loaded.report.boundary_faces},
        {"vectors", loaded.source.vector_name},
        {"reasons", totals.reasons},
        {"segment_cell_types", totals.types},
        {"cells_crossed", totals.cells},
        {"output_points", totals.points},
        {a.method == "lem" ? "closed_form_evaluations" : "field_evaluations", totals.evaluations},
        {"locator_calls", totals.locator_calls},
        {"records_computed", grid.records_computed()},
        {"timings_s", {{"read", loaded.read_s}, {"build", loaded.build_s}, {"precompute", loaded.precompute_s},
                       {"locator", locator_s}, {"trace_and_write", trace_s}}},
        {"memory_mb", {{"grid_estimate", static_cast<double>(grid.bytes()) / 1048576.0}, {"peak_rss", peak_memory_mb()}}},
        {"threads", threads}};
    write_output(a.report, report.dump(2) + "\n");
  }
  out.commit();
  return 0;
}

int run_classify(const ClassifyArgs& a) {
  Loaded loaded = load_grid(a.grid, true);
  const FieldGrid& grid = *loaded.grid;
  const std::size_t n = grid.mesh().tets.size();
  std::vector<CellRecord> records(n);
  CellRecord scratch;
  for (std::size_t c = 0; c < n; ++c) records[c] = grid.record(static_cast<int32_t>(c), scratch);
  std::string out;
  if (a.sweep.empty()) {
    int64_t count[4] = {0, 0, 0, 0};
    int64_t critical = 0;
    for (const CellRecord& r : records) {
      ++count[static_cast<int>(r.type)];
      critical += r.critical_inside;
    }
    out = "type,count,percent\n";
    for (int t = 0; t < 4; ++t)
      out += fmt::format("{},{},{:.4f}\n", cell_type_name(static_cast<CellType>(t)), count[t],
                         n ? 100.0 * static_cast<double>(count[t]) / static_cast<double>(n) : 0.0);
    out += fmt::format("critical_point_inside,{},{:.4f}\n", critical,
                       n ? 100.0 * static_cast<double>(critical) / static_cast<double>(n) : 0.0);
    out += fmt::format("total,{},100.0000\n", n);
  } else {
    const std::size_t colon = a.sweep.find(':');
    if (colon == std::string::npos) throw usage_error("--sweep-parallel '{}': expected FROM:TO, e.g. 1e-7:1e-1", a.sweep);
    const double from = numbers(a.sweep.substr(0, colon), 1, "--sweep-parallel")[0];
    const double upto = numbers(a.sweep.substr(colon + 1), 1, "--sweep-parallel")[0];
    if (!(from > 0 && upto >= from)) throw usage_error("--sweep-parallel '{}': need 0 < FROM <= TO", a.sweep);
    out = "eps_parallel,parallel,percent,extraordinary\n";
    ClassifyParams cp = grid.params();
    for (double e = from; e <= upto * (1 + 1e-9); e *= 10) {
      cp.eps_parallel = e;
      int64_t parallel = 0, extra = 0;
      for (std::size_t c = 0; c < n; ++c) {
        const CellRecord r = classify(tet_geometry(grid.mesh(), static_cast<int32_t>(c)), cp);
        parallel += r.type == CellType::parallel;
        extra += r.type == CellType::extraordinary;
      }
      out += fmt::format("{:g},{},{:.4f},{}\n", e, parallel, n ? 100.0 * static_cast<double>(parallel) / static_cast<double>(n) : 0.0, extra);
    }
  }
  if (!a.output.empty()) {
    const Dataset ug = classified_dataset(grid, records);
    const formats::OutputFormat of = formats::output_format_from_path(a.output);
    if (of.format != formats::Format::vtu && of.format != formats::Format::vtk)
      throw usage_error("classify -o writes .vtu or .vtk, not '{}'", a.output);
    formats::store_output(a.output, formats::write_dataset(ug, of.format), of.gzip);
  }
  write_output("-", out);
  return 0;
}

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

int run_gen(const GenArgs& a) {
  std::string to = a.to;
  if (to.empty()) {
    if (is_stdio(a.output)) to = "vtu";
    else {
      const formats::OutputFormat of = formats::output_format_from_path(a.output);
      if (of.format == formats::Format::vtu) to = "vtu";
      else if (of.format == formats::Format::vtk) to = "vtk";
      else throw usage_error("gen writes .vtu or .vtk, not '{}'", a.output);
    }
  }
  const auto& kinds = gen_kinds();
  if (std::find(kinds.begin(), kinds.end(), a.kind) == kinds.end())
    throw usage_error("unknown grid kind '{}' (see lemtrace gen --help)", a.kind);
  GenOptions o;
  o.kind = a.kind;
  o.n = a.n;
  o.jitter = a.jitter;
  o.seed = a.seed;
  o.hex = a.hex;
  const GeneratedGrid g = generate(o);
  const Dataset ug = dataset_from_generated(g, a.kind);
  write_output(a.output, formats::write_dataset(ug, to == "vtu" ? formats::Format::vtu : formats::Format::vtk));
  return 0;
}

namespace {

// Values of a point array at x: barycentric interpolation in the tet containing x. The
// mesh's vertices must be the dataset's points (no split that adds points).
struct PointArray {
  std::vector<double> values;
  bool ok(const FieldGrid& grid) const { return values.size() == grid.mesh().points.size(); }
  double at(const FieldGrid& grid, const Vec3& x) const {
    const int32_t cell = grid.locator().locate(x);
    if (cell < 0) return std::nan("");
    const TetGeometry g = tet_geometry(grid.mesh(), cell);
    const Eigen::Vector4d b = g.bary(x);
    const Tet& t = grid.mesh().tets[static_cast<std::size_t>(cell)];
    double v = 0;
    for (int k = 0; k < 4; ++k) v += b[k] * values[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
    return v;
  }
};

PointArray point_array(const std::string& path, const std::string& name) {
  const formats::Input in = formats::load_input(path);
  const Dataset ds = formats::parse(in, formats::read_dataset);
  // vtkFieldData::GetArray(name): the first array of that name, when it is numeric.
  const DataArray* arr = nullptr;
  for (const DataArray& candidate : ds.point_data)
    if (candidate.name == name) {
      if (candidate.numeric()) arr = &candidate;
      break;
    }
  if (!arr) throw bad_input("{}", with_location(fmt::format("no point array '{}' to colour by", name), in.name));
  if (arr->components != 1)
    throw bad_input("{}", with_location(fmt::format("point array '{}' has {} components; colour by a scalar", name,
                                                    arr->components), in.name));
  PointArray out;
  out.values.resize(arr->tuples());
  for (std::size_t i = 0; i < arr->tuples(); ++i) out.values[i] = arr->component(i, 0);
  return out;
}

Dataset probe_dataset(const ProbeMesh& mesh) {
  Dataset poly;
  poly.kind = DatasetKind::polydata;
  poly.has_points = true;
  std::vector<float> xyz;
  xyz.reserve(3 * mesh.points.size());
  for (const auto& p : mesh.points)
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
  poly.points = DataArray::from_floats("Points", 3, xyz);
  for (const auto& t : mesh.triangles) {
    const int64_t ids[3] = {t[0], t[1], t[2]};
    poly.polys.push_back(ids, 3);
  }
  for (std::size_t k = 0; k < mesh.scalars.size(); ++k) {
    std::vector<float> values;
    values.reserve(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i) values.push_back(static_cast<float>(mesh.scalars[k][i]));
    poly.point_data.push_back(DataArray::from_floats(mesh.scalar_names[k], 1, values));
  }
  return poly;
}

}  // namespace

int run_probes(const ProbesArgs& a) {
  std::string to = a.trace.to;
  if (to.empty() && !is_stdio(a.trace.output)) {
    const auto dot = a.trace.output.find_last_of('.');
    const std::string ext = dot == std::string::npos ? "" : a.trace.output.substr(dot);
    if (ext == ".ply") to = "ply";
    else if (ext == ".vtp") to = "vtp";
    else throw usage_error("cannot tell the output format from '{}'; use --to ply|vtp", a.trace.output);
  }
  if (to.empty()) to = "ply";
  if (to != "ply" && to != "vtp") throw usage_error("probes write ply or vtp, not {}", to);
  if (!(a.ribbon_width > 0) && !(a.tube_radius > 0) && !a.glyphs)
    throw usage_error("nothing to draw: give --ribbon WIDTH, --tube RADIUS and/or --glyphs");
  if (a.ribbon_width < 0 || a.tube_radius < 0 || a.glyph_scale < 0)
    throw usage_error("--ribbon, --tube and --glyph-scale must not be negative");

  const Seeds seeds = load_seeds(a.trace);
  Loaded loaded = load_grid(a.trace.grid, false);
  const FieldGrid& grid = *loaded.grid;
  TraceOptions o = trace_options(a.trace);
  if (o.method == Method::lem && o.samples_per_cell == 0) o.samples_per_cell = 4;  // smooth ribbons
  const int threads = resolve_threads(a.trace.grid.threads);
  grid.locator();

  PointArray colour;
  const bool by_speed = a.color == "speed";
  if (!by_speed) {
    colour = point_array(a.trace.grid.grid, a.color);
    if (!colour.ok(grid))
      throw bad_input("point array '{}' has {} values for {} mesh points (a split added points); colour by speed",
                      a.color, colour.values.size(), grid.mesh().points.size());
  }
  auto value_at = [&](const Vec3& x) {
    if (!by_speed) return colour.at(grid, x);
    const int32_t cell = grid.locator().locate(x);
    return cell < 0 ? 0.0 : velocity_at(grid, cell, x).norm();
  };

  // Size of the grid, for default glyph and tube sizes.
  Vec3 lo = grid.mesh().points.front(), hi = lo;
  for (const Vec3& p : grid.mesh().points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).norm();

  ProbeMesh mesh;
  std::size_t ribbons = 0, tubes = 0, glyphs = 0, outside = 0;
  std::vector<Polyline> lines;
  if (a.ribbon_width > 0 || a.tube_radius > 0) lines = trace_all(grid, seeds.x, seeds.t0, o, threads);
  if (a.ribbon_width > 0) {
    std::vector<Vec3> side(seeds.x.size());
    for (std::size_t s = 0; s < seeds.x.size(); ++s) {
      const int32_t cell = grid.locator().locate(seeds.x[s]);
      const Vec3 v = cell < 0 ? Vec3::UnitX() : velocity_at(grid, cell, seeds.x[s]);
      side[s] = seeds.x[s] + a.ribbon_width * perpendicular(v);
    }
    const std::vector<Polyline> neighbours = trace_all(grid, side, seeds.t0, o, threads);
    for (std::size_t s = 0; s < lines.size(); ++s) {
      const auto edges = ribbon_edges(lines[s], neighbours[s]);
      // Half the streamwise vorticity on the main line: the rate the twist should have.
      std::vector<double> rate;
      for (const auto& e : edges) {
        const int32_t cell = grid.locator().locate(e.a);
        double r = 0;
        if (cell >= 0) {
          const TetGeometry g = tet_geometry(grid.mesh(), cell);
          Mat3 A;
          Vec3 b;
          linear_field(g, A, b);
          r = 0.5 * streamwise_vorticity(A, A * e.a + b);
        }
        rate.push_back(r);
      }
      if (edges.size() >= 2) ++ribbons;
      append_ribbon(mesh, edges, "half_streamwise_vorticity", rate);
    }
  }
  if (a.tube_radius > 0) {
    for (const Polyline& l : lines) {
      std::vector<double> values;
      for (const Vec3& x : l.x) values.push_back(value_at(x));
      if (l.x.size() >= 2) ++tubes;
      append_tube(mesh, l, a.tube_radius, a.sides, a.color, values);
    }
  }
  if (a.glyphs) {
    const double scale = a.glyph_scale > 0 ? a.glyph_scale : 0.1 * extent / std::max(grid.max_speed(), 1e-300);
    for (const Vec3& x : seeds.x) {
      const int32_t cell = grid.locator().locate(x);
      if (cell < 0) {
        ++outside;
        continue;
      }
      const Vec3 v = velocity_at(grid, cell, x);
      const double len = scale * v.norm();
      if (!(len > 0)) {
        ++outside;
        continue;
      }
      append_arrow(mesh, x, v, len, 0.06 * len, a.sides, a.color, value_at(x));
      ++glyphs;
    }
  }
  for (auto& s : mesh.scalars) s.resize(mesh.points.size(), 0.0);

  std::string bytes;
  if (to == "ply") {
    std::vector<float> xyz;
    xyz.reserve(3 * mesh.points.size());
    for (const Vec3& p : mesh.points)
      for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
    std::vector<std::vector<float>> sc;
    for (const auto& s : mesh.scalars) sc.emplace_back(s.begin(), s.end());
    bytes = formats::write_indexed_ply(xyz, mesh.triangles, mesh.scalar_names, sc);
  } else {
    bytes = formats::write_dataset(probe_dataset(mesh), formats::Format::vtp);
  }
  write_output(a.trace.output, bytes);
  if (outside > 0) warn("lemtrace", fmt::format("{} seeds outside the grid or at rest got no glyph", outside));
  if (!a.trace.report.empty()) {
    nlohmann::json r = {{"seeds", seeds.x.size()}, {"ribbons", ribbons}, {"tubes", tubes}, {"glyphs", glyphs},
                        {"seeds_without_glyph", outside}, {"vertices", mesh.points.size()},
                        {"triangles", mesh.triangles.size()}, {"scalars", mesh.scalar_names}};
    write_output(a.trace.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::lemtrace_tool
