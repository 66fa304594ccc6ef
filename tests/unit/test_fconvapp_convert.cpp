// fest_fconv_app called directly with typed options: a PPM whose pixels are known by
// construction goes to PNG and back; PNG is lossless, so the pixels come back unchanged.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "formats/input.hpp"

namespace fs = std::filesystem;
using namespace fest;

namespace {

class FconvApp : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fest_fconvapp_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static void write(const std::string& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }
  static std::string read(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  }
  fs::path dir_;
};

// A 3x2 binary PPM: six distinct RGB pixels (0..255 all used).
std::string pixels() {
  std::string px;
  for (int i = 0; i < 18; ++i) px += static_cast<char>(i * 15);
  return px;
}
const std::string kHeader = "P6\n3 2\n255\n";

}  // namespace

TEST_F(FconvApp, PpmToPngToPpmKeepsEveryPixel) {
  write(path("a.ppm"), kHeader + pixels());
  fconv_tool::ConvertOptions to_png;
  to_png.input = path("a.ppm");
  to_png.output = path("a.png");
  ASSERT_EQ(fconv_tool::convert_command(to_png), 0);
  EXPECT_EQ(formats::load_input(path("a.png")).format, formats::Format::png);

  fconv_tool::ConvertOptions to_ppm;
  to_ppm.input = path("a.png");
  to_ppm.output = path("b.out");  // no extension: the format comes from `to`
  to_ppm.to = formats::OutputFormat{formats::Format::ppm, false};
  ASSERT_EQ(fconv_tool::convert_command(to_ppm), 0);
  const std::string back = read(path("b.out"));
  ASSERT_GE(back.size(), pixels().size());
  EXPECT_EQ(back.substr(back.size() - pixels().size()), pixels());
  EXPECT_EQ(back.compare(0, 2, "P6"), 0);
}

TEST_F(FconvApp, InfoDescribesTheImage) {
  write(path("a.ppm"), kHeader + pixels());
  fconv_tool::InfoOptions o{path("a.ppm"), path("a.json")};
  ASSERT_EQ(fconv_tool::info_command(o), 0);
  const auto j = nlohmann::json::parse(read(path("a.json")));
  EXPECT_EQ(j.at("kind"), "image");
  EXPECT_EQ(j.at("bytes"), kHeader.size() + 18);
}

TEST_F(FconvApp, ImageToMeshFormatIsAUsageError) {
  write(path("a.ppm"), kHeader + pixels());
  fconv_tool::ConvertOptions o;
  o.input = path("a.ppm");
  o.output = path("a.ply");
  EXPECT_ANY_THROW(fconv_tool::convert_command(o));
  EXPECT_FALSE(fs::exists(path("a.ply")));
}
