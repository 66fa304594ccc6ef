// lemtrace classify: the cell types and their statistics (Tables 9.1/9.2), or the parallel-cell sweep.

#include "commands.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"
#include "trace_inputs.hpp"

namespace fest::lemtrace_tool {

int run_classify(const ClassifyArgs& a) {
  Loaded loaded = load_grid(a.grid, true);
  const FieldGrid& grid = *loaded.grid;
  const std::size_t n = grid.mesh().tets.size();
  std::vector<CellRecord> records(n);
  CellRecord scratch;
  // The bar: every cell once, then once more per decade of --sweep-parallel.
  std::uint64_t decades = 0;
  if (a.sweep)
    for (double e = a.sweep->from; e <= a.sweep->to * (1 + 1e-9); e *= 10) ++decades;
  Progress bar("lemtrace classify", static_cast<std::uint64_t>(n) * (1 + decades), progress_wanted(a.progress));
  constexpr std::size_t kCellsPerStep = 4096;
  for (std::size_t c = 0; c < n; ++c) {
    records[c] = grid.record(static_cast<int32_t>(c), scratch);
    if ((c + 1) % kCellsPerStep == 0) bar.advance(kCellsPerStep);
  }
  bar.set(n);
  std::string out;
  if (!a.sweep) {
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
    const double from = a.sweep->from, upto = a.sweep->to;
    out = "eps_parallel,parallel,percent,extraordinary\n";
    ClassifyParams cp = grid.params();
    std::uint64_t decade_done = 0;
    for (double e = from; e <= upto * (1 + 1e-9); e *= 10) {
      cp.eps_parallel = e;
      int64_t parallel = 0, extra = 0;
      for (std::size_t c = 0; c < n; ++c) {
        const CellRecord r = classify(tet_geometry(grid.mesh(), static_cast<int32_t>(c)), cp);
        parallel += r.type == CellType::parallel;
        extra += r.type == CellType::extraordinary;
        if ((c + 1) % kCellsPerStep == 0) bar.advance(kCellsPerStep);
      }
      bar.set(static_cast<std::uint64_t>(n) * (++decade_done + 1));
      out += fmt::format("{:g},{},{:.4f},{}\n", e, parallel, n ? 100.0 * static_cast<double>(parallel) / static_cast<double>(n) : 0.0, extra);
    }
  }
  bar.finish();
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

}  // namespace fest::lemtrace_tool
