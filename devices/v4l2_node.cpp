#include "devices/v4l2_node.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace fest::devices {

namespace {

class SystemVideoNode : public VideoNode {
 public:
  explicit SystemVideoNode(int fd) : fd_(fd) {}
  ~SystemVideoNode() override { ::close(fd_); }
  SystemVideoNode(const SystemVideoNode&) = delete;
  SystemVideoNode& operator=(const SystemVideoNode&) = delete;

  int control(unsigned long request, void* arg) override {
    int r;
    do r = ::ioctl(fd_, request, arg);
    while (r == -1 && errno == EINTR);
    return r == -1 ? errno : 0;
  }
  void* map(std::size_t length, std::int64_t offset) override {
    void* p = ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, off_t(offset));
    return p == MAP_FAILED ? nullptr : p;
  }
  void unmap(void* address, std::size_t length) override { ::munmap(address, length); }
  int wait_readable(int timeout_ms) override {
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, timeout_ms);
    if (r < 0) return -errno;
    if (r > 0 && (p.revents & (POLLERR | POLLHUP | POLLNVAL)) && !(p.revents & POLLIN)) return -EIO;
    return r;
  }

 private:
  int fd_;
};

}  // namespace

std::unique_ptr<VideoNode> open_video_node(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd >= 0) return std::make_unique<SystemVideoNode>(fd);
  const int e = errno;
  if (e == ENOENT || e == ENODEV || e == ENXIO) throw make_error(Status::device_not_found, "v4l2 camera: no device {}", path);
  if (e == EACCES || e == EPERM)
    throw make_error(Status::permission,
                     "v4l2 camera: permission denied on {} (add the user to the 'video' group: usermod -aG video $USER)",
                     path);
  if (e == EBUSY) throw make_error(Status::device_error, "v4l2 camera: cannot open {} (busy: another program uses it)", path);
  throw make_error(Status::device_error, "v4l2 camera: cannot open {} ({})", path, std::strerror(e));
}

}  // namespace fest::devices
