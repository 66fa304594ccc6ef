#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/file_io.hpp"

namespace fs = std::filesystem;

class FileIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fest_file_io_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(FileIo, WriteThenReadIsIdentical) {
  const std::string path = (dir_ / "a.bin").string();
  std::string bytes("a\0b\xff", 4);
  fest::write_output(path, bytes);
  EXPECT_EQ(fest::read_input(path), bytes);
}

TEST_F(FileIo, AtomicWriteLeavesNoTemporaryAndReplaces) {
  const std::string path = (dir_ / "out.txt").string();
  fest::write_output(path, "old");
  fest::write_output(path, "new");
  EXPECT_EQ(fest::read_input(path), "new");
  std::size_t files = 0;
  for (auto& e : fs::directory_iterator(dir_)) {
    (void)e;
    ++files;
  }
  EXPECT_EQ(files, 1u);
}

TEST_F(FileIo, UncommittedAtomicFileIsRemoved) {
  const std::string path = (dir_ / "never.txt").string();
  std::string temp;
  {
    fest::AtomicFile f(path);
    temp = f.temp_path();
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(FileIo, MissingFileIsAnIoError) {
  try {
    fest::read_input((dir_ / "missing").string());
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::io);
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
  }
}

TEST_F(FileIo, DirectoryIsAnIoError) {
  try {
    fest::read_input(dir_.string());
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::io);
  }
}

TEST_F(FileIo, UnwritableDestinationIsAnIoError) {
  try {
    fest::write_output((dir_ / "no" / "such" / "dir.txt").string(), "x");
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::io);
  }
}

TEST_F(FileIo, InputLargerThanTheLimitIsRefused) {
  const std::string path = (dir_ / "big").string();
  fest::write_output(path, std::string(100, 'x'));
  ::setenv("FEST_MAX_INPUT_BYTES", "50", 1);
  try {
    fest::read_input(path);
    ::unsetenv("FEST_MAX_INPUT_BYTES");
    FAIL();
  } catch (const fest::Error& e) {
    ::unsetenv("FEST_MAX_INPUT_BYTES");
    EXPECT_EQ(e.status(), fest::Status::bad_input);
  }
}

TEST(FileIoNames, DashAndEmptyMeanStandardStreams) {
  EXPECT_TRUE(fest::is_stdio("-"));
  EXPECT_TRUE(fest::is_stdio(""));
  EXPECT_FALSE(fest::is_stdio("./-"));
}
