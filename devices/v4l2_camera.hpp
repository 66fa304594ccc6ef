#pragma once
// A V4L2 camera (URI `v4l2:/dev/video0[,fourcc=Y16,width=W,height=H]`, specs/capture.md
// §2.2) through OpenCV's VideoCapture with the CAP_V4L2 backend: UVC and machine-vision
// cameras. Exposure is manual (V4L2_EXPOSURE_MANUAL); V4L2 counts exposure_absolute in
// units of 100 us, and some cameras ignore it (capture selftest checks the level).
// fourcc=Y16 delivers 16-bit grey without conversion; otherwise frames arrive as 8-bit
// RGB.

#include <memory>
#include <string>

#include "capture/camera.hpp"

namespace cv {
class VideoCapture;
}

namespace fest::devices {

class V4l2Camera : public capture::Camera {
 public:
  // Throws device_not_found (5) for a missing node, permission (8) naming the video
  // group, device_error (6) when it cannot be opened otherwise; usage_error for bad
  // URI options.
  explicit V4l2Camera(const std::string& uri);
  ~V4l2Camera() override;
  capture::CameraInfo info() override;
  void set_exposure(double seconds) override;
  Image capture() override;  // timeout (7) when no frame arrives

 private:
  std::string path_;
  bool raw16_ = false;
  std::unique_ptr<cv::VideoCapture> video_;
  capture::CameraInfo info_;
};

}  // namespace fest::devices
