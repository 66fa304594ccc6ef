#include "line_stream.hpp"

#include <algorithm>
#include <condition_variable>
#include <cmath>
#include <charconv>
#include <cstring>
#include <future>
#include <memory>
#include <mutex>
#include <string_view>
#include <iterator>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/parallel_for.hpp"
#include "core/stopwatch.hpp"
#include "formats/dataset/vtp_polyline_stream.hpp"
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

namespace {

// The VTP arrays of one line, packed by a worker for the writer thread: IntegrationTime,
// CellId, Speed, Velocity, then the points (the arrays of polylines_to_dataset).
constexpr std::size_t vtp_bytes_per_point = 8 + 8 + 8 + 24 + 24;

void vtp_pack(std::string& out, const FieldGrid& grid, const Polyline& line) {
  const std::size_t n = line.x.size();
  out.resize(n * vtp_bytes_per_point);
  char* time = out.data();
  char* cell = time + 8 * n;
  char* speed = cell + 8 * n;
  char* vel = speed + 8 * n;
  char* pts = vel + 24 * n;
  const auto& source_cell = grid.mesh().source_cell;
  for (std::size_t i = 0; i < n; ++i) {
    const int32_t c = line.cell[i];
    const Vec3 v = velocity_at(grid, c, line.x[i]);
    const double s = v.norm();
    const int64_t id = source_cell[static_cast<std::size_t>(c)];
    const double xv[3] = {v[0], v[1], v[2]}, xp[3] = {line.x[i][0], line.x[i][1], line.x[i][2]};
    std::memcpy(time + 8 * i, &line.t[i], 8);
    std::memcpy(cell + 8 * i, &id, 8);
    std::memcpy(speed + 8 * i, &s, 8);
    std::memcpy(vel + 24 * i, xv, 24);
    std::memcpy(pts + 24 * i, xp, 24);
  }
}

formats::VtpPolylineLayout vtp_layout(const VtpSettings& settings) {
  using formats::VtpType;
  formats::VtpPolylineLayout l;
  l.point_data = {{"IntegrationTime", VtpType::float64, 1, false},
                  {"CellId", VtpType::int64, 1, true},
                  {"Speed", VtpType::float64, 1, false},
                  {"Velocity", VtpType::float64, 3, false}};
  l.cell_data = {{"SeedId", VtpType::int64, 1, true},
                 {"ReasonForTermination", VtpType::int32, 1, false},
                 {"NumberOfCells", VtpType::int64, 1, true}};
  l.field_name = "LemtraceOptions";
  l.field_text = settings.options;
  return l;
}

// The lines of a chunk still to be formatted, shared by the writer thread, which takes
// them from the front and writes each as it goes, and -- with one tracing thread -- the
// main thread once it has traced the next chunk, which takes them from the back instead of
// waiting. The formatting (more than the tracing: 225 instructions a number, issue 23's
// lemtrace row) is so split between the two threads as their other work leaves them time;
// the writer still writes in seed order, so the bytes do not depend on who formatted what.
class FormatShare {
 public:
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  void reset(std::size_t count) {
    std::lock_guard<std::mutex> lock(m_);
    front_ = 0;
    back_ = count;
    busy_ = 0;
  }
  // The writer's next line, or none once the rest is the main thread's (from back_end()).
  std::size_t take_front() {
    std::lock_guard<std::mutex> lock(m_);
    return front_ < back_ ? front_++ : none;
  }
  std::size_t take_back() {
    std::lock_guard<std::mutex> lock(m_);
    if (front_ >= back_) return none;
    ++busy_;
    return --back_;
  }
  void done_back() {
    std::lock_guard<std::mutex> lock(m_);
    if (--busy_ == 0) formatted_.notify_all();
  }
  // Waits until the lines taken from the back are formatted; returns the first of them.
  std::size_t back_end() {
    std::unique_lock<std::mutex> lock(m_);
    formatted_.wait(lock, [&] { return busy_ == 0; });
    return back_;
  }

 private:
  std::mutex m_;
  std::condition_variable formatted_;
  std::size_t front_ = 0, back_ = 0, busy_ = 0;
};

// What the writer thread needs of a line once its points are gone.
struct LineMeta {
  std::size_t points = 0;
  int64_t csv_index = -1;             // its number among the lines with points, -1 for none
  double cell_values[3] = {0, 0, 0};  // SeedId, ReasonForTermination, NumberOfCells
};

}  // namespace

