// devices/v4l2_camera against a scripted V4L2 driver (there is no camera in CI): format
// negotiation, mmap streaming, no picture from a frame buffered before the request,
// corrupt frames,
// timeouts, and the clean-up on destruction. The driver follows the V4L2 API as the
// kernel documents it (VIDIOC_* ioctls, EAGAIN on a non-blocking DQBUF with nothing
// ready, S_FMT adjusting an unsupported pixel format to one it has).

#include <linux/videodev2.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "capture/pixel_formats.hpp"
#include "devices/v4l2_camera.hpp"
#include "formats/image/image_io.hpp"

namespace {

using namespace fest;
using devices::V4l2Camera;

struct Frame {
  std::string bytes;
  bool arrived = true;  // false: it arrives during the next poll (time passes)
  std::uint32_t flags = 0;
};

struct Driver {
  std::vector<std::uint32_t> formats{capture::fourcc_mjpg, capture::fourcc_yuyv};
  std::uint32_t caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
  bool is_v4l2 = true;
  std::uint32_t pixfmt = capture::fourcc_mjpg;
  std::uint32_t width = 4, height = 2, padding = 0;
  unsigned max_buffers = 4;
  bool refuse_exposure = false;
  std::vector<std::string> buffers;
  std::deque<unsigned> queued;
  std::deque<Frame> frames;
  bool streaming = false;
  std::map<std::uint32_t, std::int32_t> controls;
  int mapped = 0;
  std::vector<std::string> calls;

  std::uint32_t row() const { return capture::raw_row_bytes(pixfmt, int(width)) + padding; }
  std::uint32_t size_image() const { return pixfmt == capture::fourcc_mjpg ? width * height * 2 + 4096 : row() * height; }
  bool ready() const { return streaming && !queued.empty() && !frames.empty() && frames.front().arrived; }
};

class FakeNode : public devices::VideoNode {
 public:
  explicit FakeNode(std::shared_ptr<Driver> d) : d_(std::move(d)) {}
  int control(unsigned long request, void* arg) override {
    Driver& d = *d_;
    switch (request) {
      case VIDIOC_QUERYCAP: {
        if (!d.is_v4l2) return ENOTTY;
        auto* c = static_cast<v4l2_capability*>(arg);
        std::strcpy(reinterpret_cast<char*>(c->card), "Fake UVC");
        c->capabilities = d.caps | V4L2_CAP_DEVICE_CAPS;
        c->device_caps = d.caps;
        return 0;
      }
      case VIDIOC_ENUM_FMT: {
        auto* f = static_cast<v4l2_fmtdesc*>(arg);
        if (f->index >= d.formats.size()) return EINVAL;
        f->pixelformat = d.formats[f->index];
        return 0;
      }
      case VIDIOC_G_FMT:
      case VIDIOC_S_FMT: {
        auto* f = static_cast<v4l2_format*>(arg);
        if (request == VIDIOC_S_FMT) {
          d.calls.push_back("S_FMT");
          bool known = false;
          for (const std::uint32_t c : d.formats) known |= c == f->fmt.pix.pixelformat;
          d.pixfmt = known ? f->fmt.pix.pixelformat : d.formats.front();
          d.width = std::min<std::uint32_t>(f->fmt.pix.width, 64);
          d.height = std::min<std::uint32_t>(f->fmt.pix.height, 48);
        }
        f->fmt.pix.pixelformat = d.pixfmt;
        f->fmt.pix.width = d.width;
        f->fmt.pix.height = d.height;
        f->fmt.pix.bytesperline = d.pixfmt == capture::fourcc_mjpg ? 0 : d.row();
        f->fmt.pix.sizeimage = d.size_image();
        return 0;
      }
      case VIDIOC_S_CTRL: {
        auto* c = static_cast<v4l2_control*>(arg);
        if (c->id == V4L2_CID_EXPOSURE_ABSOLUTE && d.refuse_exposure) return EINVAL;
        d.controls[c->id] = c->value;
        // Frames in flight were exposed before this: they stay ready.
        return 0;
      }
      case VIDIOC_REQBUFS: {
        auto* r = static_cast<v4l2_requestbuffers*>(arg);
        if (r->memory != V4L2_MEMORY_MMAP) return EINVAL;
        d.calls.push_back("REQBUFS " + std::to_string(r->count));
        r->count = std::min(r->count, d.max_buffers);
        d.buffers.assign(r->count, std::string(d.size_image(), '\0'));
        return 0;
      }
      case VIDIOC_QUERYBUF: {
        auto* b = static_cast<v4l2_buffer*>(arg);
        if (b->index >= d.buffers.size()) return EINVAL;
        b->length = std::uint32_t(d.buffers[b->index].size());
        b->m.offset = b->index * 4096;
        return 0;
      }
      case VIDIOC_QBUF: {
        auto* b = static_cast<v4l2_buffer*>(arg);
        if (b->index >= d.buffers.size()) return EINVAL;
        for (const unsigned q : d.queued)
          if (q == b->index) return EINVAL;
        d.queued.push_back(b->index);
        return 0;
      }
      case VIDIOC_DQBUF: {
        if (!d.ready()) return EAGAIN;
        auto* b = static_cast<v4l2_buffer*>(arg);
        b->index = d.queued.front();
        d.queued.pop_front();
        const Frame f = d.frames.front();
        d.frames.pop_front();
        std::string& buf = d.buffers[b->index];
        const std::size_t n = std::min(buf.size(), f.bytes.size());
        std::memcpy(buf.data(), f.bytes.data(), n);
        b->bytesused = std::uint32_t(n);
        b->flags = f.flags;
        return 0;
      }
      case VIDIOC_STREAMON: d.streaming = true; d.calls.push_back("STREAMON"); return 0;
      case VIDIOC_STREAMOFF: d.streaming = false; d.queued.clear(); d.calls.push_back("STREAMOFF"); return 0;
      default: return ENOTTY;
    }
  }
  void* map(std::size_t length, std::int64_t offset) override {
    const std::size_t i = std::size_t(offset / 4096);
    if (i >= d_->buffers.size() || length != d_->buffers[i].size()) return nullptr;
    ++d_->mapped;
    return d_->buffers[i].data();
  }
  void unmap(void*, std::size_t) override { --d_->mapped; }
  int wait_readable(int) override {
    Driver& d = *d_;
    if (d.streaming && !d.queued.empty() && !d.frames.empty()) {
      d.frames.front().arrived = true;
      return 1;
    }
    return 0;  // nothing will come: timed out
  }

