// libv4l2mock.so: a virtual V4L2 camera for the CLI tests, loaded with LD_PRELOAD
// (there is no camera and no v4l2loopback module in CI). It intercepts open(), ioctl(),
// mmap(), munmap(), poll() and close() on the one path named by V4L2MOCK_PATH (a plain
// file the test creates, so the tool's existence and permission checks see a node) and
// answers them as a UVC camera would:
//
//   VIDIOC_QUERYCAP  "fest virtual camera", video capture + streaming
//   VIDIOC_ENUM_FMT  V4L2MOCK_FORMATS (default "MJPG,YUYV"; only YUYV and GREY frames
//                    are generated, MJPG is listed to check the tool prefers YUYV)
//   G_FMT/S_FMT      any size up to 640 x 480 (default 32 x 16), bytesperline padded by
//                    8 bytes to check the tool honours the stride
//   S_CTRL           exposure_absolute: a frame's luma is Y = 16 + min(219, units) with
//                    neutral chroma, so a shot's grey level is 255/219 (Y - 16) by the
//                    BT.601 equations; a new exposure reaches the sensor two frames
//                    late (the frame in flight and the next keep the old one), as
//                    with UVC sensors that need the station's flush_frames
//   REQBUFS/QUERYBUF/QBUF/DQBUF/STREAMON/STREAMOFF  mmap streaming over heap buffers
//   poll             a frame "arrives" at every poll; DQBUF before that is EAGAIN;
//                    with V4L2MOCK_STALL=1 none ever does (a camera that stopped)
//
// V4L2MOCK_LOG, when set, receives one line per ioctl the tool made.
#include <dlfcn.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Camera {
  int fd = -1;
  std::vector<std::uint32_t> formats;
  std::uint32_t pixfmt = V4L2_PIX_FMT_YUYV;
  std::uint32_t width = 32, height = 16;
  std::vector<std::vector<unsigned char>> buffers;
  std::deque<unsigned> queued;
  bool streaming = false;
  bool arrived = false;  // a frame is ready for DQBUF
  long frame = 0;        // frames delivered so far
  int units = 100;       // exposure in effect on the sensor
  std::deque<std::pair<long, int>> pending;  // (first frame, units) not yet in effect

  std::uint32_t row() const { return (pixfmt == V4L2_PIX_FMT_GREY ? 1 : 2) * width + 8; }
  std::uint32_t size_image() const { return row() * height; }
} cam;

template <typename F>
F real(const char* name) {
  return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

void log_line(const char* what, long value = 0) {
  if (const char* path = std::getenv("V4L2MOCK_LOG")) {
    if (FILE* f = std::fopen(path, "a")) {
      std::fprintf(f, "%s %ld\n", what, value);
      std::fclose(f);
    }
  }
}

bool is_mocked_path(const char* path) {
  const char* mock = std::getenv("V4L2MOCK_PATH");
  return mock && path && std::strcmp(path, mock) == 0;
}

void configure() {
  const char* list = std::getenv("V4L2MOCK_FORMATS");
  std::string s = list ? list : "MJPG,YUYV";
  cam.formats.clear();
  for (std::size_t at = 0; at < s.size();) {
    std::size_t comma = s.find(',', at);
    if (comma == std::string::npos) comma = s.size();
    std::string name = s.substr(at, comma - at) + "    ";
    cam.formats.push_back(v4l2_fourcc(name[0], name[1], name[2], name[3]));
    at = comma + 1;
  }
}

void fill(std::vector<unsigned char>& buf) {
  while (!cam.pending.empty() && cam.frame >= cam.pending.front().first) {
    cam.units = cam.pending.front().second;
    cam.pending.pop_front();
  }
  const unsigned char y = static_cast<unsigned char>(16 + std::min(219, cam.units));
  std::fill(buf.begin(), buf.end(), 0xEE);  // padding stays visible
  for (std::uint32_t r = 0; r < cam.height; ++r) {
    unsigned char* p = buf.data() + std::size_t(r) * cam.row();
    if (cam.pixfmt == V4L2_PIX_FMT_GREY) {
      std::memset(p, y, cam.width);
    } else {
      for (std::uint32_t c = 0; c < cam.width; c += 2, p += 4) p[0] = y, p[1] = 128, p[2] = y, p[3] = 128;
    }
  }
  ++cam.frame;
}

int handle(unsigned long request, void* arg) {
  switch (request) {
    case VIDIOC_QUERYCAP: {
      auto* c = static_cast<v4l2_capability*>(arg);
      std::memset(c, 0, sizeof *c);
      std::strcpy(reinterpret_cast<char*>(c->driver), "v4l2mock");
      std::strcpy(reinterpret_cast<char*>(c->card), "fest virtual camera");
      c->device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
      c->capabilities = c->device_caps | V4L2_CAP_DEVICE_CAPS;
      return 0;
    }
    case VIDIOC_ENUM_FMT: {
      auto* f = static_cast<v4l2_fmtdesc*>(arg);
      if (f->index >= cam.formats.size()) return EINVAL;
      f->pixelformat = cam.formats[f->index];
      return 0;
    }
    case VIDIOC_S_FMT:
    case VIDIOC_G_FMT: {
      auto* f = static_cast<v4l2_format*>(arg);
      if (request == VIDIOC_S_FMT) {
        if (cam.streaming || !cam.buffers.empty()) return EBUSY;
        const std::uint32_t want = f->fmt.pix.pixelformat;
        cam.pixfmt = (want == V4L2_PIX_FMT_YUYV || want == V4L2_PIX_FMT_GREY) ? want : V4L2_PIX_FMT_YUYV;
        cam.width = std::clamp<std::uint32_t>(f->fmt.pix.width & ~1u, 2, 640);
        cam.height = std::clamp<std::uint32_t>(f->fmt.pix.height, 1, 480);
      }
      f->fmt.pix.pixelformat = cam.pixfmt;
      f->fmt.pix.width = cam.width;
      f->fmt.pix.height = cam.height;
      f->fmt.pix.field = V4L2_FIELD_NONE;
      f->fmt.pix.bytesperline = cam.row();
      f->fmt.pix.sizeimage = cam.size_image();
      return 0;
    }
    case VIDIOC_S_CTRL: {
      auto* c = static_cast<v4l2_control*>(arg);
      if (c->id == V4L2_CID_EXPOSURE_ABSOLUTE) {
        log_line("exposure", c->value);
        cam.pending.emplace_back(cam.frame + 2, c->value);
        return 0;
      }
      return c->id == V4L2_CID_EXPOSURE_AUTO ? 0 : EINVAL;
    }
    case VIDIOC_REQBUFS: {
      auto* r = static_cast<v4l2_requestbuffers*>(arg);
      if (r->memory != V4L2_MEMORY_MMAP) return EINVAL;
      log_line("reqbufs", long(r->count));
      r->count = std::min(r->count, 8u);
      cam.buffers.assign(r->count, std::vector<unsigned char>(cam.size_image()));
      cam.queued.clear();
      return 0;
    }
    case VIDIOC_QUERYBUF: {
      auto* b = static_cast<v4l2_buffer*>(arg);
      if (b->index >= cam.buffers.size()) return EINVAL;
      b->length = std::uint32_t(cam.buffers[b->index].size());
      b->m.offset = b->index * 0x10000u;
      return 0;
    }
    case VIDIOC_QBUF: {
      auto* b = static_cast<v4l2_buffer*>(arg);
      if (b->index >= cam.buffers.size()) return EINVAL;
      cam.queued.push_back(b->index);
      return 0;
    }
    case VIDIOC_DQBUF: {
      if (!cam.streaming || cam.queued.empty() || !cam.arrived) return EAGAIN;
      auto* b = static_cast<v4l2_buffer*>(arg);
      b->index = cam.queued.front();
      cam.queued.pop_front();
      fill(cam.buffers[b->index]);
      b->bytesused = std::uint32_t(cam.buffers[b->index].size());
      b->flags = 0;
      cam.arrived = false;
      log_line("frame", cam.units);
      return 0;
    }
    case VIDIOC_STREAMON: cam.streaming = true; log_line("streamon"); return 0;
    case VIDIOC_STREAMOFF: cam.streaming = false; cam.queued.clear(); log_line("streamoff"); return 0;
    default: return ENOTTY;
  }
}

}  // namespace

