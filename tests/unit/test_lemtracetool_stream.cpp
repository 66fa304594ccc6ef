// Streamed trace output (tools/lemtrace/line_stream.hpp): the bytes do not depend on the
// chunk size or the thread count, and equal a whole-result reference written
// independently (trace_all, then printf's "%.17g"). Seeds outside the grid (no points,
// no CSV rows) sit between the others to check the line numbering.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/file_io.hpp"
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
                  LineTotals* totals = nullptr) {
    const std::string path = (dir_ / "out.txt").string();
    fest::OutputFile out(path);
    const LineTotals t = stream_lines(grid, StreamSeeds{&c.x, &c.t0, &c.id}, TraceOptions{}, threads, f, out, chunk);
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

}  // namespace
