#pragma once
// The four system calls a V4L2 capture device is driven with -- ioctl, mmap/munmap and
// poll -- behind an interface, so that devices/v4l2_camera.cpp (format negotiation,
// buffer streaming, timeouts, corrupt-frame handling) is tested against a scripted
// driver in tests/unit/test_devices_v4l2_camera.cpp: there is no camera in CI.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace fest::devices {

class VideoNode {
 public:
  virtual ~VideoNode() = default;
  // ioctl(fd, request, arg): 0, or the errno it failed with (EINTR already retried).
  virtual int control(unsigned long request, void* arg) = 0;
  // mmap of a driver buffer (PROT_READ|PROT_WRITE, MAP_SHARED); nullptr on failure.
  virtual void* map(std::size_t length, std::int64_t offset) = 0;
  virtual void unmap(void* address, std::size_t length) = 0;
  // poll for a filled buffer: 1 ready, 0 timed out, -errno on failure.
  virtual int wait_readable(int timeout_ms) = 0;
};

// Opens a device node read-write and non-blocking. Throws device_not_found (5) when it
// does not exist, permission (8) naming the video group, device_error (6) otherwise
// (busy, or another errno, named).
std::unique_ptr<VideoNode> open_video_node(const std::string& path);

}  // namespace fest::devices
