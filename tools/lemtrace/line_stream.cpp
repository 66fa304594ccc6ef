#include "line_stream.hpp"

#include <algorithm>
#include <cmath>
#include <charconv>
#include <cstring>
#include <future>
#include <string_view>
#include <iterator>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/parallel_for.hpp"
#include "dataset_bridge.hpp"

namespace fest::lemtrace_tool {

void LineTotals::add(const Polyline& l) {
  ++lines;
  ++reasons[reason_name(l.reason)];
  cells += l.cells;
  points += static_cast<int64_t>(l.x.size());
  evaluations += l.evaluations;
  locator_calls += l.locator_calls;
  for (std::size_t i = 1; i < l.type.size(); ++i) ++types[cell_type_name(static_cast<CellType>(l.type[i]))];
}

namespace {

// The seed id as fmt's "{}" writes a double (the shortest text that round-trips, fixed
// notation below 1e16): integers, the usual ids, directly; anything else through fmt.
void append_seed_id(std::string& out, double id) {
  if (id == std::floor(id) && std::abs(id) < 1e15 && !(id == 0 && std::signbit(id))) {
    append_int(out, static_cast<int64_t>(id));
    return;
  }
  fmt::format_to(std::back_inserter(out), "{}", id);
}

void check_finite(const Polyline& line, std::size_t index) {
  for (std::size_t i = 0; i < line.x.size(); ++i)
    if (!line.x[i].allFinite() || !std::isfinite(line.t[i]))
      throw runtime_failure("line {} produced a non-finite point in cell {}", index, line.cell[i]);
}

}  // namespace

void csv_rows(std::string& out, const FieldGrid& grid, const Polyline& line, int64_t index, double seed_id) {
  std::string seed;  // "line,seed," the same on every row
  append_int(seed, index);
  seed += ',';
  append_seed_id(seed, seed_id);
  seed += ',';
  out.reserve(out.size() + line.x.size() * 150);
  const auto& source_cell = grid.mesh().source_cell;
  // One row at a time in a stack buffer (a row is at most ~190 bytes), appended once.
  char row[320];
  for (std::size_t i = 0; i < line.x.size(); ++i) {
    const Vec3 v = velocity_at(grid, line.cell[i], line.x[i]);
    char* p = row;
    std::memcpy(p, seed.data(), seed.size());
    p += seed.size();
    p = std::to_chars(p, row + sizeof row, static_cast<int64_t>(i)).ptr;
    for (int k = 0; k < 3; ++k) {
      *p++ = ',';
      p = write_g17(p, line.x[i][k]);
    }
    *p++ = ',';
    p = write_g17(p, line.t[i]);
    *p++ = ',';
    p = std::to_chars(p, row + sizeof row, source_cell[static_cast<std::size_t>(line.cell[i])]).ptr;
    *p++ = ',';
    p = std::to_chars(p, row + sizeof row, static_cast<int>(line.type[i])).ptr;
    *p++ = ',';
    p = write_g17(p, v.norm());
    *p++ = '\n';
    out.append(row, p);
  }
}

std::string json_element(const Polyline& line, double seed_id) {
  nlohmann::json pts = nlohmann::json::array();
  for (std::size_t i = 0; i < line.x.size(); ++i) pts.push_back({line.x[i][0], line.x[i][1], line.x[i][2], line.t[i]});
  const nlohmann::json element = {{"seed", seed_id},
                                  {"reason", static_cast<int>(line.reason)},
                                  {"reason_name", reason_name(line.reason)},
                                  {"cells", line.cells},
                                  {"points", pts}};
  // Inside the top-level array of dump(1) every line of an element is indented by one
  // more space than the element dumped alone.
  const std::string alone = element.dump(1);
  std::string out;
  out.reserve(alone.size() + alone.size() / 8 + 1);
  out += ' ';
  for (char c : alone) {
    out += c;
    if (c == '\n') out += ' ';
  }
  return out;
}

LineTotals stream_lines(const FieldGrid& grid, const StreamSeeds& seeds, const TraceOptions& options, int threads,
                        TextFormat format, OutputFile& out, std::size_t chunk) {
  const std::size_t n = seeds.x->size();
  threads = std::max(1, threads);
  if (chunk == 0) chunk = std::max<std::size_t>(128, 64 * static_cast<std::size_t>(threads));
  grid.locator();
  LineTotals totals;
  std::string pending;  // small pieces (indices, separators), flushed with each line's text
  if (format == TextFormat::csv) pending = "line,seed,i,x,y,z,t,cell,type,speed\n";
  else pending = n == 0 ? "[]" : "[\n";
  int64_t csv_index = 0;  // CSV numbers the lines that have points
  std::vector<Polyline> lines;
  // Two sets of text buffers: one being written while the other is filled; each
  // buffer keeps its capacity from chunk to chunk (no fresh pages for every line).
  std::vector<std::string> text[2];
  int filling = 0;
  std::future<void> writing;
  std::vector<int64_t> index;
  for (std::size_t begin = 0; begin < n; begin += chunk) {
    const std::size_t count = std::min(chunk, n - begin);
    lines.assign(count, Polyline{});
    index.assign(count, -1);
    std::vector<std::string>& tx = text[filling];
    tx.resize(count);
    // Trace in parallel; number the lines with points in seed order (the CSV's line
    // column); format in parallel.
    parallel_for(count, threads, [&](std::size_t j) {
      const std::size_t s = begin + j;
      lines[j] = trace(grid, (*seeds.x)[s], s < seeds.t0->size() ? (*seeds.t0)[s] : 0.0, options);
      check_finite(lines[j], s);
    });
    if (options.progress) options.progress(begin + count, n);
    for (std::size_t j = 0; j < count; ++j) {
      totals.add(lines[j]);
      index[j] = lines[j].x.empty() ? -1 : csv_index++;
    }
    parallel_for(count, threads, [&](std::size_t j) {
      const std::size_t s = begin + j;
      tx[j].clear();
      if (format == TextFormat::json) {
        if (s > 0) tx[j] = ",\n";
        tx[j] += json_element(lines[j], (*seeds.id)[s]);
      } else if (index[j] >= 0) {
        csv_rows(tx[j], grid, lines[j], index[j], (*seeds.id)[s]);
      }
      lines[j] = Polyline{};
    });
    // The chunk's text goes to a writer thread, in seed order, so that the disk write
    // overlaps the tracing of the next chunk (one write in flight).
    if (writing.valid()) writing.get();
    writing = std::async(std::launch::async, [&out, &tx, count, head = std::move(pending)] {
      if (!head.empty()) out.write(head);
      for (std::size_t j = 0; j < count; ++j)
        if (!tx[j].empty()) out.write(tx[j]);
    });
    pending.clear();
    filling ^= 1;
  }
  if (writing.valid()) writing.get();
  if (format == TextFormat::json && n > 0) pending += "\n]";
  if (format == TextFormat::json) pending += '\n';
  out.write(pending);
  return totals;
}

}  // namespace fest::lemtrace_tool
