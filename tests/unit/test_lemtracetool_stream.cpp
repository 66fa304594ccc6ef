// Streamed trace output (tools/lemtrace/line_stream.hpp): the bytes do not depend on the
// chunk size or the thread count, and equal a whole-result reference written
// independently (trace_all, then printf's "%.17g"). Seeds outside the grid (no points,
// no CSV rows) sit between the others to check the line numbering.

#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <filesystem>

#include "core/file_io.hpp"
#include "core/number_text.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "dataset_bridge.hpp"
#include "lemtrace/generate.hpp"
#include "line_stream.hpp"

#include <nlohmann/json.hpp>

namespace {

using namespace fest::lemtrace_tool;
namespace fs = std::filesystem;

FieldGrid helix_grid() {
  GenOptions o;
  o.kind = "helix";
  o.n = 5;
  o.jitter = 0.2;
  o.seed = 3;
  GeneratedGrid g = generate(o);
  TetMesh mesh = build_tet_mesh(g.points, g.vectors, g.cells, BuildOptions{}, nullptr);
  return FieldGrid(std::move(mesh), ClassifyParams{}, Precompute::lazy, 1);
}

struct Case {
  std::vector<Vec3> x;
  std::vector<double> t0, id;
};

Case seeds() {
  Case c;
  for (int i = 0; i < 23; ++i) {
    const bool outside = i % 7 == 3;
    c.x.emplace_back(outside ? 5.0 : 0.2 + 0.03 * i, 0.0, -0.9);
    c.t0.push_back(0.0);
    c.id.push_back(i % 5 == 0 ? 0.25 * i : static_cast<double>(i));
  }
  return c;
}

std::string reference_csv(const FieldGrid& grid, const Case& c, const TraceOptions& o) {
  const std::vector<Polyline> lines = trace_all(grid, c.x, c.t0, o, 1);
  std::string out = "line,seed,i,x,y,z,t,cell,type,speed\n";
  char buf[512];
  int index = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const Polyline& line = lines[l];
    if (line.x.empty()) continue;
    for (std::size_t i = 0; i < line.x.size(); ++i) {
      const Vec3 v = velocity_at(grid, line.cell[i], line.x[i]);
      std::snprintf(buf, sizeof buf, "%d,%g,%zu,%.17g,%.17g,%.17g,%.17g,%lld,%d,%.17g\n", index, c.id[l], i,
                    line.x[i][0], line.x[i][1], line.x[i][2], line.t[i],
                    static_cast<long long>(grid.mesh().source_cell[static_cast<std::size_t>(line.cell[i])]), static_cast<int>(line.type[i]),
                    v.norm());
      out += buf;
    }
    ++index;
  }
  return out;
}

class Stream : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fest_lemtrace_stream_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string run(const FieldGrid& grid, const Case& c, StreamFormat f, int threads, std::size_t chunk,
                  LineTotals* totals = nullptr, const std::string& options = {}) {
    const std::string path = (dir_ / "out.txt").string();
    fest::OutputFile out(path);
    const LineTotals t = stream_lines(grid, StreamSeeds{&c.x, &c.t0, &c.id}, TraceOptions{}, threads, f, out, chunk,
                                      VtpSettings{dir_.string(), options});
    out.commit();
    if (totals) *totals = t;
    return fest::read_input(path);
  }
  fs::path dir_;
};

TEST_F(Stream, CsvEqualsTheWholeResultReferenceForAnyChunkAndThreads) {
  const FieldGrid grid = helix_grid();
  const Case c = seeds();
  const std::string want = reference_csv(grid, c, TraceOptions{});
  for (int threads : {1, 2, 3})
    for (std::size_t chunk : {1, 2, 5, 64}) EXPECT_EQ(run(grid, c, StreamFormat::csv, threads, chunk), want)
        << threads << " threads, chunk " << chunk;
}

TEST_F(Stream, JsonIsOneDocumentAndIndependentOfChunkAndThreads) {
  const FieldGrid grid = helix_grid();
  const Case c = seeds();
  LineTotals totals;
  const std::string want = run(grid, c, StreamFormat::json, 1, 1000, &totals);
  const nlohmann::json doc = nlohmann::json::parse(want);
  ASSERT_EQ(doc.size(), c.x.size());
  EXPECT_EQ(doc.dump(1) + "\n", want);  // the layout of the whole-document dump
  EXPECT_EQ(totals.lines, static_cast<int64_t>(c.x.size()));
  for (int threads : {2, 3})
    for (std::size_t chunk : {1, 4}) EXPECT_EQ(run(grid, c, StreamFormat::json, threads, chunk), want);
}

TEST_F(Stream, NoSeedsGiveHeaderOrEmptyArray) {
  const FieldGrid grid = helix_grid();
  const Case none;
  EXPECT_EQ(run(grid, none, StreamFormat::csv, 2, 0), "line,seed,i,x,y,z,t,cell,type,speed\n");
  EXPECT_EQ(run(grid, none, StreamFormat::json, 2, 0), "[]\n");
}