 private:
  std::shared_ptr<Driver> d_;
};

std::unique_ptr<V4l2Camera> open(const std::shared_ptr<Driver>& d, const std::string& options = "") {
  return std::make_unique<V4l2Camera>("v4l2:/dev/video7" + options, std::make_unique<FakeNode>(d));
}

Error error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  return Error(Status::ok, "no error");
}

// A YUYV frame of the driver's size whose every pixel has luma y, neutral chroma.
std::string yuyv(const Driver& d, int y) {
  std::string s;
  for (std::uint32_t r = 0; r < d.height; ++r) {
    for (std::uint32_t c = 0; c < d.width; c += 2) s += {char(y), char(128), char(y), char(128)};
    s += std::string(d.padding, '\x55');
  }
  return s;
}

// The grey level 255/219 (y-16) that luma y maps to.
int grey_of(const Image& img) { return img.pixels.at<cv::Vec3b>(0, 0)[1]; }

TEST(DevicesV4l2Camera, PrefersUncompressedYuyvAndReportsTheNegotiatedSize) {
  auto d = std::make_shared<Driver>();
  d->width = 640, d->height = 480;
  auto cam = open(d);
  EXPECT_EQ(cam->pixel_format(), capture::fourcc_yuyv);
  const capture::CameraInfo info = cam->info();
  EXPECT_EQ(info.width, 64);  // the driver's largest
  EXPECT_EQ(info.height, 48);
  EXPECT_EQ(info.channels, 3);
  EXPECT_EQ(info.bits, 8);
  EXPECT_EQ(info.name, "v4l2:/dev/video7 (Fake UVC)");
  EXPECT_EQ(d->controls[V4L2_CID_EXPOSURE_AUTO], V4L2_EXPOSURE_MANUAL);
  EXPECT_EQ(d->mapped, 4);
}

TEST(DevicesV4l2Camera, AskedSizeAndFormat) {
  auto d = std::make_shared<Driver>();
  auto cam = open(d, ",fourcc=MJPG,width=32,height=16");
  EXPECT_EQ(cam->pixel_format(), capture::fourcc_mjpg);
  EXPECT_EQ(cam->info().width, 32);
  EXPECT_EQ(cam->info().height, 16);
}

