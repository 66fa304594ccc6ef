#include "formats/image/netpbm_rows.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/image/image_headers.hpp"

namespace fest::formats {

namespace {

// Enough for any header fest writes and most others; a longer header (pages of
// comments) is simply read whole by the caller.
constexpr std::size_t header_probe = 64 * 1024;

bool host_little_endian() {
  const std::uint16_t probe = 1;
  std::uint8_t first;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

// pread until n bytes are in or the file ends; returns the count read.
std::size_t read_at(int fd, void* dst, std::size_t n, std::uint64_t offset, const std::string& path) {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fd, static_cast<char*>(dst) + done, n - done, static_cast<off_t>(offset + done));
    if (got < 0) {
      if (errno == EINTR) continue;
      throw io_error("cannot read: {} ({})", std::strerror(errno), path);
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

constexpr std::size_t max_parts = 512;  // below every system's IOV_MAX (1024 on Linux)

// preadv until the parts are full or the file ends; returns the count read. `parts` is
// consumed.
std::size_t read_scattered(int fd, std::vector<iovec>& parts, std::uint64_t offset, const std::string& path) {
  std::size_t done = 0, at = 0;
  while (at < parts.size()) {
    const ssize_t got = ::preadv(fd, parts.data() + at, static_cast<int>(parts.size() - at), static_cast<off_t>(offset + done));
    if (got < 0) {
      if (errno == EINTR) continue;
      throw io_error("cannot read: {} ({})", std::strerror(errno), path);
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
    for (std::size_t left = static_cast<std::size_t>(got); left > 0 && at < parts.size();) {
      const std::size_t take = std::min(left, parts[at].iov_len);
      parts[at].iov_base = static_cast<char*>(parts[at].iov_base) + take;
      parts[at].iov_len -= take;
      left -= take;
      if (parts[at].iov_len == 0) ++at;
    }
  }
  return done;
}

}  // namespace

std::unique_ptr<NetpbmRowFile> NetpbmRowFile::open(const std::string& path) {
  if (is_stdio(path)) return nullptr;
  // Only regular files are opened here: opening a named pipe and closing it again would
  // take its data from the reader that follows (or block).
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return nullptr;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return nullptr;  // the whole-file reader gives the message
  std::unique_ptr<NetpbmRowFile> f(new NetpbmRowFile);
  f->fd_ = fd;
  f->path_ = path;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return nullptr;
  std::string head(std::min<std::uint64_t>(header_probe, static_cast<std::uint64_t>(st.st_size)), '\0');
  head.resize(read_at(fd, head.data(), head.size(), 0, path));
  if (head.size() < 3 || head[0] != 'P') return nullptr;
  const char magic = head[1];
  const bool pfm = magic == 'F' || magic == 'f';
  if (!pfm && magic != '5' && magic != '6' && magic != '7') return nullptr;
  image_detail::NetpbmLayout layout;
  try {
    layout = image_detail::read_netpbm_layout(head, pfm, static_cast<std::uint64_t>(st.st_size));
  } catch (const Error& e) {
    // A header longer than the probe: the whole-file reader decides.
    if (head.size() < static_cast<std::size_t>(st.st_size)) return nullptr;
    throw Error(e.status(), with_location(e.what(), path));
  }
  if (!pfm && layout.maxval != 255 && layout.maxval != 65535) return nullptr;
  f->header_ = layout.header;
  f->data_offset_ = layout.data_offset;
  f->pfm_ = pfm;
  // Netpbm's 16-bit samples are big-endian; PFM's order is the sign of its scale.
  const bool file_big = pfm ? layout.big_endian : true;
  f->swap_ = (layout.header.bits > 8) && file_big == host_little_endian();
  return f;
}

NetpbmRowFile::~NetpbmRowFile() {
  if (fd_ >= 0) ::close(fd_);
}

int NetpbmRowFile::cv_type() const {
  const int depth = header_.is_float ? CV_32F : header_.bits == 16 ? CV_16U : CV_8U;
  return CV_MAKETYPE(depth, header_.channels);
}

ColorSpace NetpbmRowFile::color_space() const { return pfm_ ? ColorSpace::linear : Image{}.color_space; }

std::size_t NetpbmRowFile::row_bytes() const {
  return static_cast<std::size_t>(header_.width) * static_cast<std::size_t>(header_.channels) *
         static_cast<std::size_t>(header_.bits / 8);
}

void NetpbmRowFile::read_rows(int first, int last, void* dst) const {
  const std::size_t row = row_bytes(), n = static_cast<std::size_t>(last - first);
  auto* out = static_cast<char*>(dst);
  if (!pfm_) {  // rows top to bottom: one read
    if (read_at(fd_, out, n * row, data_offset_ + static_cast<std::uint64_t>(first) * row, path_) != n * row)
      throw io_error("cannot read: the file ended early, it changed while being read ({})", path_);
  } else {  // PFM stores the bottom row first: one scattered read puts each file row in place
    const std::uint64_t file_first = static_cast<std::uint64_t>(header_.height - last);
    std::vector<iovec> parts;
    for (std::size_t i = 0; i < n; i += max_parts) {
      const std::size_t k = std::min(max_parts, n - i);  // file rows file_first + i ... + i + k
      parts.resize(k);
      for (std::size_t j = 0; j < k; ++j) parts[j] = {out + (n - 1 - i - j) * row, row};
      if (read_scattered(fd_, parts, data_offset_ + (file_first + i) * row, path_) != k * row)
        throw io_error("cannot read: the file ended early, it changed while being read ({})", path_);
    }
  }
  if (!swap_) return;
  const std::size_t bytes = header_.bits / 8, count = n * row / bytes;
  auto* p = reinterpret_cast<unsigned char*>(out);
  if (bytes == 2)
    for (std::size_t i = 0; i < count; ++i, p += 2) std::swap(p[0], p[1]);
  else
    for (std::size_t i = 0; i < count; ++i, p += 4) {
      std::swap(p[0], p[3]);
      std::swap(p[1], p[2]);
    }
}

}  // namespace fest::formats
