#pragma once
// Streaming trace output: seeds are traced in chunks, each chunk's lines traced in
// parallel, formatted (by the workers, or with one thread by the writer thread while the
// next chunk is traced) and written in seed order as soon as the chunk is done. The output is the same for any thread count, and
// memory holds only the lines of one chunk, never the whole result.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/file_io.hpp"
#include "lemtrace/field_grid.hpp"
#include "lemtrace/tracer.hpp"

namespace fest::lemtrace_tool {

using namespace fest::lemtrace;

enum class StreamFormat { csv, json, vtp };

// What the VTP output needs beyond the lines: where its per-array temporaries go (the
// output's folder, so the copy stays on one file system) and the LemtraceOptions text.
struct VtpSettings {
  std::string temp_dir = ".";
  std::string options;
};

// What the report counts, summed over every line as it passes.
struct LineTotals {
  std::map<std::string, int64_t> reasons, types;
  int64_t lines = 0, cells = 0, points = 0, evaluations = 0, locator_calls = 0;
  // Seconds: tracing and formatting (worker threads, wall), waiting for the writer
  // thread, the writer thread's own time, and the VTP header and copy at the end.
  double trace_s = 0, format_s = 0, wait_s = 0, write_s = 0, finish_s = 0;
  void add(const Polyline& line);
};

struct StreamSeeds {
  const std::vector<Vec3>* x;
  const std::vector<double>* t0;
  const std::vector<double>* id;
};

// Traces every seed and writes the lines to `out` as CSV (line,seed,i,x,y,z,t,cell,type,
// speed with %.17g numbers), as a JSON array (the layout of nlohmann's dump(1)) or as
// VTK PolyData (.vtp, the bytes VTK writes for polylines_to_dataset's dataset; the
// per-point arrays pass through temporaries, formats/dataset/vtp_polyline_stream.hpp).
// Throws runtime_failure on a non-finite point. `chunk` = 0 picks 64 lines per thread.
LineTotals stream_lines(const FieldGrid& grid, const StreamSeeds& seeds, const TraceOptions& options, int threads,
                        StreamFormat format, OutputFile& out, std::size_t chunk = 0, const VtpSettings& vtp = {});

// One line's CSV rows (`index` is its number among the lines with points), and one line
// as its element of the JSON array.
// csv_rows appends to `out` (a buffer reused from chunk to chunk).
void csv_rows(std::string& out, const FieldGrid& grid, const Polyline& line, int64_t index, double seed_id);
std::string json_element(const Polyline& line, double seed_id);

}  // namespace fest::lemtrace_tool
