// fest_hdrmerge_app called with typed options (no argv): a radiance image bracketed by
// the simulated camera (no noise) and merged back with the camera's true response keeps
// the ratio of its radiances, up to 8-bit rounding -- known by construction, since the
// response is only determined up to scale (Debevec & Malik 1997, eq. 3-5).

#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fest::hdrmerge_tool;

// A grey PFM, one row, little-endian (scale -1).
void write_pfm(const fs::path& p, const std::vector<float>& row) {
  std::ofstream out(p, std::ios::binary);
  out << "Pf\n" << row.size() << " 1\n-1.0\n";
  out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
}

// First channel of every pixel of a little-endian PFM.
std::vector<float> read_pfm(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::string magic;
  int w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  in.get();
  const int channels = magic == "PF" ? 3 : 1;
  std::vector<float> all(static_cast<std::size_t>(w * h * channels));
  in.read(reinterpret_cast<char*>(all.data()), static_cast<std::streamsize>(all.size() * sizeof(float)));
  std::vector<float> first;
  for (std::size_t i = 0; i < all.size(); i += static_cast<std::size_t>(channels)) first.push_back(all[i]);
  return first;
}

TEST(HdrmergeApp, BracketThenMergeKeepsRadianceRatios) {
  const fs::path dir = fs::temp_directory_path() / ("fest_hdrmergeapp_" + std::to_string(::getpid()));
  fs::create_directories(dir / "series");
  const std::vector<float> radiance{0.05f, 0.1f, 0.2f, 0.4f};
  write_pfm(dir / "E.pfm", radiance);

  BracketOptions b;
  b.radiance = (dir / "E.pfm").string();
  b.times = {0.25, 0.5, 1.0, 2.0};
  b.camera.noise_dn = 0;
  b.directory = (dir / "series").string();
  b.response_out = (dir / "true.csv").string();
  ASSERT_EQ(run_bracket(b), 0);

  MergeOptions m;
  for (int k = 0; k < 4; ++k) m.series.images.push_back((dir / "series" / ("e0" + std::to_string(k) + ".png")).string());
  m.series.times = b.times;
  m.response_in = b.response_out;
  m.output = (dir / "merged.pfm").string();
  m.to = fest::formats::Format::pfm;
  ASSERT_EQ(run_merge(m), 0);

  const std::vector<float> merged = read_pfm(dir / "merged.pfm");
  ASSERT_EQ(merged.size(), radiance.size());
  for (std::size_t i = 1; i < merged.size(); ++i)
    EXPECT_NEAR(merged[i] / merged[0], radiance[i] / radiance[0], 0.03 * radiance[i] / radiance[0]) << "pixel " << i;
  fs::remove_all(dir);
}

}  // namespace