TEST(DevicesV4l2Camera, Y16IsSixteenBitGrey) {
  auto d = std::make_shared<Driver>();
  d->formats = {capture::fourcc_grey, capture::fourcc_y16};
  auto cam = open(d, ",fourcc=Y16");
  EXPECT_EQ(cam->info().bits, 16);
  EXPECT_EQ(cam->info().channels, 1);
  std::string frame;
  for (std::uint32_t i = 0; i < d->width * d->height; ++i) frame += {char(0x00), char(0x80)};
  d->frames.push_back({frame});
  const Image img = cam->capture();
  ASSERT_EQ(img.pixels.type(), CV_16UC1);
  EXPECT_EQ(img.pixels.at<std::uint16_t>(1, 3), 0x8000);
}

TEST(DevicesV4l2Camera, FormatsItCannotUseAreDeviceErrors) {
  auto d = std::make_shared<Driver>();
  d->formats = {capture::fourcc_yuyv};
  Error e = error_of([&] { open(d, ",fourcc=MJPG"); });
  EXPECT_EQ(e.status(), Status::device_error);
  EXPECT_STREQ(e.what(), "v4l2 camera: /dev/video7 does not offer fourcc MJPG (it offers YUYV)");
  d->formats = {capture::fourcc('N', 'V', '1', '2')};
  e = error_of([&] { open(d); });
  EXPECT_EQ(e.status(), Status::device_error);
  EXPECT_STREQ(e.what(),
               "v4l2 camera: /dev/video7 offers none of the formats fest converts (it offers NV12; fest converts "
               "YUYV, MJPG, GREY, RGB3, Y16)");
  e = error_of([&] { open(d, ",fourcc=NV12"); });
  EXPECT_EQ(e.status(), Status::usage);
  EXPECT_EQ(error_of([&] { open(d, ",width=0"); }).status(), Status::usage);
  EXPECT_EQ(error_of([&] { open(d, ",gain=3"); }).status(), Status::usage);
}

TEST(DevicesV4l2Camera, NodesThatAreNotStreamingCaptureDevices) {
  auto d = std::make_shared<Driver>();
  d->is_v4l2 = false;
  Error e = error_of([&] { open(d); });
  EXPECT_EQ(e.status(), Status::device_error);
  EXPECT_EQ(std::string(e.what()).rfind("v4l2 camera: /dev/video7 is not a V4L2 device (", 0), 0u) << e.what();
  d->is_v4l2 = true;
  d->caps = V4L2_CAP_VIDEO_OUTPUT | V4L2_CAP_STREAMING;
  e = error_of([&] { open(d); });
  EXPECT_STREQ(e.what(), "v4l2 camera: /dev/video7 (Fake UVC) is not a video capture device");
  d->caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_READWRITE;
  e = error_of([&] { open(d); });
  EXPECT_STREQ(e.what(), "v4l2 camera: /dev/video7 (Fake UVC) does not support streaming I/O");
  d->caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
  d->max_buffers = 1;
  e = error_of([&] { open(d); });
  EXPECT_STREQ(e.what(), "v4l2 camera: /dev/video7 granted 1 streaming buffer(s), 2 are needed");
}

TEST(DevicesV4l2Camera, YuyvFramesWithPaddedRows) {
  auto d = std::make_shared<Driver>();
  d->padding = 6;
  auto cam = open(d, ",fourcc=YUYV,width=4,height=2");
  d->frames.push_back({yuyv(*d, 235)});
  const Image img = cam->capture();
  ASSERT_EQ(img.pixels.type(), CV_8UC3);
  EXPECT_EQ(img.pixels.at<cv::Vec3b>(1, 3), cv::Vec3b(255, 255, 255));
}

TEST(DevicesV4l2Camera, TheFirstPictureIsTheFirstFrameAfterStreamOn) {
  auto d = std::make_shared<Driver>();
  auto cam = open(d, ",fourcc=YUYV,width=4,height=2");
  EXPECT_FALSE(d->streaming);  // streaming starts with the first picture
  for (const int y : {126, 16}) d->frames.push_back({yuyv(*d, y), false});
  EXPECT_EQ(grey_of(cam->capture()), 128);  // 255/219 * 110 = 128.08
  EXPECT_EQ(d->frames.size(), 1u);
}

