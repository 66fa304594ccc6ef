#include "devices/v4l2_camera.hpp"

#include <linux/videodev2.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "capture/device_uri.hpp"
#include "core/error.hpp"
#include "devices/v4l2_frame.hpp"

namespace fest::devices {

namespace {

using capture::fourcc_name;

// Without fourcc=: the formats fest converts, cheapest and least lossy first.
constexpr std::uint32_t preferred_formats[] = {capture::fourcc_rgb3, capture::fourcc_yuyv, capture::fourcc_grey,
                                               capture::fourcc_mjpg};
constexpr unsigned buffer_count = 4;       // as many as v4l2-ctl and OpenCV ask for
constexpr int max_corrupt_in_a_row = 3;

int bounded_int(const std::string& key, const std::string& text, long lo, long hi) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || v < lo || v > hi)
    throw usage_error("v4l2 camera: {}={} is not an integer in {}..{}", key, text, lo, hi);
  return int(v);
}

std::string format_list(const std::vector<std::uint32_t>& codes) {
  std::string s;
  for (const std::uint32_t c : codes) s += (s.empty() ? "" : ", ") + fourcc_name(c);
  return s.empty() ? "none" : s;
}

std::string supported_list() { return "YUYV, MJPG, GREY, RGB3, Y16"; }

}  // namespace

struct V4l2Camera::Options {
  std::string path;
  std::uint32_t fourcc = 0;  // 0: choose
  int width = 0, height = 0; // 0: keep the device's
};

V4l2Camera::Options V4l2Camera::parse(const std::string& uri) {
  const capture::DeviceUri u = capture::parse_device_uri(uri);
  if (u.scheme != "v4l2") throw usage_error("not a v4l2: camera URI: {}", uri);
  u.expect_only({"fourcc", "width", "height"});
  Options o;
  o.path = u.path.empty() ? "/dev/video0" : u.path;
  const std::string fourcc = u.get("fourcc");
  if (u.has("fourcc")) {
    if (fourcc.size() > 4 || fourcc.empty())
      throw usage_error("v4l2 camera: fourcc '{}' is not 1 to 4 characters", fourcc);
    o.fourcc = capture::fourcc_from_name(fourcc);
    if (!is_supported_v4l2_format(o.fourcc))
      throw usage_error("v4l2 camera: fourcc '{}' is not a format fest converts ({})", fourcc, supported_list());
  }
  if (u.has("width")) o.width = bounded_int("width", u.get("width"), 1, 65535);
  if (u.has("height")) o.height = bounded_int("height", u.get("height"), 1, 65535);
  return o;
}

V4l2Camera::V4l2Camera(const std::string& uri) {
  const Options o = parse(uri);
  path_ = o.path;
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) throw make_error(Status::device_not_found, "v4l2 camera: no device {}", path_);
  if (::access(path_.c_str(), R_OK | W_OK) != 0 && errno == EACCES)
    throw make_error(Status::permission,
                     "v4l2 camera: permission denied on {} (add the user to the 'video' group: usermod -aG video $USER)",
                     path_);
  node_ = open_video_node(path_);
  open(o);
}

V4l2Camera::V4l2Camera(const std::string& uri, std::unique_ptr<VideoNode> node) : node_(std::move(node)) {
  const Options o = parse(uri);
  path_ = o.path;
  open(o);
}

void V4l2Camera::open(const Options& o) {
  // A constructor that throws runs no destructor: give back what was mapped so far.
  try {
    setup(o);
  } catch (...) {
    release();
    throw;
  }
}

void V4l2Camera::setup(const Options& o) {
  v4l2_capability cap{};
  if (const int e = node_->control(VIDIOC_QUERYCAP, &cap))
    throw make_error(Status::device_error, "v4l2 camera: {} is not a V4L2 device ({})", path_, std::strerror(e));
  const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
  const std::string card(reinterpret_cast<const char*>(cap.card), strnlen(reinterpret_cast<const char*>(cap.card), sizeof cap.card));
  if (!(caps & V4L2_CAP_VIDEO_CAPTURE))
    throw make_error(Status::device_error, "v4l2 camera: {} ({}) is not a video capture device", path_, card);
  if (!(caps & V4L2_CAP_STREAMING))
    throw make_error(Status::device_error, "v4l2 camera: {} ({}) does not support streaming I/O", path_, card);
  negotiate_format(o);
  // V4L2_EXPOSURE_MANUAL; a camera without the control keeps its own exposure, which
  // capture selftest's level checks reveal.
  v4l2_control manual{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL};
  (void)node_->control(VIDIOC_S_CTRL, &manual);
  map_buffers();
  info_.channels = fourcc_ == capture::fourcc_y16 ? 1 : 3;
  info_.bits = fourcc_ == capture::fourcc_y16 ? 16 : 8;
  info_.name = "v4l2:" + path_ + (card.empty() ? "" : " (" + card + ")");
}

