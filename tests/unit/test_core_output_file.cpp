// OutputFile: an output written in pieces keeps write_output's guarantees: nothing at
// the destination until commit(), an earlier file left untouched when abandoned, no
// temporary left behind either way.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <thread>

#include "core/error.hpp"
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

namespace {

// A source file of `n` bytes whose byte i is i * 7 + 3 (mod 256): any shift or gap in a
// copy shows.
int source_fd(const fs::path& path, std::size_t n, std::string& bytes) {
  bytes.resize(n);
  for (std::size_t i = 0; i < n; ++i) bytes[i] = static_cast<char>(i * 7 + 3);
  fest::write_output(path.string(), bytes);
  return ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
}

}  // namespace

TEST_F(OutputFileTest, CopyFromAppendsTheRangeBetweenWrites) {
  std::string bytes;
  const int fd = source_fd(dir_ / "src.bin", (std::size_t(5) << 20) + 17, bytes);  // over one 4 MiB chunk
  ASSERT_GE(fd, 0);
  const std::string path = (dir_ / "out.bin").string();
  {
    fest::OutputFile out(path);
    out.write("head");
    out.copy_from(fd, 11, bytes.size() - 11);
    out.write("mid");
    out.copy_from(fd, 0, 5);
    out.copy_from(fd, 3, 0);
    out.write("tail");
    out.commit();
  }
  EXPECT_EQ(fest::read_input(path), "head" + bytes.substr(11) + "mid" + bytes.substr(0, 5) + "tail");
  ::close(fd);
}

TEST_F(OutputFileTest, CopyFromIntoAPipeTakesTheReadWritePath) {
  // copy_file_range refuses a pipe (EINVAL): the copy must fall back and still arrive whole.
  std::string bytes;
  const int fd = source_fd(dir_ / "src.bin", 300000, bytes);
  ASSERT_GE(fd, 0);
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = fest::read_input(fifo.string()); });
  {
    fest::OutputFile out(fifo.string());
    out.write("x");
    out.copy_from(fd, 100, bytes.size() - 100);
    out.commit();
  }
  reader.join();
  EXPECT_EQ(got, "x" + bytes.substr(100));
  ::close(fd);
}

TEST_F(OutputFileTest, CopyFromAShortSourceIsAnIoError) {
  std::string bytes;
  const int fd = source_fd(dir_ / "src.bin", 1000, bytes);
  ASSERT_GE(fd, 0);
  const std::string path = (dir_ / "out.bin").string();
  try {
    fest::OutputFile out(path);
    out.copy_from(fd, 900, 200);  // 100 bytes are there, 200 asked for
    FAIL() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::io);
    EXPECT_NE(std::string(e.what()).find("ended early"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  ::close(fd);
}