// The VTP written as the lines come (per-point arrays through temporaries, header last)
// is the file VTK's vtkXMLPolyDataWriter writes for the whole dataset (formats/dataset,
// appended raw): same counts, ranges, offsets and blocks, for any chunk and thread count.
TEST_F(Stream, VtpIsTheFileVtksWriterMakesForAnyChunkAndThreads) {
  const FieldGrid grid = helix_grid();
  Case c = seeds();
  c.id[4] = -7.0;  // a negative seed id in SeedId's range
  const std::string options = "h.vtu --seed-line 0.2,0,-0.9:0.86,0,-0.9:23 -o lines.vtp";
  const std::vector<Polyline> lines = trace_all(grid, c.x, c.t0, TraceOptions{}, 1);
  const std::string want = fest::formats::write_dataset(polylines_to_dataset(grid, LineSet{&lines, &c.id, options}),
                                                        fest::formats::Format::vtp);
  for (int threads : {1, 2, 3})
    for (std::size_t chunk : {1, 5, 64})
      EXPECT_EQ(run(grid, c, StreamFormat::vtp, threads, chunk, nullptr, options), want)
          << threads << " threads, chunk " << chunk;
  // No temporaries left beside the output (they were unlinked from the start).
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.path().filename() != "out.txt";
  EXPECT_EQ(files, 0u);
}

TEST_F(Stream, VtpWithoutLinesIsVtksEmptyFile) {
  const FieldGrid grid = helix_grid();
  Case outside;
  outside.x = {Vec3(5, 5, 5), Vec3(-4, 0, 0)};
  outside.t0 = {0, 0};
  outside.id = {1, 2};
  const std::vector<Polyline> lines = trace_all(grid, outside.x, outside.t0, TraceOptions{}, 1);
  const std::string want = fest::formats::write_dataset(polylines_to_dataset(grid, LineSet{&lines, &outside.id, "x"}),
                                                        fest::formats::Format::vtp);
  EXPECT_EQ(run(grid, outside, StreamFormat::vtp, 2, 0, nullptr, "x"), want);
}

// Every number of the CSV parses back (strtod) to the very double it was written from:
// the coordinates and time of each traced point and its speed.
TEST_F(Stream, CsvNumbersParseBackExactly) {
  const FieldGrid grid = helix_grid();
  const Case c = seeds();
  const std::vector<Polyline> lines = trace_all(grid, c.x, c.t0, TraceOptions{}, 1);
  const std::string text = run(grid, c, StreamFormat::csv, 2, 3);
  std::vector<std::array<double, 5>> want;
  for (const Polyline& l : lines)
    for (std::size_t i = 0; i < l.x.size(); ++i)
      want.push_back({l.x[i][0], l.x[i][1], l.x[i][2], l.t[i], velocity_at(grid, l.cell[i], l.x[i]).norm()});
  std::size_t row = 0, pos = text.find('\n') + 1;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    std::vector<std::string> f;
    std::size_t a = pos;
    for (std::size_t b; (b = text.find(',', a)) < end; a = b + 1) f.push_back(text.substr(a, b - a));
    f.push_back(text.substr(a, end - a));
    ASSERT_EQ(f.size(), 10u);
    ASSERT_LT(row, want.size());
    const int column[5] = {3, 4, 5, 6, 9};
    for (int k = 0; k < 5; ++k) {
      const double back = std::strtod(f[std::size_t(column[k])].c_str(), nullptr);
      EXPECT_EQ(std::memcmp(&back, &want[row][std::size_t(k)], sizeof back), 0)
          << "row " << row << " column " << column[k] << ": " << f[std::size_t(column[k])];
    }
    ++row;
    pos = end + 1;
  }
  EXPECT_EQ(row, want.size());
}

// The number writer itself (fest::write_g17, the CSV's "%.17g"): strtod gives back the
// same bits for random bit patterns over the whole range, both of its paths (the integer
// one for 1e-15 <= |x| < 1e16, the library's elsewhere), and the edges.
TEST(CsvNumberWriter, SeventeenDigitsParseBackToTheSameBits) {
  std::mt19937_64 rng(23);
  auto round_trips = [](double x) {
    char buf[48];
    *fest::write_g17(buf, x) = '\0';
    const double back = std::strtod(buf, nullptr);
    return std::memcmp(&back, &x, sizeof x) == 0;
  };
  std::size_t bad = 0;
  for (int i = 0; i < 100000; ++i) {
    uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    bad += !round_trips(x);
    // The same significand at exponents where coordinates and times live.
    bits = (bits & 0x800fffffffffffffull) | (uint64_t(1023 + int(rng() % 80) - 40) << 52);
    std::memcpy(&x, &bits, sizeof x);
    bad += !round_trips(x);
  }
  for (double x : {0.0, -0.0, 1e-15, 1e16, 9.999999999999999e15, 1e-16, 5e-324, 1.7976931348623157e308, 0.1, 38.0,
                   -0.9, 2.2250738585072014e-308})
    bad += !round_trips(x) + !round_trips(std::nextafter(x, 1e300)) + !round_trips(std::nextafter(x, -1e300));
  EXPECT_EQ(bad, 0u);
}

}  // namespace