TEST(DevicesV4l2Camera, FramesBufferedBeforeTheRequestAreNeverReturned) {
  auto d = std::make_shared<Driver>();
  auto cam = open(d, ",fourcc=YUYV,width=4,height=2");
  d->frames.push_back({yuyv(*d, 235), false});
  EXPECT_EQ(grey_of(cam->capture()), 255);
  // While the table turned, the driver filled two buffers...
  d->frames.push_back({yuyv(*d, 16), true});
  d->frames.push_back({yuyv(*d, 16), true});
  cam->set_exposure(0.0125);
  EXPECT_EQ(d->controls[V4L2_CID_EXPOSURE_ABSOLUTE], 125);  // units of 100 us
  // ...and a third was being exposed when the picture was asked for.
  d->frames.push_back({yuyv(*d, 16), false});
  d->frames.push_back({yuyv(*d, 126), false});
  EXPECT_EQ(grey_of(cam->capture()), 128);
  EXPECT_TRUE(d->frames.empty());
}

std::string jpeg_frame(int width, int height, int level) {
  Image img;
  img.pixels = cv::Mat(height, width, CV_8UC3, cv::Scalar(level, level, level));
  formats::ImageWriteOptions o;
  o.jpeg_quality = 90;
  return formats::write_image(img, formats::Format::jpeg, o);
}

TEST(DevicesV4l2Camera, CorruptFramesAreSkippedThenReported) {
  auto d = std::make_shared<Driver>();
  auto cam = open(d, ",fourcc=MJPG,width=16,height=16");
  const std::string good = jpeg_frame(16, 16, 200);
  d->frames.push_back({good.substr(0, good.size() / 2)});  // truncated in transfer
  d->frames.push_back({good, true, V4L2_BUF_FLAG_ERROR});  // flagged by the driver
  d->frames.push_back({good});
  const Image img = cam->capture();
  EXPECT_NEAR(img.pixels.at<cv::Vec3b>(8, 8)[0], 200, 2);

  d->frames.push_back({good, false});  // in flight when asked: dropped
  for (int i = 0; i < 3; ++i) d->frames.push_back({good.substr(0, 100), false});
  const Error e = error_of([&] { cam->capture(); });
  EXPECT_EQ(e.status(), Status::device_error);
  const std::string m = e.what();
  EXPECT_EQ(m.rfind("v4l2 camera: /dev/video7 delivered 3 corrupt frames in a row (last: MJPEG frame of 100 bytes: ", 0),
            0u)
      << m;
  EXPECT_EQ(m.find('\n'), std::string::npos);
}

TEST(DevicesV4l2Camera, NoFrameIsATimeout) {
  auto d = std::make_shared<Driver>();
  auto cam = open(d, ",fourcc=YUYV");
  const Error e = error_of([&] { cam->capture(); });
  EXPECT_EQ(e.status(), Status::timeout);
  EXPECT_STREQ(e.what(), "v4l2 camera: /dev/video7 did not deliver a frame in 5 s");
}

TEST(DevicesV4l2Camera, ExposureErrors) {
  auto d = std::make_shared<Driver>();
  auto cam = open(d);
  EXPECT_EQ(error_of([&] { cam->set_exposure(-1); }).status(), Status::usage);
  d->refuse_exposure = true;
  const Error e = error_of([&] { cam->set_exposure(0.01); });
  EXPECT_EQ(e.status(), Status::device_error);
  EXPECT_STREQ(e.what(), "v4l2 camera: /dev/video7 refused exposure 0.01 s");
}

TEST(DevicesV4l2Camera, DestructionStopsStreamingAndFreesTheBuffers) {
  auto d = std::make_shared<Driver>();
  {
    auto cam = open(d, ",fourcc=YUYV");
    d->frames.push_back({yuyv(*d, 100)});
    cam->capture();
    EXPECT_TRUE(d->streaming);
  }
  EXPECT_FALSE(d->streaming);
  EXPECT_EQ(d->mapped, 0);
  ASSERT_FALSE(d->calls.empty());
  EXPECT_EQ(d->calls.back(), "REQBUFS 0");
}

TEST(DevicesV4l2Camera, RealNodes) {
  Error e = error_of([] { V4l2Camera("v4l2:/dev/fest-no-such-video"); });
  EXPECT_EQ(e.status(), Status::device_not_found);
  EXPECT_STREQ(e.what(), "v4l2 camera: no device /dev/fest-no-such-video");
  // /dev/null opens but answers VIDIOC_QUERYCAP with ENOTTY.
  e = error_of([] { V4l2Camera("v4l2:/dev/null"); });
  EXPECT_EQ(e.status(), Status::device_error);
  EXPECT_EQ(std::string(e.what()).rfind("v4l2 camera: /dev/null is not a V4L2 device (", 0), 0u) << e.what();
}

}  // namespace
