#pragma once
// Whole-file input and atomic output: the only file access in lib/ (README "Layout" keeps the
// algorithms free of I/O; tools and formats/ call these).
//
// A path of "-" or "" means standard input / standard output.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace fest {

bool is_stdio(std::string_view path) noexcept;

// Upper bound on what one input may occupy in memory once read (and, in formats/, once
// decompressed). Overridden by the environment variable FEST_MAX_INPUT_BYTES.
std::uint64_t max_input_bytes();

// Reads a whole file (or standard input) into memory. Throws Status::io when it cannot be
// opened or read, Status::bad_input when it is larger than max_input_bytes().
std::string read_input(const std::string& path);

// Writes bytes to a file atomically (a temporary name in the same folder, renamed over
// the destination once complete and flushed), or to standard output. Throws Status::io.
void write_output(const std::string& path, std::string_view bytes);

// Lower-level piece of write_output for callers that produce a file by other means
// (a library that insists on writing to a path): gives a temporary path next to
// `path`; commit() renames it into place, the destructor removes it otherwise.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& temp_path() const noexcept { return temp_; }
  void commit();

 private:
  std::string path_;
  std::string temp_;
  bool committed_ = false;
};

// An output written in pieces (a tool streaming results as they are finished) with the
// guarantees of write_output: to a temporary file next to `path`, renamed into place by
// commit(); removed, leaving any earlier file untouched, when destroyed uncommitted (an
// error part-way). Standard output and devices are written as the pieces come. Throws
// Status::io.
class OutputFile {
 public:
  explicit OutputFile(const std::string& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(std::string_view bytes);
  // Appends `bytes` bytes of the open file `fd`, read from `offset` on (its own file
  // position is not used). Into a regular file the kernel copies them (copy_file_range:
  // no trip through user memory, which halved the time of lemtrace's VTP blocks); into a
  // pipe, or where the kernel cannot, they are read and written. Throws Status::io, also
  // when `fd` ends early.
  void copy_from(int fd, std::uint64_t offset, std::uint64_t bytes);
  void commit();

 private:
  std::string path_;
  std::string where_;
  int fd_ = -1;
  bool owns_fd_ = false;
  bool copy_kernel_ = true;  // until copy_file_range says it cannot
  std::unique_ptr<AtomicFile> atomic_;
};

}  // namespace fest
