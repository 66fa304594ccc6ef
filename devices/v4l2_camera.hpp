#pragma once
// A V4L2 camera (URI `v4l2:/dev/video0[,fourcc=F][,width=W][,height=H]`,
// docs/capture.md §4.1): UVC and machine-vision cameras driven through the kernel's
// V4L2 interface directly (linux/videodev2.h), the way v4l2-ctl and fswebcam do:
// VIDIOC_QUERYCAP, ENUM_FMT/S_FMT, REQBUFS + mmap streaming, QBUF/DQBUF with a poll
// timeout, STREAMON/OFF. Exposure is manual (V4L2_EXPOSURE_MANUAL); V4L2 counts
// exposure_absolute in units of 100 us, and some cameras ignore it (capture selftest
// checks the level).
//
// Pixel formats (devices/v4l2_frame.hpp): fourcc=Y16 delivers 16-bit grey unconverted;
// YUYV (BT.601 limited range), MJPG (libjpeg-turbo), GREY and RGB3 arrive as 8-bit RGB.
// Without fourcc= the first the camera offers of RGB3, YUYV, GREY, MJPG is used.
// Every picture is a frame whose exposure began after capture() was called: frames the
// driver buffered in between (while the table turned, the lights switched or the
// exposure changed) are given back unread and the frame in flight is dropped; a sensor
// that applies a new exposure a frame late is covered by the station's flush_frames.
// A corrupt frame (a truncated MJPEG, a buffer the driver flags as bad) is skipped;
// three in a row are a device error.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "capture/camera.hpp"
#include "devices/v4l2_node.hpp"

namespace fest::devices {

class V4l2Camera : public capture::Camera {
 public:
  // Throws device_not_found (5) for a missing node, permission (8) naming the video
  // group, device_error (6) when it is not a streaming capture device or offers no
  // format fest converts; usage_error for bad URI options.
  explicit V4l2Camera(const std::string& uri);
  // The same over an already opened node (tests drive a scripted driver through it).
  V4l2Camera(const std::string& uri, std::unique_ptr<VideoNode> node);
  ~V4l2Camera() override;
  V4l2Camera(const V4l2Camera&) = delete;
  V4l2Camera& operator=(const V4l2Camera&) = delete;

  capture::CameraInfo info() override;
  void set_exposure(double seconds) override;
  Image capture() override;  // timeout (7) when no frame arrives

  std::uint32_t pixel_format() const { return fourcc_; }

 private:
  struct Options;
  static Options parse(const std::string& uri);
  void open(const Options& options);
  void setup(const Options& options);
  void negotiate_format(const Options& options);
  void map_buffers();
  void start_streaming();
  void stop_streaming() noexcept;
  void release() noexcept;
  bool dequeue(unsigned& index, std::uint32_t& bytes_used, std::uint32_t& flags, bool wait);
  void requeue(unsigned index);
  int frame_timeout_ms() const;

  struct Buffer {
    void* start = nullptr;
    std::size_t length = 0;
  };
  std::string path_;
  std::unique_ptr<VideoNode> node_;
  std::uint32_t fourcc_ = 0;
  int stride_ = 0;
  std::vector<Buffer> buffers_;
  bool streaming_ = false;
  double exposure_s_ = 0;
  capture::CameraInfo info_;
};

}  // namespace fest::devices