LineTotals stream_lines(const FieldGrid& grid, const StreamSeeds& seeds, const TraceOptions& options, int threads,
                        StreamFormat format, OutputFile& out, std::size_t chunk, const VtpSettings& vtp_settings) {
  const std::size_t n = seeds.x->size();
  threads = std::max(1, threads);
  if (chunk == 0) chunk = std::max<std::size_t>(128, 64 * static_cast<std::size_t>(threads));
  // With one tracing thread the writer thread formats too: a pipeline, tracing the next
  // chunk while this one is formatted and written, and the main thread, once it has
  // traced, takes over lines still to be formatted from the writer (FormatShare). With
  // more, the workers format (in parallel, so that the output keeps up with them) and the
  // writer thread only writes.
  const bool writer_formats = threads == 1;
  grid.locator();
  LineTotals totals;
  std::unique_ptr<formats::VtpPolylineStream> vtp;
  if (format == StreamFormat::vtp)
    vtp = std::make_unique<formats::VtpPolylineStream>(vtp_layout(vtp_settings), vtp_settings.temp_dir);
  std::string pending;  // small pieces (indices, separators), flushed with each line's text
  if (format == StreamFormat::csv) pending = "line,seed,i,x,y,z,t,cell,type,speed\n";
  else if (format == StreamFormat::json) pending = n == 0 ? "[]" : "[\n";
  int64_t csv_index = 0;  // CSV numbers the lines that have points
  // Two sets of lines and buffers (text, or a VTP line's packed arrays): one being
  // written while the other is filled; each buffer keeps its capacity from chunk to
  // chunk (no fresh pages for every line).
  std::vector<Polyline> line_sets[2];
  std::vector<std::string> text[2];
  std::vector<LineMeta> meta[2];
  FormatShare share[2];
  std::size_t written_begin = 0;  // the first seed of the chunk the writer has
  int filling = 0;
  double write_s = 0;  // the writer thread's, read after each get()
  // One line's text (or packed arrays) into `buf`; the line's points are released.
  auto format_line = [&](std::string& buf, Polyline& line, const LineMeta& m, std::size_t s) {
    buf.clear();
    if (format == StreamFormat::json) {
      if (s > 0) buf = ",\n";
      buf += json_element(line, (*seeds.id)[s]);
    } else if (m.csv_index >= 0) {
      if (format == StreamFormat::csv) csv_rows(buf, grid, line, m.csv_index, (*seeds.id)[s]);
      else vtp_pack(buf, grid, line);
    }
    line = Polyline{};
  };
  // With one tracing thread: the main thread formats lines of the chunk being written,
  // from its end, until it meets the writer (FormatShare). Returns the seconds it spent.
  auto help_format = [&](int set) {
    if (!writer_formats) return 0.0;
    const auto h0 = SteadyClock::now();
    for (std::size_t j; (j = share[set].take_back()) != FormatShare::none;) {
      struct Done {  // even when formatting throws, or the writer would wait for ever
        FormatShare& s;
        ~Done() { s.done_back(); }
      } done{share[set]};
      format_line(text[set][j], line_sets[set][j], meta[set][j], written_begin + j);
    }
    return seconds_since(h0);
  };
  auto write_line = [&](const std::string& buf, const LineMeta& m) {
    if (buf.empty()) return;
    if (!vtp) {
      out.write(buf);
      return;
    }
    const std::size_t np = m.points;
    const char* p = buf.data();
    const void* arrays[4] = {p, p + 8 * np, p + 16 * np, p + 24 * np};
    vtp->add_line(np, reinterpret_cast<const double*>(p + 48 * np), arrays, m.cell_values);
  };
  std::future<void> writing;
  for (std::size_t begin = 0; begin < n; begin += chunk) {
    const std::size_t count = std::min(chunk, n - begin);
    std::vector<Polyline>& lines = line_sets[filling];
    std::vector<std::string>& tx = text[filling];
    std::vector<LineMeta>& mx = meta[filling];
    lines.assign(count, Polyline{});
    tx.resize(count);
    mx.assign(count, LineMeta{});
    // Trace in parallel; number the lines with points in seed order (the CSV's line
    // column); format in parallel.
    auto t0 = SteadyClock::now();
    parallel_for(count, threads, [&](std::size_t j) {
      const std::size_t s = begin + j;
      lines[j] = trace(grid, (*seeds.x)[s], s < seeds.t0->size() ? (*seeds.t0)[s] : 0.0, options);
      check_finite(lines[j], s);
    });
    if (options.progress) options.progress(begin + count, n);
    totals.trace_s += seconds_since(t0);
    t0 = SteadyClock::now();
    for (std::size_t j = 0; j < count; ++j) {
      const Polyline& l = lines[j];
      totals.add(l);
      mx[j] = LineMeta{l.x.size(), l.x.empty() ? -1 : csv_index++,
                       {static_cast<double>(static_cast<int64_t>((*seeds.id)[begin + j])),
                        static_cast<double>(static_cast<int>(l.reason)), static_cast<double>(l.cells)}};
    }
    if (!writer_formats)
      parallel_for(count, threads, [&](std::size_t j) { format_line(tx[j], lines[j], mx[j], begin + j); });
    totals.format_s += seconds_since(t0);
    // The chunk goes to a writer thread, in seed order, so that the disk write overlaps
    // the tracing of the next chunk (one write in flight).
    if (writing.valid()) totals.format_s += help_format(filling ^ 1);
    t0 = SteadyClock::now();
    if (writing.valid()) writing.get();
    totals.wait_s += seconds_since(t0);
    share[filling].reset(writer_formats ? count : 0);
    written_begin = begin;
    writing = std::async(std::launch::async, [&, &L = lines, &T = tx, &M = mx, &S = share[filling], begin, count, head = std::move(pending)] {
      const auto w0 = SteadyClock::now();
      if (!head.empty()) out.write(head);
      std::size_t j = 0;
      if (writer_formats) {
        for (; (j = S.take_front()) != FormatShare::none;) {
          format_line(T[j], L[j], M[j], begin + j);
          write_line(T[j], M[j]);
        }
        j = S.back_end();
      }
      for (; j < count; ++j) write_line(T[j], M[j]);
      write_s += seconds_since(w0);
    });
    pending.clear();
    filling ^= 1;
  }
  if (writing.valid()) totals.format_s += help_format(filling ^ 1);
  auto t0 = SteadyClock::now();
  if (writing.valid()) writing.get();
  totals.wait_s += seconds_since(t0);
  totals.write_s = write_s;
  t0 = SteadyClock::now();
  if (vtp) {
    vtp->finish(out);
  } else {
    if (format == StreamFormat::json && n > 0) pending += "\n]";
    if (format == StreamFormat::json) pending += '\n';
    out.write(pending);
  }
  totals.finish_s = seconds_since(t0);
  return totals;
}

}  // namespace fest::lemtrace_tool
