#include "core/file_io.hpp"
#include "core/input_name.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <vector>

#include "core/error.hpp"

namespace fest {

namespace {

std::string errno_text() { return std::strerror(errno); }


void write_all(int fd, std::string_view bytes, const std::string& where) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw io_error("cannot write: {} ({})", errno_text(), where);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

}  // namespace

bool is_stdio(std::string_view path) noexcept { return path.empty() || path == "-"; }

std::string input_name(const std::string& path) { return is_stdio(path) ? std::string(standard_input_name) : path; }

std::uint64_t max_input_bytes() {
  // 8 GiB: a third of the project's reference machine; anything larger is almost
  // certainly a corrupt size field or a decompression bomb.
  constexpr std::uint64_t fallback = 8ull << 30;
  const char* env = std::getenv("FEST_MAX_INPUT_BYTES");
  if (env == nullptr || *env == '\0') return fallback;
  char* end = nullptr;
  unsigned long long v = std::strtoull(env, &end, 10);
  if (end == env || *end != '\0' || v == 0) return fallback;
  return v;
}

std::string read_input(const std::string& path) {
  const bool from_stdin = is_stdio(path);
  int fd = from_stdin ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw io_error("cannot open: {} ({})", errno_text(), path);

  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    if (!from_stdin) ::close(fd);
    throw io_error("is a directory ({})", input_name(path));
  }
  const std::uint64_t limit = max_input_bytes();
  std::string data;
  if (S_ISREG(st.st_mode) && st.st_size > 0) {
    if (static_cast<std::uint64_t>(st.st_size) > limit) {
      if (!from_stdin) ::close(fd);
      throw bad_input("input of {} bytes exceeds the limit of {} bytes; raise FEST_MAX_INPUT_BYTES ({})",
                      st.st_size, limit, input_name(path));
    }
    data.reserve(static_cast<std::size_t>(st.st_size));
  }
  std::vector<char> chunk(1 << 16);
  for (;;) {
    ssize_t n = ::read(fd, chunk.data(), chunk.size());
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      int saved = errno;
      if (!from_stdin) ::close(fd);
      errno = saved;
      throw io_error("cannot read: {} ({})", errno_text(), input_name(path));
    }
    if (data.size() + static_cast<std::size_t>(n) > limit) {
      if (!from_stdin) ::close(fd);
      throw bad_input("input exceeds the limit of {} bytes; raise FEST_MAX_INPUT_BYTES ({})", limit,
                      input_name(path));
    }
    data.append(chunk.data(), static_cast<std::size_t>(n));
  }
  if (!from_stdin) ::close(fd);
  return data;
}

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  std::string pattern = path + ".tmp.XXXXXX";
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  int fd = ::mkstemp(buf.data());
  if (fd < 0) throw io_error("cannot create a file next to it: {} ({})", errno_text(), path);
  ::close(fd);
  temp_.assign(buf.data());
}

AtomicFile::~AtomicFile() {
  if (!committed_) ::unlink(temp_.c_str());
}

void AtomicFile::commit() {
  // mkstemp creates 0600; give the result the permissions a plain creat() would.
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(temp_.c_str(), 0666 & ~mask);
  if (::rename(temp_.c_str(), path_.c_str()) != 0)
    throw io_error("cannot rename into place: {} ({})", errno_text(), path_);
  committed_ = true;
}

void write_output(const std::string& path, std::string_view bytes) {
  // One piece: the same temporary-then-rename, device and standard-output rules.
  OutputFile file(path);
  file.write(bytes);
  file.commit();
}

OutputFile::OutputFile(const std::string& path) : path_(path) {
  if (is_stdio(path)) {
    fd_ = STDOUT_FILENO;
    where_ = "standard output";
    return;
  }
  where_ = path;
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) throw io_error("cannot open: {} ({})", errno_text(), path);
    owns_fd_ = true;
    return;
  }
  atomic_ = std::make_unique<AtomicFile>(path);
  fd_ = ::open(atomic_->temp_path().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd_ < 0) throw io_error("cannot open: {} ({})", errno_text(), path);
  owns_fd_ = true;
}

OutputFile::~OutputFile() {
  if (owns_fd_ && fd_ >= 0) ::close(fd_);
  // atomic_'s destructor removes the temporary file when commit() was not reached.
}

void OutputFile::write(std::string_view bytes) {
  if (fd_ < 0) throw io_error("cannot write after commit ({})", where_);
  write_all(fd_, bytes, where_);
}

void OutputFile::copy_from(int fd, std::uint64_t offset, std::uint64_t bytes) {
  if (fd_ < 0) throw io_error("cannot write after commit ({})", where_);
  // The kernel's copy while it takes it. Any refusal (EINVAL for a pipe or a terminal,
  // EXDEV on older kernels across file systems, EBADF for an O_APPEND standard output,
  // ENOSYS...) hands the rest to the loop below, which meets a real error (a full disk)
  // again and reports it in the usual words.
  auto off = static_cast<off_t>(offset);
  while (bytes > 0 && copy_kernel_) {
    const ssize_t n = ::copy_file_range(fd, &off, fd_, nullptr, static_cast<std::size_t>(std::min<std::uint64_t>(bytes, 1u << 30)), 0);
    if (n > 0) {
      bytes -= static_cast<std::uint64_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) throw io_error("cannot copy into {}: the source ended early", where_);
    copy_kernel_ = false;
  }
  std::vector<char> chunk(std::min<std::uint64_t>(bytes, std::uint64_t(4) << 20));
  while (bytes > 0) {
    const ssize_t n = ::pread(fd, chunk.data(), static_cast<std::size_t>(std::min<std::uint64_t>(bytes, chunk.size())), off);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw io_error("cannot read what is copied into {}: {}", where_, errno_text());
    if (n == 0) throw io_error("cannot copy into {}: the source ended early", where_);
    write_all(fd_, std::string_view(chunk.data(), static_cast<std::size_t>(n)), where_);
    off += n;
    bytes -= static_cast<std::uint64_t>(n);
  }
}

void OutputFile::commit() {
  if (owns_fd_ && fd_ >= 0) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw io_error("cannot write: {} ({})", errno_text(), path_);
  }
  fd_ = -1;
  if (atomic_) atomic_->commit();
}

}  // namespace fest