extern "C" {

int open(const char* path, int flags, ...) {
  mode_t mode = 0;
  if (flags & (O_CREAT | O_TMPFILE)) {
    va_list ap;
    va_start(ap, flags);
    mode = mode_t(va_arg(ap, int));
    va_end(ap);
  }
  if (is_mocked_path(path)) {
    configure();
    cam.fd = real<int (*)(const char*, int, ...)>("open")("/dev/null", O_RDWR | (flags & O_CLOEXEC));
    return cam.fd;
  }
  return real<int (*)(const char*, int, ...)>("open")(path, flags, mode);
}

int open64(const char* path, int flags, ...) {
  mode_t mode = 0;
  if (flags & (O_CREAT | O_TMPFILE)) {
    va_list ap;
    va_start(ap, flags);
    mode = mode_t(va_arg(ap, int));
    va_end(ap);
  }
  return open(path, flags, mode);
}

int ioctl(int fd, unsigned long request, ...) {
  va_list ap;
  va_start(ap, request);
  void* arg = va_arg(ap, void*);
  va_end(ap);
  if (fd >= 0 && fd == cam.fd) {
    const int e = handle(request, arg);
    if (e == 0) return 0;
    errno = e;
    return -1;
  }
  return real<int (*)(int, unsigned long, void*)>("ioctl")(fd, request, arg);
}

void* mmap(void* addr, size_t length, int prot, int flags, int fd, off_t offset) {
  if (fd >= 0 && fd == cam.fd) {
    const std::size_t i = std::size_t(offset) / 0x10000u;
    if (i >= cam.buffers.size() || length != cam.buffers[i].size()) {
      errno = EINVAL;
      return MAP_FAILED;
    }
    return cam.buffers[i].data();
  }
  return real<void* (*)(void*, size_t, int, int, int, off_t)>("mmap")(addr, length, prot, flags, fd, offset);
}

void* mmap64(void* addr, size_t length, int prot, int flags, int fd, off_t offset) {
  return mmap(addr, length, prot, flags, fd, offset);
}

int munmap(void* addr, size_t length) {
  for (const auto& b : cam.buffers)
    if (addr == b.data()) return 0;
  return real<int (*)(void*, size_t)>("munmap")(addr, length);
}

// glibc declares poll's array write-only (__attr_access), so GCC takes reading fd here
// for a read of uninitialised memory; the caller did set it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
int poll(struct pollfd* fds, nfds_t n, int timeout) {
  if (n == 1 && fds[0].fd >= 0 && fds[0].fd == cam.fd) {
    const char* stall = std::getenv("V4L2MOCK_STALL");
    if (!cam.streaming || cam.queued.empty() || (stall && *stall == '1')) return 0;  // times out at once
    cam.arrived = true;
    fds[0].revents = POLLIN;
    return 1;
  }
  return real<int (*)(struct pollfd*, nfds_t, int)>("poll")(fds, n, timeout);
}
#pragma GCC diagnostic pop

int close(int fd) {
  if (fd >= 0 && fd == cam.fd) cam.fd = -1;
  return real<int (*)(int)>("close")(fd);
}

}  // extern "C"
