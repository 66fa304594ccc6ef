// lemtrace trace: streamlines from the seeds, streamed as CSV/JSON or written as VTK polylines.

#include "commands.hpp"

#include <sys/stat.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/stopwatch.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "line_stream.hpp"
#include "trace_inputs.hpp"

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

// Where the VTP's temporaries go: beside the output (one file system, like OutputFile's
// own temporary), else $TMPDIR or /tmp for standard output.
std::string temporary_folder(const std::string& output) {
  if (!is_stdio(output)) {
    const auto slash = output.find_last_of('/');
    struct stat st;
    if (::stat(output.c_str(), &st) != 0 || S_ISREG(st.st_mode))
      return slash == std::string::npos ? "." : slash == 0 ? "/" : output.substr(0, slash);
  }
  const char* tmp = std::getenv("TMPDIR");
  return tmp != nullptr && *tmp != '\0' ? tmp : "/tmp";
}

}  // namespace

int run_trace(const TraceArgs& a) {
  // Decide the output format before the work, so a bad -o fails at once.
  LineFormat to = a.to;
  if (to == LineFormat::unset && !is_stdio(a.output)) {
    const std::string ext = a.output.substr(a.output.find_last_of('.') == std::string::npos ? a.output.size()
                                                                                            : a.output.find_last_of('.'));
    if (ext == ".csv") to = LineFormat::csv;
    else if (ext == ".vtp") to = LineFormat::vtp;
    else if (ext == ".vtk") to = LineFormat::vtk;
    else if (ext == ".json") to = LineFormat::json;
    else throw usage_error("cannot tell the output format from '{}'; use --to csv|vtp|vtk|json", a.output);
  }
  if (to == LineFormat::unset) to = LineFormat::csv;

  const Seeds seeds = load_seeds(a);
  Loaded loaded = load_grid(a.grid, false);
  const FieldGrid& grid = *loaded.grid;
  TraceOptions o = trace_options(a);
  Progress bar("lemtrace trace", seeds.x.size(), progress_wanted(a.progress));
  o.progress = bar.callback();
  const int threads = resolve_threads(a.grid.threads);
  auto t0 = SteadyClock::now();
  grid.locator();
  const double locator_s = seconds_since(t0);
  // CSV, JSON and VTP stream: each chunk of lines is written as it is finished, in seed
  // order (line_stream.hpp). Legacy .vtk goes through a dataset, built from all the lines.
  // A reader that goes away (a closed pipe) or a full disk is an I/O error, exit 4 with
  // one message, rather than a death by SIGPIPE or SIGXFSZ half-way through the output.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  OutputFile out(a.output);
  LineTotals totals;
  t0 = SteadyClock::now();
  if (to != LineFormat::vtk) {
    const StreamFormat format =
        to == LineFormat::csv ? StreamFormat::csv : to == LineFormat::json ? StreamFormat::json : StreamFormat::vtp;
    totals = stream_lines(grid, StreamSeeds{&seeds.x, &seeds.t0, &seeds.id}, o, threads, format, out, 0,
                          VtpSettings{temporary_folder(a.output), a.command_line});
  } else {
    const std::vector<Polyline> lines = trace_all(grid, seeds.x, seeds.t0, o, threads);
    check_numbers(lines);
    for (const Polyline& l : lines) totals.add(l);
    LineSet set{&lines, &seeds.id, a.command_line};
    const Dataset poly = polylines_to_dataset(grid, set);
    out.write(formats::write_dataset(poly, formats::Format::vtk));
  }
  bar.finish();
  const double trace_s = seconds_since(t0);

  if (!a.report.empty()) {
    nlohmann::json report = {
        {"seeds", seeds.x.size()},
        {"method", method_name(a.method)},
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
        {a.method == Method::lem ? "closed_form_evaluations" : "field_evaluations", totals.evaluations},
        {"locator_calls", totals.locator_calls},
        {"records_computed", grid.records_computed()},
        {"timings_s", {{"read", loaded.read_s}, {"build", loaded.build_s}, {"precompute", loaded.precompute_s},
                       {"locator", locator_s}, {"trace_and_write", trace_s},
                       {"stream", {{"trace", totals.trace_s}, {"format", totals.format_s},
                                   {"wait_for_writer", totals.wait_s}, {"writer_thread", totals.write_s},
                                   {"finish", totals.finish_s}}}}},
        {"memory_mb", {{"grid_estimate", static_cast<double>(grid.bytes()) / 1048576.0}, {"peak_rss", peak_memory_mb()}}},
        {"threads", threads}};
    write_output(a.report, report.dump(2) + "\n");
  }
  out.commit();
  return 0;
}

}  // namespace fest::lemtrace_tool
