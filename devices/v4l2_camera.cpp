#include "devices/v4l2_camera.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "capture/device_uri.hpp"
#include "core/error.hpp"

namespace fest::devices {

namespace {

int positive_int(const std::string& key, const std::string& text) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || v < 1 || v > 65535) throw usage_error("v4l2 camera: {}={} is not a positive integer", key, text);
  return int(v);
}

}  // namespace

V4l2Camera::V4l2Camera(const std::string& uri) {
  const capture::DeviceUri u = capture::parse_device_uri(uri);
  if (u.scheme != "v4l2") throw usage_error("not a v4l2: camera URI: {}", uri);
  u.expect_only({"fourcc", "width", "height"});
  path_ = u.path.empty() ? "/dev/video0" : u.path;
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) throw make_error(Status::device_not_found, "v4l2 camera: no device {}", path_);
  if (::access(path_.c_str(), R_OK | W_OK) != 0 && errno == EACCES)
    throw make_error(Status::permission,
                     "v4l2 camera: permission denied on {} (add the user to the 'video' group: usermod -aG video $USER)",
                     path_);
  video_ = std::make_unique<cv::VideoCapture>(path_, cv::CAP_V4L2);
  if (!video_->isOpened()) throw make_error(Status::device_error, "v4l2 camera: cannot open {} (busy or not a capture device)", path_);
  const std::string fourcc = u.get("fourcc");
  if (!fourcc.empty()) {
    if (fourcc.size() > 4) throw usage_error("v4l2 camera: fourcc '{}' has more than 4 characters", fourcc);
    const std::string f = (fourcc + "    ").substr(0, 4);
    video_->set(cv::CAP_PROP_FOURCC, cv::VideoWriter::fourcc(f[0], f[1], f[2], f[3]));
    raw16_ = fourcc == "Y16";
    if (raw16_) video_->set(cv::CAP_PROP_CONVERT_RGB, 0);
  }
  if (u.has("width")) video_->set(cv::CAP_PROP_FRAME_WIDTH, positive_int("width", u.get("width")));
  if (u.has("height")) video_->set(cv::CAP_PROP_FRAME_HEIGHT, positive_int("height", u.get("height")));
  // V4L2_EXPOSURE_MANUAL = 1 (OpenCV passes the value through to the V4L2 control).
  video_->set(cv::CAP_PROP_AUTO_EXPOSURE, 1);
  info_.width = int(video_->get(cv::CAP_PROP_FRAME_WIDTH));
  info_.height = int(video_->get(cv::CAP_PROP_FRAME_HEIGHT));
  info_.channels = raw16_ ? 1 : 3;
  info_.bits = raw16_ ? 16 : 8;
  info_.name = "v4l2:" + path_;
}

V4l2Camera::~V4l2Camera() = default;

capture::CameraInfo V4l2Camera::info() { return info_; }

void V4l2Camera::set_exposure(double seconds) {
  if (!(seconds > 0) || !std::isfinite(seconds)) throw usage_error("v4l2 camera: exposure {} s must be positive", seconds);
  // exposure_absolute: units of 100 us.
  if (!video_->set(cv::CAP_PROP_EXPOSURE, std::max(1.0, std::round(seconds * 1e4))))
    throw make_error(Status::device_error, "v4l2 camera: {} refused exposure {} s", path_, seconds);
}

Image V4l2Camera::capture() {
  cv::Mat frame;
  if (!video_->read(frame) || frame.empty())
    throw make_error(Status::timeout, "v4l2 camera: {} did not deliver a frame", path_);
  if (frame.channels() == 3) cv::cvtColor(frame, frame, cv::COLOR_BGR2RGB);
  info_.width = frame.cols;
  info_.height = frame.rows;
  return Image{frame, ColorSpace::srgb};
}

}  // namespace fest::devices