void V4l2Camera::negotiate_format(const Options& o) {
  std::vector<std::uint32_t> offered;
  for (std::uint32_t i = 0; i < 256; ++i) {
    v4l2_fmtdesc d{};
    d.index = i;
    d.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (node_->control(VIDIOC_ENUM_FMT, &d) != 0) break;
    offered.push_back(d.pixelformat);
  }
  const auto offers = [&](std::uint32_t c) { return std::find(offered.begin(), offered.end(), c) != offered.end(); };
  std::uint32_t want = o.fourcc;
  if (want != 0 && !offered.empty() && !offers(want))
    throw make_error(Status::device_error, "v4l2 camera: {} does not offer fourcc {} (it offers {})", path_,
                     fourcc_name(want), format_list(offered));
  if (want == 0) {
    for (const std::uint32_t c : preferred_formats)
      if (offers(c)) {
        want = c;
        break;
      }
  }
  if (want == 0)
    throw make_error(Status::device_error, "v4l2 camera: {} offers none of the formats fest converts (it offers {}; fest converts {})",
                     path_, format_list(offered), supported_list());

  v4l2_format f{};
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (const int e = node_->control(VIDIOC_G_FMT, &f))
    throw make_error(Status::device_error, "v4l2 camera: {} does not report its format ({})", path_, std::strerror(e));
  f.fmt.pix.pixelformat = want;
  if (o.width) f.fmt.pix.width = std::uint32_t(o.width);
  if (o.height) f.fmt.pix.height = std::uint32_t(o.height);
  f.fmt.pix.field = V4L2_FIELD_NONE;
  f.fmt.pix.bytesperline = 0;  // let the driver choose
  if (const int e = node_->control(VIDIOC_S_FMT, &f))
    throw make_error(Status::device_error, "v4l2 camera: {} refused format {} {} x {} ({})", path_, fourcc_name(want),
                     f.fmt.pix.width, f.fmt.pix.height, std::strerror(e));
  if (f.fmt.pix.pixelformat != want)
    throw make_error(Status::device_error, "v4l2 camera: {} delivers {} instead of the format {} it was set to", path_,
                     fourcc_name(f.fmt.pix.pixelformat), fourcc_name(want));
  if (f.fmt.pix.width == 0 || f.fmt.pix.height == 0 || f.fmt.pix.width > 65535 || f.fmt.pix.height > 65535)
    throw make_error(Status::device_error, "v4l2 camera: {} reports a frame of {} x {} pixels", path_, f.fmt.pix.width,
                     f.fmt.pix.height);
  fourcc_ = want;
  info_.width = int(f.fmt.pix.width);
  info_.height = int(f.fmt.pix.height);
  const int row = capture::raw_row_bytes(want, info_.width);
  stride_ = f.fmt.pix.bytesperline >= std::uint32_t(row) && f.fmt.pix.bytesperline <= 0x7FFFFFFF ? int(f.fmt.pix.bytesperline) : row;
}

void V4l2Camera::map_buffers() {
  v4l2_requestbuffers req{};
  req.count = buffer_count;
  req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  req.memory = V4L2_MEMORY_MMAP;
  if (const int e = node_->control(VIDIOC_REQBUFS, &req))
    throw make_error(Status::device_error, "v4l2 camera: {} cannot allocate mmap streaming buffers ({})", path_,
                     e == EINVAL ? "memory-mapped streaming not supported" : std::strerror(e));
  if (req.count < 2)
    throw make_error(Status::device_error, "v4l2 camera: {} granted {} streaming buffer(s), 2 are needed", path_, req.count);
  for (unsigned i = 0; i < req.count; ++i) {
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = i;
    if (const int e = node_->control(VIDIOC_QUERYBUF, &b))
      throw make_error(Status::device_error, "v4l2 camera: {} cannot describe buffer {} ({})", path_, i, std::strerror(e));
    void* p = node_->map(b.length, b.m.offset);
    if (!p) throw make_error(Status::device_error, "v4l2 camera: {} cannot map buffer {} of {} bytes", path_, i, b.length);
    buffers_.push_back({p, b.length});
  }
}

V4l2Camera::~V4l2Camera() { release(); }

void V4l2Camera::release() noexcept {
  if (!node_) return;
  stop_streaming();
  for (const Buffer& b : buffers_) node_->unmap(b.start, b.length);
  if (!buffers_.empty()) {
    v4l2_requestbuffers req{};
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    (void)node_->control(VIDIOC_REQBUFS, &req);  // count 0: free them
  }
  buffers_.clear();
}

capture::CameraInfo V4l2Camera::info() { return info_; }

