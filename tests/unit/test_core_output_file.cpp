// OutputFile: an output written in pieces keeps write_output's guarantees: nothing at
// the destination until commit(), an earlier file left untouched when abandoned, no
// temporary left behind either way.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "core/file_io.hpp"

namespace fs = std::filesystem;

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fest_output_file_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::size_t files() const {
    std::size_t n = 0;
    for (auto& e : fs::directory_iterator(dir_)) {
      (void)e;
      ++n;
    }
    return n;
  }
  fs::path dir_;
};

TEST_F(OutputFileTest, PiecesAppearOnlyAtCommit) {
  const std::string path = (dir_ / "out.csv").string();
  {
    fest::OutputFile out(path);
    out.write("a,b\n");
    out.write("1,2\n");
    EXPECT_FALSE(fs::exists(path));
    out.commit();
  }
  EXPECT_EQ(fest::read_input(path), "a,b\n1,2\n");
  EXPECT_EQ(files(), 1u);
}

TEST_F(OutputFileTest, AbandonedOutputLeavesTheOldFile) {
  const std::string path = (dir_ / "out.csv").string();
  fest::write_output(path, "old");
  try {
    fest::OutputFile out(path);
    out.write("partial");
    throw 1;  // an error part-way through
  } catch (int) {
  }
  EXPECT_EQ(fest::read_input(path), "old");
  EXPECT_EQ(files(), 1u);
}

TEST_F(OutputFileTest, DeviceIsWrittenInPlace) {
  fest::OutputFile out("/dev/null");
  out.write("discarded");
  out.commit();
  EXPECT_TRUE(fs::exists("/dev/null"));
}
