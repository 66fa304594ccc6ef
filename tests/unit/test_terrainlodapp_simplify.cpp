// fest_terrainlod_app called with typed options (no argv): a planar DEM simplifies to
// two triangles over its four corners, whatever the bound, because a plane is exact on
// any triangulation of its corners (docs/terrainlod.md, simplify).

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fest::terrainlod_tool;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(TerrainlodApp, PlanarDemSimplifiesToTwoTriangles) {
  const fs::path dir = fs::temp_directory_path() / ("fest_terrainlodapp_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    // z = 2x + 3y on a 9 x 9 grid (ESRI ASCII: rows from the north).
    std::ofstream out(dir / "plane.asc");
    out << "ncols 9\nnrows 9\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
    for (int r = 0; r < 9; ++r) {
      for (int c = 0; c < 9; ++c) out << (c ? " " : "") << 2 * c + 3 * (8 - r);
      out << "\n";
    }
  }
  for (const auto start : {fest::terrainlod::StartRule::rtin, fest::terrainlod::StartRule::lattice}) {
    SimplifyArgs args;
    args.dem.path = (dir / "plane.asc").string();
    args.max_error = 0.001;
    args.start = start;
    args.output = (dir / "plane.off").string();
    args.report = (dir / "report.json").string();
    ASSERT_EQ(run_simplify(args), 0);
    const nlohmann::json report = nlohmann::json::parse(slurp(dir / "report.json"));
    EXPECT_EQ(report["triangles"], 2);
    EXPECT_EQ(report["vertices"], 4);
    EXPECT_EQ(report["start"], start == fest::terrainlod::StartRule::rtin ? "rtin" : "lattice");
    EXPECT_LE(report["measured_error"].get<double>(), 1e-9);
  }
  fs::remove_all(dir);
}

}  // namespace
