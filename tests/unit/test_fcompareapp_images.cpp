// fest_fcompare_app called directly with typed options: two images that differ by one
// grey level in one pixel, so max_abs is 1 by construction.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "compare/checks.hpp"

namespace fs = std::filesystem;
using namespace fest;

namespace {

class FcompareApp : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fest_fcompareapp_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    // 2x2 binary PGMs: b is a with its third pixel one grey level brighter.
    write(path("a.pgm"), std::string("P5\n2 2\n255\n") + '\x0a' + '\x14' + '\x1e' + '\x28');
    write(path("b.pgm"), std::string("P5\n2 2\n255\n") + '\x0a' + '\x14' + '\x1f' + '\x28');
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static void write(const std::string& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }
  static nlohmann::json read_json(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()));
  }
  fcompare_tool::CompareOptions options() const {
    fcompare_tool::CompareOptions o;
    o.a = path("a.pgm");
    o.b = path("b.pgm");
    o.report = path("r.json");
    o.quiet = true;
    return o;
  }
  fs::path dir_;
};

}  // namespace

TEST_F(FcompareApp, OneGreyLevelApartIsMaxAbsOne) {
  fcompare_tool::CompareOptions o = options();
  EXPECT_EQ(fcompare_tool::compare_command(o), 1);  // default tolerance 0: not within it
  const auto r = read_json(path("r.json"));
  EXPECT_EQ(r.at("kind"), "image");
  EXPECT_DOUBLE_EQ(r.at("metrics").at("max_abs").get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(r.at("metrics").at("rmse").get<double>(), 0.5);  // sqrt(1/4)
}

TEST_F(FcompareApp, ToleranceOneAccepts) {
  fcompare_tool::CompareOptions o = options();
  o.tol = 1;
  o.tol_given = true;
  EXPECT_EQ(fcompare_tool::compare_command(o), 0);
}

TEST_F(FcompareApp, ThresholdOnTheFamilyReplacesTheDefault) {
  fcompare_tool::CompareOptions o = options();
  o.thresholds.push_back(compare::Check{"rmse", true, 0.5});
  EXPECT_EQ(fcompare_tool::compare_command(o), 0);
  o.thresholds = {compare::Check{"rmse", true, 0.4}};
  EXPECT_EQ(fcompare_tool::compare_command(o), 1);
}

TEST_F(FcompareApp, SameFileIsWithinZero) {
  fcompare_tool::CompareOptions o = options();
  o.b = o.a;
  EXPECT_EQ(fcompare_tool::compare_command(o), 0);
  EXPECT_DOUBLE_EQ(read_json(path("r.json")).at("metrics").at("max_abs").get<double>(), 0.0);
}