void V4l2Camera::set_exposure(double seconds) {
  if (!(seconds > 0) || !std::isfinite(seconds)) throw usage_error("v4l2 camera: exposure {} s must be positive", seconds);
  // exposure_absolute: units of 100 us.
  v4l2_control c{V4L2_CID_EXPOSURE_ABSOLUTE, std::int32_t(std::clamp(std::round(seconds * 1e4), 1.0, 2147483647.0))};
  if (node_->control(VIDIOC_S_CTRL, &c) != 0)
    throw make_error(Status::device_error, "v4l2 camera: {} refused exposure {} s", path_, seconds);
  exposure_s_ = seconds;
}

void V4l2Camera::start_streaming() {
  for (unsigned i = 0; i < buffers_.size(); ++i) requeue(i);
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (const int e = node_->control(VIDIOC_STREAMON, &type))
    throw make_error(Status::device_error, "v4l2 camera: {} cannot start streaming ({})", path_, std::strerror(e));
  streaming_ = true;
}

void V4l2Camera::stop_streaming() noexcept {
  if (!streaming_) return;
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  (void)node_->control(VIDIOC_STREAMOFF, &type);  // also takes every buffer back
  streaming_ = false;
}

void V4l2Camera::requeue(unsigned index) {
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  b.index = index;
  if (const int e = node_->control(VIDIOC_QBUF, &b))
    throw make_error(Status::device_error, "v4l2 camera: {} does not take buffer {} back ({})", path_, index, std::strerror(e));
}

int V4l2Camera::frame_timeout_ms() const {
  // A frame takes at most its exposure plus readout; 5 s covers USB hiccups and slow
  // frame rates, the exposure twice over long ones.
  return int(std::min(5000.0 + 2000.0 * exposure_s_, 3.6e6));
}

// One filled buffer: true and its index, or false (only when !wait) when none is ready.
bool V4l2Camera::dequeue(unsigned& index, std::uint32_t& bytes_used, std::uint32_t& flags, bool wait) {
  using clock = std::chrono::steady_clock;
  const int timeout_ms = frame_timeout_ms();
  const auto deadline = clock::now() + std::chrono::milliseconds(timeout_ms);
  while (true) {
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    const int e = node_->control(VIDIOC_DQBUF, &b);
    if (e == 0) {
      if (b.index >= buffers_.size())
        throw make_error(Status::device_error, "v4l2 camera: {} returned buffer {} of {}", path_, b.index, buffers_.size());
      index = b.index;
      bytes_used = std::min<std::uint32_t>(b.bytesused, std::uint32_t(buffers_[b.index].length));
      flags = b.flags;
      return true;
    }
    if (e == ENODEV) throw make_error(Status::device_not_found, "v4l2 camera: {} was unplugged", path_);
    if (e != EAGAIN && e != EIO)
      throw make_error(Status::device_error, "v4l2 camera: {} failed to deliver a frame ({})", path_, std::strerror(e));
    if (!wait) return false;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
    const int r = left > 0 ? node_->wait_readable(int(left)) : 0;
    if (r == 0)
      throw make_error(Status::timeout, "v4l2 camera: {} did not deliver a frame in {} s", path_, timeout_ms / 1000.0);
    if (r == -ENODEV) throw make_error(Status::device_not_found, "v4l2 camera: {} was unplugged", path_);
    if (r < 0 && r != -EINTR)
      throw make_error(Status::device_error, "v4l2 camera: {} failed while waiting for a frame ({})", path_, std::strerror(-r));
  }
}

Image V4l2Camera::capture() {
  unsigned index = 0;
  std::uint32_t used = 0, flags = 0;
  if (!streaming_) {
    start_streaming();  // every frame from now on begins after this call
  } else {
    // The driver kept filling buffers since the last picture, while the table turned or
    // the lights switched: give the filled ones back unread (at most one pass, so that a
    // driver that always has a frame ready cannot keep this going), then drop the frame
    // in flight, whose exposure began before this call.
    for (std::size_t n = 0; n < buffers_.size() && dequeue(index, used, flags, false); ++n) requeue(index);
    dequeue(index, used, flags, true);
    requeue(index);
  }
  int corrupt = 0;
  std::string last_problem;
  while (true) {
    dequeue(index, used, flags, true);
    if (flags & V4L2_BUF_FLAG_ERROR) {
      last_problem = "the driver marked the buffer as corrupt";
    } else {
      const capture::RawFrame raw{fourcc_, info_.width, info_.height, stride_,
                                  std::string_view(static_cast<const char*>(buffers_[index].start), used)};
      try {
        Image image = decode_v4l2_frame(raw);  // copies out of the buffer
        requeue(index);
        return image;
      } catch (const Error& e) {
        if (e.status() != Status::bad_input) {
          requeue(index);
          throw;
        }
        last_problem = e.what();
      }
    }
    requeue(index);
    if (++corrupt >= max_corrupt_in_a_row)
      throw make_error(Status::device_error, "v4l2 camera: {} delivered {} corrupt frames in a row (last: {})", path_,
                       corrupt, last_problem);
  }
}

}  // namespace fest::devices
